"""tests/cli/statics.sh's cases: catena's single-cable and small-system statics against
references computed here (statics_ref.py), the way an independent checker would.

    python3 statics_check.py CATENA CASE

prints nothing when CASE holds, else one line per problem (and exits 1).
"""
import math
import sys

from statics_ref import (add, catenary_profile, dot, elastic_catenary, frame, mul, norm,
                         positions, reactions, residual, run, stretch, sub)

BIN = sys.argv[1]
PROBLEMS = []


def need(cond, what):
    if not cond:
        PROBLEMS.append(what)


def solve(text, what):
    rc, res, err = run(BIN, text)
    if rc != 0 or res is None or not res["converged"]:
        PROBLEMS.append("%s: exit %d: %s" % (what, rc, err.strip()))
        return None
    return res


def tension(lam, EA, law):
    """The documented laws: engineering N = EA (lam - 1); Green-Lagrange N = EA (lam^2 - 1)/2 lam."""
    return EA * (lam - 1) if law == "engineering" else EA * (lam * lam - 1) * 0.5 * lam


def chain(n):
    """Node ids of a generated `cable 1 2 n=N` (the first model lines define nodes 1 and 2)."""
    return [1] + list(range(3, 3 + n - 1)) + [2]


def self_weights(res, w, g):
    return {e["id"]: mul(w * e["l0"], g) for e in res["elements"] if e.get("type") is None}


def check_residual(res, loads, weights, what, tol=1e-10):
    worst, scale = residual(res, loads, weights)
    need(worst <= tol * scale, "%s: out of balance %.3g of forces %.3g recomputed from the output" % (what, worst, scale))


def cable_model(A, B, g, E, area, w, law, card, units="kN m", extra=""):
    return ("units %s\ngravity %.17g %.17g %.17g\nmaterial m E=%.17g strain=%s\n"
            "section s material=m A=%.17g w=%.17g\nnode 1 %.17g %.17g %.17g fix=xyz\n"
            "node 2 %.17g %.17g %.17g fix=xyz\n%s\n%s" %
            ((units,) + tuple(g) + (E, law, area, w) + tuple(A) + tuple(B) + (card, extra)))


