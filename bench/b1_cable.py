#!/usr/bin/env python3
# bench/b1_cable.py N [SAG] [EXTRA_LINE]: the OpenSees B1 cable as a .cable model on stdout
# (issue 29): a 1000 m span of N `element`s prestressed by eps0 = 1e-3 on a parabola of SAG
# (default 1 m; negative: an arch bulging up), its weight 0.1 kN/m as point loads of
# 0.1 L/N on the interior nodes, a plane model (nodes held in z); EXTRA_LINE (e.g. a
# `solve` line) is appended. Used by bench/iterations.sh and tests/cli/loaded_starts.sh.
import sys
n = int(sys.argv[1])
s = float(sys.argv[2]) if len(sys.argv) > 2 else 1.0
extra = sys.argv[3] if len(sys.argv) > 3 else ""
L, w = 1000.0, 0.1
print("units kN m\nmaterial steel E=2.0e8\nsection c material=steel A=3.14e-4")
for i in range(n + 1):
    x = L * i / n
    print("node %d %r %r 0%s" % (i + 1, x, -4 * s * x * (L - x) / L ** 2, " fix=xyz" if i in (0, n) else " fix=z"))
for i in range(n):
    print("element %d %d %d section=c eps0=1e-3" % (i + 1, i + 1, i + 2))
for i in range(1, n):
    print("load %d 0 %r 0" % (i + 1, -w * L / n))
if extra:
    print(extra)
