#!/usr/bin/env python3
# bench/beam_grid.py K: a K x K grillage of steel tube beams on a 100 m square (2 K (K + 1)
# beam elements, one per grid edge), its boundary nodes clamped, a downward load of
# 1 kN on every free node, as a .cable model on stdout: the beam counterpart of
# bench/hypar_net.py's net for the issue-23 target (1e5 beam elements solve within 2x
# the time per DOF of a cable net of the same DOF count; bench/RESULTS.md).
#   python3 bench/beam_grid.py 224 > grid.cable     (100 800 elements, 297 774 DOFs)
import sys
k = int(sys.argv[1])
h = 100.0 / k
w = sys.stdout.write
w("units kN m\nmaterial steel E=210GPa nu=0.3\nsection tube material=steel d=0.3 t=0.01\n")
def nid(i, j): return i * (k + 1) + j + 1
for i in range(k + 1):
    for j in range(k + 1):
        fix = " fix=xyzrxryrz" if i in (0, k) or j in (0, k) else ""
        w("node %d %.6f %.6f 0%s\n" % (nid(i, j), -50 + i * h, -50 + j * h, fix))
e = 0
for i in range(k + 1):
    for j in range(k + 1):
        for (di, dj) in ((1, 0), (0, 1)):
            if i + di > k or j + dj > k: continue
            e += 1
            w("beam %d %d %d section=tube orient=0,0,1\n" % (e, nid(i, j), nid(i + di, j + dj)))
for i in range(1, k):
    for j in range(1, k):
        w("load %d 0 0 -1\n" % nid(i, j))
