#!/usr/bin/env python3
# bench/hypar_net.py K [MATERIAL_FLAGS] [SNOW] [--issue10]: a K x K hyperbolic-paraboloid
# cable net on a 100 m square, z = 10 (x^2 - y^2) / 50^2, boundary pinned, as a .cable
# model on stdout. Env E, A: the strands (default 1.6e8, 1.5e-4); MASS: their mass per
# length (t/m; default none), MODES: a `modes count=MODES` line.
#   default:   every strand prestressed to 10 kN (its l0 computed for Green-Lagrange
#              strain), snow SNOW kN (default 0.5) on every free node;
#   --issue10: the net of issue 10 (and of the CalculiX/OpenSees comparison in
#              bench/nets): two-way strands prestressed by eps0 = 2e-3, a downward
#              pressure of 0.2 kN/m^2 on the plan, (100/K)^2 * 0.2 kN on every free node.
#   python3 bench/hypar_net.py 100 > net.cable            (tension-only strands)
#   python3 bench/hypar_net.py 50 "" > net2.cable         (two-way strands)
#   python3 bench/hypar_net.py 400 --issue10 > net400.cable
#   python3 bench/hypar_net.py 100 --ccx > net100.inp   (the --issue10 net for CalculiX:
#              T3D2 trusses, NLGEOM, the prestrain eps0 = 2e-3 as a cooling of 200 K with
#              alpha = 1e-5, the same nodal loads)
import sys, math, os
ccx = "--ccx" in sys.argv
args = [a for a in sys.argv[1:] if a not in ("--issue10", "--ccx")]
issue10 = ccx or len(args) != len(sys.argv) - 1
k = int(args[0])
mat = "" if issue10 else (args[1] if len(args) > 1 else "tension-only")
snow = float(args[2]) if len(args) > 2 else 0.5
E, A, N0 = float(os.environ.get("E", "1.6e8")), float(os.environ.get("A", "1.5e-4")), 10.0
EA = E * A
h = 100.0 / k
if issue10: snow = 0.2 * h * h
w = sys.stdout.write
def nid(i, j): return i * (k + 1) + j + 1
def pos(i, j):
    x, y = -50 + i * h, -50 + j * h
    return (x, y, 10 * (x * x - y * y) / 2500.0)
def strands():
    for i in range(k + 1):
        for j in range(k + 1):
            for (di, dj) in ((1, 0), (0, 1)):
                if i + di > k or j + dj > k: continue
                if (i in (0, k) and di == 0) or (j in (0, k) and dj == 0): continue  # boundary edges
                yield nid(i, j), nid(i + di, j + dj)
if ccx:
    w("*NODE, NSET=NALL\n")
    for i in range(k + 1):
        w("".join("%d, %.17g, %.17g, %.17g\n" % ((nid(i, j),) + pos(i, j)) for j in range(k + 1)))
    w("*ELEMENT, TYPE=T3D2, ELSET=EALL\n")
    w("".join("%d, %d, %d\n" % (e + 1, a, b) for e, (a, b) in enumerate(strands())))
    w("*NSET, NSET=FIX\n")
    w("".join("%d,\n" % nid(i, j) for i in range(k + 1) for j in range(k + 1) if i in (0, k) or j in (0, k)))
    w("*MATERIAL, NAME=STRAND\n*ELASTIC\n%g, 0.3\n*EXPANSION\n1e-5\n" % E)
    w("*SOLID SECTION, ELSET=EALL, MATERIAL=STRAND\n%g\n" % A)
    w("*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 0.\n*BOUNDARY\nFIX, 1, 3\n")
    w("*STEP, NLGEOM\n*STATIC\n*TEMPERATURE\nNALL, -200.\n*CLOAD\n")
    w("".join("%d, 3, %.17g\n" % (nid(i, j), -snow) for i in range(1, k) for j in range(1, k)))
    w("*NODE FILE\nU\n*END STEP\n")
    sys.exit(0)
mass = os.environ.get("MASS", "")
w("units kN m\nmaterial strand E=%g %s\nsection s material=strand A=%g%s\n" % (E, mat, A, " mass=" + mass if mass else ""))
if os.environ.get("MODES"): w("modes count=%d\n" % int(os.environ["MODES"]))
for i in range(k + 1):
    rows = []
    for j in range(k + 1):
        x, y, z = pos(i, j)
        fix = " fix=xyz" if i in (0, k) or j in (0, k) else ""
        rows.append("node %d %.17g %.17g %.17g%s\n" % (nid(i, j), x, y, z, fix))
    w("".join(rows))
def lam_for(N):  # Green-Lagrange: N = EA (l^2-1)/2 l
    lo, hi = 1.0, 1.1
    for _ in range(200):
        m = 0.5 * (lo + hi)
        if EA * (m * m - 1) / 2 * m > N: hi = m
        else: lo = m
    return 0.5 * (lo + hi)
lam = lam_for(N0)
rows = []
for e, (a, b) in enumerate(strands()):
    if issue10:
        rows.append("element %d %d %d section=s eps0=2e-3\n" % (e + 1, a, b))
    else:
        ia, ja, ib, jb = (a - 1) // (k + 1), (a - 1) % (k + 1), (b - 1) // (k + 1), (b - 1) % (k + 1)
        l = math.dist(pos(ia, ja), pos(ib, jb))
        rows.append("element %d %d %d section=s l0=%.17g\n" % (e + 1, a, b, l / lam))
    if len(rows) >= 4096:
        w("".join(rows))
        rows = []
w("".join(rows))
rows = []
for i in range(1, k):
    for j in range(1, k):
        rows.append("load %d 0 0 %.17g\n" % (nid(i, j), -snow))
w("".join(rows))