# --- 1. self-weight: Irvine's elastic catenary -----------------------------------------
def catenary_case(A, B, g, L0, w, E, area, law, units, meshes, what):
    """Fine meshes of a cable under its own weight against the continuous elastic
    catenary: node positions (at their unstressed arc length), end reactions, mid-span
    sag, all at O(h^2) (each halving of h divides the error by 4 +- 10 %), and the
    equilibrium of every mesh recomputed from its output."""
    e_h, up, span, rise = frame(A, B, g)
    W = w * norm(g)
    EA = E * area
    H, V0 = elastic_catenary(span, rise, L0, W, EA, law)
    V1 = V0 + W * L0
    Tmax = max(math.hypot(H, V0), math.hypot(H, V1))
    RA = mul(-1.0, add(mul(H, e_h), mul(V0, up)))
    RB = add(mul(H, e_h), mul(V1, up))
    # reference mid-span sag: the point at half the horizontal span, below the chord
    lo, hi = 0.0, L0
    for _ in range(100):
        m = 0.5 * (lo + hi)
        if catenary_profile(H, V0, W, EA, law, m)[0] < span / 2:
            lo = m
        else:
            hi = m
    sag = rise / 2 - catenary_profile(H, V0, W, EA, law, 0.5 * (lo + hi))[1]
    errs = []
    states = []
    for n in meshes:
        res = solve(cable_model(A, B, g, E, area, w, law, "cable 1 2 section=s n=%d length=%.17g" % (n, L0), units),
                    "%s n=%d" % (what, n))
        if res is None:
            return
        X = positions(res)
        ep = 0.0
        for k, i in enumerate(chain(n)):
            x, z = catenary_profile(H, V0, W, EA, law, L0 * k / n)
            ep = max(ep, norm(sub(X[i], add(A, add(mul(x, e_h), mul(z, up))))))
        R = reactions(res)
        er = max(norm(sub(R[1], RA)), norm(sub(R[2], RB))) / Tmax
        es = abs(res["cables"][0]["sag"] - sag) / sag
        errs.append((ep / span, er, es))
        states.append((n, X, R, res["cables"][0]["sag"]))
        check_residual(res, {}, self_weights(res, w, g), "%s n=%d" % (what, n))
    for (a, b) in zip(errs, errs[1:]):
        for j, name in enumerate(("positions", "reactions", "sag")):
            ratio = a[j] / b[j]
            need(3.6 < ratio < 4.4, "%s: %s error ratio %.3f on halving h (O(h^2) wants 4): %s" % (what, name, ratio, errs))
    # Richardson's extrapolation of the two finest meshes, (4 fine - coarse) / 3 at the
    # coarse mesh's nodes, cancels the h^2 term: what is left is O(h^4) and the reference
    (n1, X1, R1, s1), (n2, X2, R2, s2) = states[-2], states[-1]
    c1, c2 = chain(n1), chain(n2)
    ep = 0.0
    for k, i in enumerate(c1):
        x, z = catenary_profile(H, V0, W, EA, law, L0 * k / n1)
        Xr = mul(1 / 3.0, sub(mul(4.0, X2[c2[2 * k]]), X1[i]))
        ep = max(ep, norm(sub(Xr, add(A, add(mul(x, e_h), mul(z, up))))))
    er = max(norm(sub(mul(1 / 3.0, sub(mul(4.0, R2[j]), R1[j])), ref)) for j, ref in ((1, RA), (2, RB))) / Tmax
    es = abs((4 * s2 - s1) / 3 - sag) / sag
    # measured: positions 9.1e-9 of the span, reactions 1.2e-8 of the largest tension, sag 3.5e-7
    need(ep < 5e-8 * span and er < 5e-8 and es < 2e-6,
         "%s: Richardson's extrapolation of n=%d and %d is off the reference by %.3g (positions / span), "
         "%.3g (reactions / T), %.3g (sag)" % (what, n1, n2, ep / span, er, es))
    # the finest mesh: the errors the O(h^2) constant allows (measured: 1.7e-5, 6.8e-5 at n = 80)
    n = meshes[-1]
    need(errs[-1][0] < 0.15 / n ** 2 and errs[-1][1] < 0.5 / n ** 2,
         "%s: n=%d errors %s too large" % (what, n, errs[-1]))


def case_catenary():
    # an inclined span in 3D, not along an axis, gravity along -z, both strain laws
    for law in ("engineering", "green-lagrange"):
        catenary_case((1, 2, 3), (150, 90, 60), (0, 0, -1), 200.0, 0.1, 2e8, 3.14e-4, law, "kN m",
                      (20, 40, 80), "slack 3D span, %s" % law)
    # a taut level span (stretch matters: the laws differ by 5e-4 in H), gravity along -y
    for law in ("engineering", "green-lagrange"):
        catenary_case((0, 0, 0), (200, 0, 0), (0, -1, 0), 200.3340 * 0.999, 0.1, 2e8, 3.14e-4, law, "kN m",
                      (20, 40, 80), "taut span, %s" % law)
    # N mm, supports at different heights, span along no axis; w as a mass with |g| = 9806.65
    catenary_case((0, 0, 0), (120000, -30000, 50000), (0, -9806.65, 0), 135000.0, 0.1 / 9806.65, 2e5, 314.0,
                  "engineering", "N mm", (20, 40, 80), "N mm inclined span")


