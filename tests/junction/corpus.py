#!/usr/bin/env python3
"""The junction corpus: corpus.py DIR [catenary]

Writes DIR/*.cable: K = 3 or 4 cables of n = 10 or 50 `cable` elements from pinned
supports (level, or at heights 0, 15, -10, 25 m, on a 50 m circle) to a free node with a
concentrated load (100 kN down, 40/10/-60 kN sideways, or a light 2 kN), with self-weight
(a steel strand, two-way, or a tension-only chain). Each cable is a straight line or an arc
from its support to a guessed junction position (under the centre, at the centre, off the
centre, or far: 30/25/30, above the supports), of a length 1.05 times its chord to the
guess (slack), equal to it, 0.995 times it (taut, shape=straight) or mixed over the
cables. 768 models. With `catenary`: the same junctions with one catenary element per
cable (n is then irrelevant). Run them with tests/junction/run.sh."""
import math, os, sys, itertools
out = sys.argv[1]; CAT = len(sys.argv) > 2
os.makedirs(out, exist_ok=True)

def model(name, K, n, fac, P, guess, geo, w, E, A, tonly, sw=True, extra=""):
    sup = geo
    J = guess
    L = []
    L.append("units kN m")
    L.append("gravity 0 0 -1")
    L.append("material m E=%g strain=engineering%s" % (E, " tension-only" if tonly else ""))
    L.append("section s material=m A=%g w=%g" % (A, w if sw else 0))
    for i, p in enumerate(sup):
        L.append("node %d %g %g %g fix=xyz" % (i + 1, *p))
    j = len(sup) + 1
    L.append("node %d %g %g %g" % (j, *J))
    for i, p in enumerate(sup):
        ch = math.dist(p, J)
        length = ch * fac[i] if isinstance(fac, list) else ch * fac
        shape = "" if length > ch * (1 + 1e-9) else " shape=straight"
        L.append(("catenary %d %d %d section=s length=%.6f" % (100 + i, i + 1, j, length)) if CAT else ("cable %d %d section=s n=%d length=%.6f%s" % (i + 1, j, n, length, shape)))
    L.append("load %d %g %g %g" % (j, *P))
    L.append(extra)
    open(os.path.join(out, name + ".cable"), "w").write("\n".join(L) + "\n")

R = 50.0
def ring(K, zs):
    return [(R * math.cos(2 * math.pi * i / K), R * math.sin(2 * math.pi * i / K), zs[i % len(zs)]) for i in range(K)]
geos = {
    "level": lambda K: ring(K, [0]),
    "3d": lambda K: ring(K, [0, 15, -10, 25]),
}
guesses = {
    "under": (0, 0, -20),
    "center": (0, 0, 0),
    "off": (8, -5, -12),
    "far": (30, 25, 30),
}
loads = {"down": (0, 0, -100), "side": (40, 10, -60), "light": (0, 0, -2)}
facs = {"slack": 1.05, "equal": 1.0, "taut": 0.995, "mixed": [1.05, 1.0, 1.02, 0.998]}
sections = {"strand": (2e8, 3.14e-4, 0.1, False), "chain": (1e8, 2e-3, 1.5, True)}
for K, n, (gn, geo), (un, g), (ln, P), (fn, f), (sn, sec) in itertools.product(
        (3, 4), (10, 50), geos.items(), guesses.items(), loads.items(), facs.items(), sections.items()):
    E, A, w, t = sec
    if un == "center" and gn == "level":
        g = (0, 0, 0.0)
    fl = f if not isinstance(f, list) else [f[i % 4] for i in range(K)]
    model("K%d_n%d_%s_%s_%s_%s_%s" % (K, n, gn, un, ln, fn, sn), K, n, fl, P, g, geos[gn](K), w, E, A, t)
