"""Independent references for single-cable and small-system statics (tests/cli/statics.sh).

Nothing here uses catena's own analytic code: the elastic catenary is integrated from its
differential equations (Irvine's closed form for engineering strain, Gauss-Legendre
quadrature for Green-Lagrange) and its end conditions solved by Newton's method here;
the equilibrium of a catena result is recomputed from the forces and positions it prints.
Plain Python (math only), so that it runs wherever python3 does.
"""
import json
import math
import os
import subprocess
import tempfile


def run(binary, text, args=("--json",), name="m.cable"):
    """Solve the model TEXT; return (exit code, parsed JSON or None, stderr with the
    temporary path shown as FILE)."""
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, name)
        with open(path, "w") as f:
            f.write(text)
        p = subprocess.run([binary, "solve", path] + list(args), capture_output=True, text=True)
        res = None
        if p.stdout.strip().startswith("{"):
            res = json.loads(p.stdout)
        return p.returncode, res, p.stderr.replace(path, "FILE")


# --- small vector helpers (tuples of 3) ---
def add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def mul(k, a):
    return tuple(k * x for x in a)


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def norm(a):
    return math.sqrt(dot(a, a))


def stretch(T, EA, law):
    """lambda = dp/ds for the axial force T (true force, unstressed area)."""
    if law == "engineering":
        return 1.0 + T / EA
    # Green-Lagrange: T = EA (lambda^2 - 1)/2 * lambda, by Newton from the linear guess
    lam = 1.0 + T / EA
    for _ in range(60):
        f = EA * (lam ** 3 - lam) * 0.5 - T
        d = EA * (3 * lam * lam - 1) * 0.5
        step = f / d
        lam -= step
        if abs(step) < 1e-17:
            break
    return lam


# 10-point Gauss-Legendre nodes and weights on [-1, 1]
_GX = (0.1488743389816312, 0.4333953941292472, 0.6794095682990244, 0.8650633666889845, 0.9739065285171717)
_GW = (0.2955242247147529, 0.2692667193099963, 0.2190863625159820, 0.1494513491505806, 0.0666713443086881)


def gauss(f, a, b, panels=16):
    h = (b - a) / panels
    tot = 0.0
    for k in range(panels):
        m = a + (k + 0.5) * h
        for x, wt in zip(_GX, _GW):
            tot += wt * (f(m - 0.5 * h * x) + f(m + 0.5 * h * x))
    return tot * 0.5 * h


def catenary_profile(H, V0, w, EA, law, s):
    """Point (horizontal, up) at unstressed arc length s from the first end of a cable with
    horizontal tension H and upward tension component V0 at s = 0 (negative: the cable
    starts downward), weight w per unstressed length: dx = H/T lam ds, dz = Tv/T lam ds,
    Tv = V0 + w s, T = sqrt(H^2 + Tv^2)."""
    if s == 0:
        return 0.0, 0.0
    if law == "engineering":  # Irvine's closed form
        v1 = V0 + w * s
        x = H * s / EA + H / w * (math.asinh(v1 / H) - math.asinh(V0 / H))
        z = (V0 * s + 0.5 * w * s * s) / EA + (math.hypot(H, v1) - math.hypot(H, V0)) / w
        return x, z

    def fx(t):
        T = math.hypot(H, V0 + w * t)
        return H / T * stretch(T, EA, law)

    def fz(t):
        tv = V0 + w * t
        T = math.hypot(H, tv)
        return tv / T * stretch(T, EA, law)

    return gauss(fx, 0, s), gauss(fz, 0, s)


def elastic_catenary(span, rise, L0, w, EA, law):
    """(H, V0) of the cable of unstressed length L0 and weight w per unstressed length
    between ends (0, 0) and (span, rise) (rise measured up), by Newton's method on
    (log H, V0) with a difference Jacobian."""
    chord = math.hypot(span, rise)
    slack = max(L0 - chord, 1e-4 * chord)
    sag = math.sqrt(3.0 * chord * slack / 8.0)
    p = [math.log(w * L0 * span / (8 * sag)), 0.0]
    p[1] = rise / span * math.exp(p[0]) - w * L0 / 2

    def res(q):
        x, z = catenary_profile(math.exp(q[0]), q[1], w, EA, law, L0)
        return [(x - span) / chord, (z - rise) / chord]

    r = res(p)
    for _ in range(100):
        h0, h1 = 1e-7, 1e-7 * max(abs(p[1]), w * L0)
        a = res([p[0] + h0, p[1]])
        b = res([p[0], p[1] + h1])
        J = [[(a[0] - r[0]) / h0, (b[0] - r[0]) / h1], [(a[1] - r[1]) / h0, (b[1] - r[1]) / h1]]
        det = J[0][0] * J[1][1] - J[0][1] * J[1][0]
        d0 = (r[0] * J[1][1] - r[1] * J[0][1]) / det
        d1 = (J[0][0] * r[1] - J[1][0] * r[0]) / det
        t = 1.0
        while True:
            q = [p[0] - t * d0, p[1] - t * d1]
            rq = res(q)
            if max(map(abs, rq)) < max(map(abs, r)) or t < 1e-3:
                break
            t *= 0.5
        p, r = q, rq
        if max(map(abs, r)) < 1e-15:
            break
    assert max(map(abs, r)) < 1e-13, r
    return math.exp(p[0]), p[1]


def frame(A, B, g):
    """(e_h, e_up, span, rise): the unit horizontal vector along the span, the unit up
    vector -g/|g|, the horizontal span and the rise from A to B."""
    up = mul(-1.0 / norm(g), g)
    d = sub(B, A)
    rise = dot(d, up)
    hvec = sub(d, mul(rise, up))
    span = norm(hvec)
    return mul(1.0 / span, hvec), up, span, rise


def positions(res):
    """{id: current position} of a catena result."""
    return {n["id"]: (n["x"] + n["ux"], n["y"] + n["uy"], n["z"] + n["uz"]) for n in res["nodes"]}


def reactions(res):
    return {r["node"]: (r["fx"], r["fy"], r["fz"]) for r in res["reactions"]}


def residual(res, loads, weights):
    """Equilibrium recomputed from the result: at every node the pulls of its elements
    (force along the current chord), the external loads and the reaction, which must sum
    to zero.  LOADS is {node: force}; WEIGHTS {element id: the element's weight vector}
    (half to each node).  Returns (largest nodal out-of-balance, largest force)."""
    X = positions(res)
    bal = {i: (0.0, 0.0, 0.0) for i in X}
    scale = 0.0
    for e in res["elements"]:
        assert len(e["nodes"]) == 2
        a, b = e["nodes"]
        c = sub(X[b], X[a])
        t = mul(e["force"] / norm(c), c)
        bal[a] = add(bal[a], t)
        bal[b] = sub(bal[b], t)
        scale = max(scale, abs(e["force"]))
        if e["id"] in weights:
            hw = mul(0.5, weights[e["id"]])
            bal[a] = add(bal[a], hw)
            bal[b] = add(bal[b], hw)
    for n, f in loads.items():
        bal[n] = add(bal[n], f)
    for n, f in reactions(res).items():
        bal[n] = add(bal[n], f)
    return max(norm(v) for v in bal.values()), scale