# --- 2. a concentrated load: two straight segments ----------------------------------------
def two_segments(A, B, L1, L2, P, EA, law, C):
    """The joint C of two straight segments of unstressed lengths L1, L2 between A and B
    under the load P: Newton's method on C (3 unknowns), difference Jacobian."""
    def r(C):
        d1, d2 = sub(C, A), sub(B, C)
        t1 = tension(norm(d1) / L1, EA, law)
        t2 = tension(norm(d2) / L2, EA, law)
        return add(add(mul(-t1 / norm(d1), d1), mul(t2 / norm(d2), d2)), P)
    for _ in range(50):
        f = r(C)
        if norm(f) < 1e-14 * norm(P):
            break
        J = []
        for j in range(3):
            h = 1e-7 * max(1.0, abs(C[j]))
            Cj = list(C)
            Cj[j] += h
            J.append([(a - b) / h for a, b in zip(r(tuple(Cj)), f)])  # J[j] = dr/dC_j
        M = [[J[j][i] for j in range(3)] + [-f[i]] for i in range(3)]
        for c in range(3):
            p = max(range(c, 3), key=lambda k: abs(M[k][c]))
            M[c], M[p] = M[p], M[c]
            for k in range(c + 1, 3):
                m = M[k][c] / M[c][c]
                M[k] = [x - m * y for x, y in zip(M[k], M[c])]
        d = [0.0] * 3
        for c in (2, 1, 0):
            d[c] = (M[c][3] - sum(M[c][l] * d[l] for l in range(c + 1, 3))) / M[c][c]
        C = tuple(x + y for x, y in zip(C, d))
    return C


def case_point_load():
    A, B, S, P = (2.0, 1.0, -3.0), (62.0, 25.0, -18.0), 70.0, (3.0, -7.0, -40.0)
    EA = 2e8 * 1e-4
    for law in ("engineering", "green-lagrange"):
        for n, k in ((2, 1), (10, 3), (25, 17)):
            what = "point load %s n=%d at node %d" % (law, n, k)
            text = ("units kN m\nmaterial m E=2e8 strain=%s\nsection s material=m A=1e-4\n"
                    "node 1 %g %g %g fix=xyz\nnode 2 %g %g %g fix=xyz\n"
                    "cable 1 2 section=s n=%d length=%g shape=straight\nload %d %g %g %g\n" %
                    ((law,) + A + B + (n, S, 2 + k) + P))
            res = solve(text, what)
            if res is None:
                continue
            X = positions(res)
            # from the straight chord's point at fraction k/n, not from catena's answer
            C = two_segments(A, B, S * k / n, S * (n - k) / n, P, EA, law,
                             add(A, add(mul(k / n, sub(B, A)), (0.0, -5.0, -5.0))))
            need(norm(sub(X[2 + k], C)) < 1e-11 * S, "%s: load point %s, closed form %s" % (what, X[2 + k], C))
            d1 = sub(C, A)
            RA = mul(-tension(norm(d1) / (S * k / n), EA, law) / norm(d1), d1)
            R = reactions(res)
            need(norm(sub(R[1], RA)) < 1e-11 * norm(P), "%s: reaction %s, closed form %s" % (what, R[1], RA))
            need(norm(add(add(R[1], R[2]), P)) < 1e-11 * norm(P), "%s: reactions do not balance the load" % what)
            check_residual(res, {2 + k: P}, {}, what)


# --- 3. a load per horizontal length: the elastic parabola --------------------------------
def parabola_length(H, q, span, rise, EA, law, x):
    """Unstressed length from the first end to horizontal position x of the cable whose
    shape is z = V0/H x + q x^2/(2H) (z up, q per horizontal length downward)."""
    V0 = H * rise / span - q * span / 2

    def f(t):
        zp = (V0 + q * t) / H
        return math.sqrt(1 + zp * zp) / stretch(H * math.sqrt(1 + zp * zp), EA, law)
    from statics_ref import gauss
    return gauss(f, 0.0, x), V0


