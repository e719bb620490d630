#!/usr/bin/env python3
# bench/peers/mooring_line.py N - a mooring line as a plain cable model (the subset that
# bench/peers/cable2peer.py takes), for bench/peers/mooring.sh: a chain of unstretched
# length S = 302 m from an anchor at (0, 0) to a fairlead at (280, 100) (y up, 100 m of
# water, the plane x-y), N elements of equal length on the inextensible catenary through
# the two points (y = a (cosh((x - x0)/a) - cosh(x0/a)): tanh((u + v)/2) = h / S,
# 2 a sinh(X / 2a) = sqrt(S^2 - h^2)), EA = 7.5e5 kN, mass 0.115 t/m, submerged weight
# 0.98 kN/m as loads at the nodes (half of each element's at each end), every node held
# in z. The elements start prestrained by eps0 = 5e-4 (OpenSees' corotTruss on
# InitStrainMaterial, L from the nodes: an unstressed length L (1 - eps0), about the
# equilibrium's stretch, so the drawn line carries its tension from the start: a chain
# drawn unstressed has no stiffness across it, and OpenSees' first Newton step is
# singular). No seabed (the line is suspended all the way: its lowest point is the
# anchor, where it is nearly horizontal), no hydrodynamic drag or added mass.
import sys, math

n = int(sys.argv[1])
X, h, S, EA, m, w = 280.0, 100.0, 302.0, 7.5e5, 0.115, 0.98
lo, hi = 1.0, 1e6                              # 2 a sinh(X / 2a) = sqrt(S^2 - h^2)
c = math.sqrt(S * S - h * h)
for _ in range(200):
    a = 0.5 * (lo + hi)
    if 2 * a * math.sinh(X / (2 * a)) > c: lo = a
    else: hi = a
v = math.atanh(h / S) - X / (2 * a)
x0 = -a * v
pts = []
for k in range(n + 1):
    s = S * k / n
    x = x0 + a * math.asinh(s / a + math.sinh(-x0 / a))
    pts.append((x, a * (math.cosh((x - x0) / a) - math.cosh(x0 / a))))
pts[-1] = (X, h)
W = sys.stdout.write
W("# mooring line, %d elements (bench/peers/mooring_line.py)\nunits kN m\n" % n)
W("material chain E=%.17g\nsection c material=chain A=1 mass=%.17g\n" % (EA, m))
for k, (x, y) in enumerate(pts):
    fix = "xyz" if k in (0, n) else "z"
    W("node %d %.17g %.17g 0 fix=%s\n" % (k + 1, x, y, fix))
L = [math.hypot(pts[k + 1][0] - pts[k][0], pts[k + 1][1] - pts[k][1]) for k in range(n)]
for k in range(n):
    W("element %d %d %d section=c eps0=5e-4\n" % (k + 1, k + 1, k + 2))
for k in range(1, n):
    W("load %d 0 %.17g 0\n" % (k + 1, -w * (L[k - 1] + L[k]) / 2))
