#!/usr/bin/env python3
# bench/hypar_net.py K [MATERIAL_FLAGS] [SNOW]: a K x K hyperbolic-paraboloid cable net on a
# 100 m square, z = 10 (x^2 - y^2) / 50^2, boundary pinned, every strand prestressed to
# 10 kN (its l0 computed for Green-Lagrange strain), snow SNOW kN (default 0.5) on every
# free node, as a .cable model on stdout. Env E, A: the strands (default 1.6e8, 1.5e-4);
# MASS: their mass per length (t/m; default none), MODES: a `modes count=MODES` line.
#   python3 bench/hypar_net.py 100 > net.cable            (tension-only strands)
#   python3 bench/hypar_net.py 50 "" > net2.cable         (two-way strands)
import sys, math
k = int(sys.argv[1]); mat = sys.argv[2] if len(sys.argv) > 2 else "tension-only"
snow = float(sys.argv[3]) if len(sys.argv) > 3 else 0.5
import os
E, A, N0 = float(os.environ.get("E", "1.6e8")), float(os.environ.get("A", "1.5e-4")), 10.0
EA = E * A
mass = os.environ.get("MASS", "")
out = ["units kN m", "material strand E=%g %s" % (E, mat),
       "section s material=strand A=%g%s" % (A, " mass=" + mass if mass else "")]
if os.environ.get("MODES"): out.append("modes count=%d" % int(os.environ["MODES"]))
h = 100.0 / k
def nid(i, j): return i * (k + 1) + j + 1
pos = {}
for i in range(k + 1):
    for j in range(k + 1):
        x, y = -50 + i * h, -50 + j * h
        z = 10 * (x * x - y * y) / 2500.0
        pos[nid(i, j)] = (x, y, z)
        fix = " fix=xyz" if i in (0, k) or j in (0, k) else ""
        out.append("node %d %.17g %.17g %.17g%s" % (nid(i, j), x, y, z, fix))
def lam_for(N):  # Green-Lagrange: N = EA (l^2-1)/2 l
    lo, hi = 1.0, 1.1
    for _ in range(200):
        m = 0.5 * (lo + hi)
        if EA * (m * m - 1) / 2 * m > N: hi = m
        else: lo = m
    return 0.5 * (lo + hi)
lam = lam_for(N0)
e = 1
for i in range(k + 1):
    for j in range(k + 1):
        for (di, dj) in ((1, 0), (0, 1)):
            if i + di > k or j + dj > k: continue
            a, b = nid(i, j), nid(i + di, j + dj)
            if (i in (0, k) and di == 0) or (j in (0, k) and dj == 0): continue  # boundary edges
            pa, pb = pos[a], pos[b]
            l = math.dist(pa, pb)
            out.append("element %d %d %d section=s l0=%.17g" % (e, a, b, l / lam)); e += 1
for i in range(1, k):
    for j in range(1, k):
        out.append("load %d 0 0 %g" % (nid(i, j), -snow))
print("\n".join(out))