def case_parabola():
    A, B, g, q, L0, E, area = (0, 0, 0), (80, 60, -100), (0.3, -1, 0.2), 2.0, 150.0, 2e8, 3e-4
    EA = E * area
    e_h, up, span, rise = frame(A, B, g)
    for law in ("engineering", "green-lagrange"):
        lo, hi = 1e-3, 1e6
        for _ in range(200):
            H = math.sqrt(lo * hi)
            if parabola_length(H, q, span, rise, EA, law, span)[0] > L0:
                lo = H
            else:
                hi = H
        errs, Hs = [], []
        for n in (20, 40, 80):
            what = "hload parabola %s n=%d" % (law, n)
            res = solve(cable_model(A, B, g, E, area, 0.0, law, "cable 1 2 section=s n=%d length=%g" % (n, L0),
                                    extra="hload q=%g\n" % q), what)
            if res is None:
                return
            X = positions(res)
            ez = es = 0.0
            for k, i in enumerate(chain(n)):
                d = sub(X[i], A)
                x, z = dot(d, e_h), dot(d, up)
                s, V0 = parabola_length(H, q, span, rise, EA, law, x)
                ez = max(ez, abs(z - (V0 / H * x + q * x * x / (2 * H))), norm(sub(d, add(mul(x, e_h), mul(z, up)))))
                es = max(es, abs(s - L0 * k / n))
            Hfe = -dot(reactions(res)[1], e_h)
            errs.append((ez / span, es / L0, abs(Hfe / H - 1)))
            Hs.append(Hfe)
            gu = mul(1 / norm(g), g)
            loads = {}
            for e in res["elements"]:
                a, b = e["nodes"]
                c = sub(X[b], X[a])
                loads[e["id"]] = mul(q * norm(sub(c, mul(dot(c, up), up))), gu)
            check_residual(res, {}, loads, what)
        for a, b in zip(errs, errs[1:]):
            for j, name in enumerate(("shape", "arc length", "H")):
                need(3.6 < a[j] / b[j] < 4.4, "hload %s: %s error ratio %.3f (O(h^2) wants 4): %s" % (law, name, a[j] / b[j], errs))
        HR = (4 * Hs[-1] - Hs[-2]) / 3  # Richardson: O(h^4) (1.7e-8, 1.1e-9, 9e-11 from n = 40, 80, 160 on)
        need(abs(HR / H - 1) < 5e-8, "hload %s: H extrapolated from n=40, 80 is %.17g, the elastic parabola's %.17g" % (law, HR, H))
        need(errs[-1][0] < 0.15 / 80 ** 2 and errs[-1][2] < 0.6 / 80 ** 2, "hload %s: n=80 errors %s" % (law, errs[-1]))


# --- 4. temperature and prestress ----------------------------------------------------------
TAUT = """units kN m
material m E=2e8 strain=%s alpha=1.2e-5
section s material=m A=3e-4
node 1 0 0 0 fix=xyz
node 2 30 40 0 fix=xyz
"""


def case_prestress_temperature():
    EA = 2e8 * 3e-4
    for law in ("engineering", "green-lagrange"):
        lam_eps = (1.001 if law == "engineering" else math.sqrt(1.002))
        for key, want in (("N0=50", 50.0), ("s0=200000", 60.0), ("eps0=0.001", tension(lam_eps, EA, law))):
            what = "prestress %s %s" % (law, key)
            res = solve(TAUT % law + "cable 1 2 section=s n=5 length=50 shape=straight %s\n" % key, what)
            if res:
                for e in res["elements"]:
                    need(abs(e["force"] - want) < 1e-11 * want, "%s: element %d force %.17g" % (what, e["id"], e["force"]))
        for dT in (30.0, -40.0):
            what = "temperature %s dT=%g" % (law, dT)
            res = solve(TAUT % law + "cable 1 2 section=s n=5 length=49.9 shape=straight\ntemperature all dT=%g\n" % dT, what)
            if res is None:
                continue
            lam = 50.0 / (49.9 * (1 + 1.2e-5 * dT))
            N = tension(lam, EA, law)
            eps = lam - 1 if law == "engineering" else (lam * lam - 1) / 2
            for e in res["elements"]:
                need(abs(e["force"] - N) < 1e-11 * N and abs(e["strain"] - eps) < 1e-12 * eps,
                     "%s: element %d force %.17g strain %.17g, closed form %.17g %.17g" % (what, e["id"], e["force"], e["strain"], N, eps))
            R = reactions(res)
            need(norm(sub(R[1], mul(-N / 50, (30, 40, 0)))) < 1e-11 * N, "%s: reaction %s" % (what, R[1]))
        # in steps: the first step unheated, then +20 K in 3 substeps, then element 3 -10 K more
        what = "temperature steps %s" % law
        res = solve(TAUT % law + "cable 1 2 section=s n=5 length=49.9 shape=straight\n"
                    "step a\nstep b substeps=3\ntemperature all dT=20\nstep c\ntemperature 3 dT=-10\n", what)
        if res:
            for st, dts in zip(res["steps"], ((0,) * 5, (20,) * 5, (20, 20, 10, 20, 20))):
                l0 = [9.98 * (1 + 1.2e-5 * t) for t in dts]
                # series chain: one force N; sum of stretched lengths = 50
                lo, hi = 0.0, 1e4
                for _ in range(200):
                    N = 0.5 * (lo + hi)
                    if sum(L * stretch(N, EA, law) for L in l0) < 50:
                        lo = N
                    else:
                        hi = N
                for e in st["elements"]:
                    need(abs(e["force"] - N) < 1e-10 * N, "%s step %s: element %d force %.17g, closed form %.17g" % (what, st["name"], e["id"], e["force"], N))
    # a sagging span heated and cooled, one catenary element: Irvine with the expanded
    # length L0 (1 + alpha dT) and the same weight w L0
    A, B, g, w, E, area, al, L0 = (0, 0, 0), (200, 0, 30), (0, 0, -1), 0.1, 2e8, 3.14e-4, 1.2e-5, 205.0
    e_h, up, span, rise = frame(A, B, g)
    for dT in (60.0, -80.0):
        what = "catenary element dT=%g" % dT
        res = solve("units kN m\ngravity 0 0 -1\nmaterial m E=2e8 strain=engineering alpha=1.2e-5\n"
                    "section s material=m A=3.14e-4 w=0.1\nnode 1 0 0 0 fix=xyz\nnode 2 200 0 30 fix=xyz\n"
                    "catenary 7 1 2 section=s length=205\ntemperature all dT=%g\n" % dT, what)
        if res is None:
            continue
        Le = L0 * (1 + al * dT)
        H, V0 = elastic_catenary(span, rise, Le, w * L0 / Le, E * area, "engineering")
        R = reactions(res)
        ref = mul(-1.0, add(mul(H, e_h), mul(V0, up)))
        need(norm(sub(R[1], ref)) < 1e-11 * H, "%s: reaction %s, Irvine %s" % (what, R[1], ref))
        need(abs(dot(add(R[1], R[2]), up) - w * L0) < 1e-11 * w * L0, "%s: the weight changed with temperature" % what)


# --- 5. load histories, displaced supports, springs ------------------------------------
PAPER = """units kN m
gravity 0 -1 0
material steel E=2.0e8 alpha=1.2e-5
section strand material=steel A=3.14e-4 w=0.1
node 1 0 0 0 fix=xyz
node 2 200 0 0 fix=xyz
cable 1 2 section=strand n=20 length=200.3340
"""
STEPS = ("", "load 13 0 -5 0\nload 8 1 -2 3\n", "displace 2 x=0.5 y=-0.3\ntemperature all dT=25\nhload q=0.2 elements=3-9\n")


def state_diff(a, b):
    X, Y = positions(a), positions(b)
    RA, RB = reactions(a), reactions(b)
    return (max(norm(sub(X[i], Y[i])) for i in X), max(norm(sub(RA[i], RB[i])) for i in RA),
            max(abs(x["force"] - y["force"]) for x, y in zip(a["elements"], b["elements"])))


def case_steps():
    res = solve(PAPER + "step sw\n" + STEPS[0] + "step point substeps=4\n" + STEPS[1] + "step pull substeps=2\n" + STEPS[2],
                "three steps")
    if res is None:
        return
    for k, st in enumerate(res["steps"]):
        one = solve(PAPER + "".join(STEPS[:k + 1]), "one-step solve of step %d's loads" % (k + 1))
        if one:
            dx, dr, df = state_diff(st, one)
            need(dx < 1e-11 and dr < 1e-9 and df < 1e-9, "step %s differs from a one-step solve of its loads: %g m, %g kN, %g kN" % (st["name"], dx, dr, df))
    need(state_diff(res, res["steps"][-1]) == (0, 0, 0), "the top-level state is not the last step's")
    last = res["steps"][-1]
    X = positions(last)
    need(abs(X[2][0] - 200.5) < 1e-12 and abs(X[2][1] + 0.3) < 1e-12, "the displaced support is at %s" % (X[2],))
    loads = {}
    for e in last["elements"]:
        a, b = e["nodes"]
        loads[e["id"]] = (0.0, -0.1 * e["l0"], 0.0)
        if 3 <= e["id"] <= 9:
            c = sub(X[b], X[a])
            loads[e["id"]] = add(loads[e["id"]], (0.0, -0.2 * math.hypot(c[0], c[2]), 0.0))
    check_residual(last, {13: (0, -5, 0), 8: (1, -2, 3)}, loads, "the last step")


def case_springs_reactions():
    what = "spring-held sliding end"
    res = solve("material steel E=2e8\nsection c material=steel A=1e-4 w=0.2\ngravity 0 0 -1\n"
                "node 1 0 0 0 fix=xyz\nnode 2 40 0 0 fix=yz\nnode 3 41 0 0 fix=xyz\n"
                "cable 1 2 section=c n=16 length=41\nspring 100 2 3 k=50\nload 2 3 0 0\n", what)
    if res:
        X, R = positions(res), reactions(res)
        sp = [e for e in res["elements"] if e["id"] == 100][0]
        N = 50 * (norm(sub(X[3], X[2])) - 1.0)
        need(abs(sp["force"] - N) < 1e-12 * N, "%s: spring force %.17g, k (l - l0) = %.17g" % (what, sp["force"], N))
        # the support of the spring pulls the structure towards it: +x
        need(abs(R[3][0] - N) < 1e-12 * N and R[3][1] == 0 and R[3][2] == 0, "%s: spring support reaction %s" % (what, R[3]))
        need(R[2][0] == 0, "%s: a reaction along the free direction x of node 2" % what)
        need(norm(add(add(add(R[1], R[2]), R[3]), (3.0, 0.0, -0.2 * 41))) < 1e-10, "%s: the reactions do not balance the loads" % what)
        check_residual(res, {2: (3, 0, 0)}, {e["id"]: (0, 0, -0.2 * e["l0"]) for e in res["elements"] if e["id"] != 100}, what)
    # a deck load on "all" elements: the cable's horizontal projection carries it, the
    # spring that holds the cable's end none (as temperature passes over springs)
    what = "hload over a cable and a spring"
    res = solve("material steel E=2e8\nsection c material=steel A=1e-4 w=0.2\ngravity 0 0 -1\n"
                "node 1 0 0 0 fix=xyz\nnode 2 40 0 0 fix=yz\nnode 3 41 0 0 fix=xyz\n"
                "cable 1 2 section=c n=16 length=41\nspring 100 2 3 k=50\nhload q=2\n", what)
    if res:
        X = positions(res)
        deck = 2 * (X[2][0] - X[1][0])
        Rz = sum(r[2] for r in reactions(res).values())
        need(abs(Rz - 0.2 * 41 - deck) < 1e-10 * Rz, "%s: vertical reactions %.17g, weight and deck %.17g" % (what, Rz, 0.2 * 41 + deck))
        loads = {}
        for e in res["elements"]:
            if e["id"] != 100:
                a, b = e["nodes"]
                loads[e["id"]] = (0.0, 0.0, -0.2 * e["l0"] - 2 * math.hypot(X[b][0] - X[a][0], X[b][1] - X[a][1]))
        check_residual(res, {}, loads, what)
    # loads on fixed DOFs go into the reactions (R = f_int - f_ext)
    what = "loads on fixed DOFs"
    loads = {3: (0, -10, 7), 2: (1, 2, 3), 1: (4, 5, 6)}
    res = solve("units kN m\nmaterial m E=2e8 strain=engineering\nsection s material=m A=1e-4\n"
                "node 1 0 0 0 fix=xyz\nnode 2 10 0 0 fix=yz\nnode 3 5 -1 0 fix=z\nnode 4 20 0 0 fix=xyz\n"
                "element 1 1 3 section=s\nelement 2 3 2 section=s\nspring 3 2 4 k=1000\n"
                + "".join("load %d %g %g %g\n" % ((n,) + f) for n, f in loads.items()), what)
    if res:
        R = reactions(res)
        need(R[3] == (0, 0, -7), "%s: node 3's reaction %s (its z load is 7)" % (what, R[3]))
        check_residual(res, loads, {}, what)
    # a displaced support of a taut bar: N = EA (l / l0 - 1) at the new distance
    what = "displaced support"
    res = solve(TAUT % "engineering" + "element 1 1 2 section=s l0=49.95\ndisplace 2 x=0.03 y=0.04\n", what)
    if res:
        N = 2e8 * 3e-4 * (50.05 / 49.95 - 1)
        R = reactions(res)
        need(abs(res["elements"][0]["force"] - N) < 1e-11 * N, "%s: force %.17g, closed form %.17g" % (what, res["elements"][0]["force"], N))
        need(norm(sub(R[2], mul(N / 50, (30, 40, 0)))) < 1e-11 * N, "%s: reaction %s" % (what, R[2]))


def case_arclength():
    base = ("units kN m\nmaterial steel E=2.0e8 strain=engineering\nsection rod material=steel A=1e-4\n"
            "node 1 0 0 0 fix=xyz\nnode 2 10 0 0 fix=xyz\nnode 3 5 -1 0 fix=z\n"
            "element 1 1 3 section=rod\nelement 2 3 2 section=rod\n")
    a = solve(base + "load 3 0 -10 0\nsolve method=arclength steps=4 lambda=3\n", "arc-length to lambda 3")
    if a is None:
        return
    need(abs(a["load_factor"] - 3) < 1e-12, "arc-length stopped at %.17g" % a["load_factor"])
    C = two_segments((0, 0, 0), (10, 0, 0), math.hypot(5, 1), math.hypot(5, 1), (0, -30, 0), 2e4, "engineering", (5, -2, 0))
    need(norm(sub(positions(a)[3], C)) < 1e-11, "arc-length at lambda 3: %s, closed form %s" % (positions(a)[3], C))
    check_residual(a, {3: (0, -30, 0)}, {}, "arc-length at lambda 3")


CASES = {"catenary": case_catenary, "point_load": case_point_load, "parabola": case_parabola,
         "prestress_temperature": case_prestress_temperature, "steps": case_steps,
         "springs_reactions": case_springs_reactions, "arclength": case_arclength}

if __name__ == "__main__":
    CASES[sys.argv[2]]()
    for p in PROBLEMS:
        print(p)
    sys.exit(1 if PROBLEMS else 0)
