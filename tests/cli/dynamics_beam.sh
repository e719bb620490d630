#!/usr/bin/env bash
# tests/cli/dynamics_beam.sh CATENA: beams in a dynamics analysis (issue 26): 6-DOF nodes
# with rotary inertia, the rotations turned by spins and integrated by Newmark on the
# material rotation increment (src/analysis/dynamics/dyn_rot.c).
#   - tests/models/dynamics/beam_cantilever.cable: a cantilever released from a static
#     tip deflection. The tip's history, fitted by least squares with two harmonics (the
#     first frequency searched, the second the modal analysis's next mode in z), gives
#     f1 within 2e-5 of the modal analysis's f1 as the trapezoidal rule shifts it
#     ((2 / dt) atan(w dt / 2), exact for a linear mode: 3.4e-4 here), and, that shift
#     taken out, within 5e-4 of Euler-Bernoulli's closed form (the mesh: the beam's mass
#     interpolates translations linearly, O(h^2), measured -2.4e-4 at n = 20);
#   - tests/models/dynamics/beam_pendulum.cable (a stiff beam pinned at one end, swung
#     from horizontal through 180 deg) at dt = 4e-3 and 2e-3: the energy balance's
#     largest error falls by 4 (3.5 to 4.6: O(dt^2)) and is below 1e-4 at 4e-3; the
#     period from two passages under the pin is the elliptic integral's within 1e-4 and
#     its error falls by 3 or more when dt halves;
#   - tests/models/dynamics/beam_top.cable (a section of unequal inertias turned 45 deg
#     about the member, swung from horizontal: the motion leaves its plane, uz > 0.05)
#     at dt = 2e-3 and 1e-3: the tip against the rigid body's motion about the pin
#     (Euler's equations integrated by RK4 here) within 1e-4, falling by 3.5 to 4.5
#     (without the gyroscopic term W x J W it is 0.13 off: measured by taking it out);
#     the energy balance's error falling by 3.5 to 4.6 (which the gyroscopic term does
#     not decide: it does no work); the same with `damping alpha=0.5` against the rigid
#     body with -alpha I W; method=central on a softer member against the implicit method
#     (same lumped mass) and the rigid body of the lumped inertia;
#   - the cantilever with a tip mass, modal and Rayleigh damping: the first mode's damping
#     ratio from the decay of the tip within 1e-3 of the closed form;
#   - a clamped cantilever's support force and moment (record ... reaction: fx .. mz) in
#     equilibrium with the nodes' inertia (rates rebuilt by Newmark's relations) and the
#     loads within 1e-8;
#   - method=central above the stable step of the rotary inertia refused (exit 2).
# Prints "N passed, N failed"; exit 1 on any failure.
# ctest-cost: 6
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init dynamics_beam "${1:-}"

"$BIN" solve tests/models/dynamics/beam_cantilever.cable -q -o "$T/c" 2>"$T/err"; rc=$?
[ $rc -eq 0 ] || WHY+=("cantilever: exit $rc: $(cat "$T/err")")
if [ $rc -eq 0 ] && [ $have_python = 1 ]; then
    msg=$(python3 - "$T/c" <<'PY'
import csv, json, math, sys
d = sys.argv[1]
js = json.load(open(d + "/result.json"))
zm = sorted(js["modes"], key=lambda m: -m["effective_mass"]["z"])[:2]
f1, f2 = sorted(m["frequency"] for m in zm)
rows = [[float(v) for v in r] for r in list(csv.reader(open(d + "/history.csv")))[1:]]
t, x = [r[0] for r in rows], [r[1] for r in rows]
w2 = 2 * math.pi * f2

def solve(A, b):
    n = len(b)
    M = [A[i][:] + [b[i]] for i in range(n)]
    for k in range(n):
        p = max(range(k, n), key=lambda i: abs(M[i][k]))
        M[k], M[p] = M[p], M[k]
        for i in range(k + 1, n):
            f = M[i][k] / M[k][k]
            for j in range(k, n + 1):
                M[i][j] -= f * M[k][j]
    y = [0.0] * n
    for k in reversed(range(n)):
        y[k] = (M[k][n] - sum(M[k][j] * y[j] for j in range(k + 1, n))) / M[k][k]
    return y

def residual(w):
    B = [[math.cos(w * s), math.sin(w * s), math.cos(w2 * s), math.sin(w2 * s)] for s in t]
    A = [[sum(r[i] * r[j] for r in B) for j in range(4)] for i in range(4)]
    b = [sum(r[i] * xi for r, xi in zip(B, x)) for i in range(4)]
    c = solve(A, b)
    return sum((xi - sum(ci * ri for ci, ri in zip(c, r))) ** 2 for r, xi in zip(B, x))

lo, hi, g = 2 * math.pi * f1 * 0.98, 2 * math.pi * f1 * 1.02, (math.sqrt(5) - 1) / 2
for _ in range(50):
    a, b = hi - g * (hi - lo), lo + g * (hi - lo)
    if residual(a) < residual(b): hi = b
    else: lo = a
fd = (lo + hi) / 4 / math.pi
dt = 1.4e-3
ftr = 2 / dt * math.atan(2 * math.pi * f1 * dt / 2) / (2 * math.pi)
EI, m, L, bl = 2.1e11 * 1e-7, 7.85, 2.0, 1.8751040687119611
feb = bl * bl * math.sqrt(EI / (m * L ** 4)) / (2 * math.pi)
e_tr, e_eb = fd / ftr - 1, fd * f1 / ftr / feb - 1          # e_eb: the integrator's shift taken out
print("f1 %.9g: vs the modal analysis through the trapezoidal rule %.3g, vs Euler-Bernoulli %.3g" % (fd, e_tr, e_eb),
      file=sys.stderr)
why = []
if not abs(e_tr) < 2e-5: why.append("f1 %.9g off the modal %.9g (trapezoidal %.9g) by %.3g" % (fd, f1, ftr, e_tr))
if not abs(e_eb) < 5e-4: why.append("f1 %.9g (shift taken out) off Euler-Bernoulli %.9g by %.3g" % (fd * f1 / ftr, feb, e_eb))
print("; ".join(why))
PY
)
    [ -z "$msg" ] || WHY+=("$msg")
fi
finish "a cantilever's free vibration: the modal analysis and Euler-Bernoulli"

for dt in 4e-3 2e-3; do
    sed "s/^dynamics dt=2e-3/dynamics dt=$dt/" tests/models/dynamics/beam_pendulum.cable >"$T/p$dt.cable"
    "$BIN" solve "$T/p$dt.cable" -q -o "$T/p$dt" 2>"$T/err"; rc=$?
    [ $rc -eq 0 ] || WHY+=("pendulum dt=$dt: exit $rc: $(cat "$T/err")")
done
if [ ${#WHY[@]} -eq 0 ] && [ $have_python = 1 ]; then
    msg=$(python3 - "$T" <<'PY'
import csv, json, math, sys
d = sys.argv[1]
I, mgd, K = 1 / 3 + 1e-3, 9.81 * 0.5, 1.8540746773013719       # K(m = 1/2)
T = 4 * math.sqrt(I / mgd) * K
why, err, per = [], [], []
for dt in ("4e-3", "2e-3"):
    js = json.load(open("%s/p%s/result.json" % (d, dt)))["dynamics"]
    err.append(js["energy_error"])
    rows = [[float(v) for v in r] for r in list(csv.reader(open("%s/p%s/history.csv" % (d, dt))))[1:]]
    c = []                                   # the tip under the pin: x = 1 + ux = 0
    for a, b in zip(rows, rows[1:]):
        xa, xb = 1 + a[1], 1 + b[1]
        if (xa < 0) != (xb < 0): c.append(a[0] + (b[0] - a[0]) * xa / (xa - xb))
    if len(c) < 2:
        why.append("dt=%s: %d passages under the pin" % (dt, len(c)))
        continue
    per.append(2 * (c[1] - c[0]) / T - 1)
print("energy errors %r (ratio %.3g), period errors %r" % (err, err[0] / err[1], per), file=sys.stderr)
if not (3.5 < err[0] / err[1] < 4.6 and err[0] < 1e-4): why.append("energy errors %r: not O(dt^2)" % err)
if len(per) == 2 and not (abs(per[0]) < 1e-4 and abs(per[0]) > 3 * abs(per[1])):
    why.append("period errors %r (T = %.9g)" % (per, T))
print("; ".join(why))
PY
)
    [ -z "$msg" ] || WHY+=("$msg")
fi
finish "a beam pendulum swung through 180 deg: energy to O(dt^2), the elliptic period"

top=tests/models/dynamics/beam_top.cable
for dt in 2e-3 1e-3; do
    sed "s/^dynamics dt=2e-3/dynamics dt=$dt/" $top >"$T/g$dt.cable"
    sed "s/^dynamics dt=2e-3/damping alpha=0.5 beta=0\ndynamics dt=$dt/" $top >"$T/gd$dt.cable"
done
# central differences on a softer member (E = 2.5e6: a stable step of 2.6e-5 s set by
# the rotary inertia), against the implicit method on the same lumped mass
sed -e 's/E=1e8/E=2.5e6/' -e 's/^dynamics .*/dynamics dt=2e-5 t_end=0.3 method=central output_every=25/' $top >"$T/gc.cable"
sed -e 's/E=1e8/E=2.5e6/' -e 's/^dynamics .*/dynamics dt=5e-4 t_end=0.3 method=genalpha rho_inf=1 mass=lumped/' $top >"$T/gl.cable"
for g in g2e-3 g1e-3 gd2e-3 gd1e-3 gc gl; do
    "$BIN" solve "$T/$g.cable" -q -o "$T/$g" 2>"$T/err"; rc=$?
    [ $rc -eq 0 ] || WHY+=("3D pendulum $g: exit $rc: $(cat "$T/err")")
done
if [ ${#WHY[@]} -eq 0 ] && [ $have_python = 1 ]; then
    msg=$(python3 - "$T" <<'PY'
import csv, json, math, sys
d = sys.argv[1]
# the rigid body about the pin: Euler's equations I W' + W x I W = tau - alpha I W in the
# body frame (alpha: the mass-proportional damping on every mass and rotary inertia),
# I = c rho A L^3 (1 - e1 e1^T) + L (rho J e1 e1^T + rho Iy e2 e2^T + rho Iz e3 e3^T)
# (c = 1/3 for the consistent mass, sum m_i x_i^2 / (rho A L^3) = 3/8 for the lumped
# one of two elements), q' = q (0, W) / 2, by RK4 (h = 5e-4); the tip at R (L, 0, 0)
L, rA, g = 1.0, 1.0, 9.81
s2 = 1 / math.sqrt(2)
e1, e2, e3 = (1, 0, 0), (0, s2, -s2), (0, s2, s2)
rJ, rIy, rIz = 0.055, 0.05, 0.005
def inv3(a):
    c = [[a[(j+1)%3][(i+1)%3]*a[(j+2)%3][(i+2)%3] - a[(j+1)%3][(i+2)%3]*a[(j+2)%3][(i+1)%3] for j in range(3)] for i in range(3)]
    det = sum(a[0][k] * c[k][0] for k in range(3))
    return [[c[i][j] / det for j in range(3)] for i in range(3)]
mv = lambda a, x: [sum(a[i][k] * x[k] for k in range(3)) for i in range(3)]
cr = lambda a, b: [a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0]]
def rot(q):
    w, x, y, z = q
    return [[1-2*(y*y+z*z), 2*(x*y-w*z), 2*(x*z+w*y)], [2*(x*y+w*z), 1-2*(x*x+z*z), 2*(y*z-w*x)], [2*(x*z-w*y), 2*(y*z+w*x), 1-2*(x*x+y*y)]]
def tip(times, alpha=0.0, c=1 / 3):
    I = [[c * rA * L ** 3 * ((i == j) - e1[i] * e1[j]) + L * (rJ * e1[i] * e1[j] + rIy * e2[i] * e2[j] + rIz * e3[i] * e3[j])
          for j in range(3)] for i in range(3)]
    Ii = inv3(I)
    def f(s):
        q, W = s[:4], s[4:]
        R = rot(q)
        gb = [sum(R[k][i] * (0, -rA * L * g, 0)[k] for k in range(3)) for i in range(3)]   # R^T F
        tau = cr((L / 2, 0, 0), gb)
        JW = mv(I, W)
        Wd = [a - alpha * w for a, w in zip(mv(Ii, [tau[i] - cr(W, JW)[i] for i in range(3)]), W)]
        w, x, y, z = q
        qd = [0.5 * (-x*W[0] - y*W[1] - z*W[2]), 0.5 * (w*W[0] + y*W[2] - z*W[1]), 0.5 * (w*W[1] + z*W[0] - x*W[2]), 0.5 * (w*W[2] + x*W[1] - y*W[0])]
        return qd + Wd
    s, t, h, out = [1.0, 0, 0, 0, 0, 0, 0], 0.0, 5e-4, []
    for tr in times:
        while t < tr - 1e-12:
            hh = min(h, tr - t)
            k1 = f(s); k2 = f([a + hh/2*b for a, b in zip(s, k1)]); k3 = f([a + hh/2*b for a, b in zip(s, k2)]); k4 = f([a + hh*b for a, b in zip(s, k3)])
            s = [a + hh/6*(b + 2*c + 2*dd + e) for a, b, c, dd, e in zip(s, k1, k2, k3, k4)]
            n = math.sqrt(sum(v*v for v in s[:4])); s[:4] = [v / n for v in s[:4]]
            t += hh
        R = rot(s[:4])
        out.append((R[0][0] * L - L, R[1][0] * L, R[2][0] * L))
    return out
def rows(name):
    return [[float(v) for v in r] for r in list(csv.reader(open("%s/%s/history.csv" % (d, name))))[1:]]
def off(rs, ref):
    return max(math.sqrt(sum((r[1 + k] - u[k]) ** 2 for k in range(3))) for r, u in zip(rs, ref))
energy = lambda name: json.load(open("%s/%s/result.json" % (d, name)))["dynamics"]["energy_error"]
why = []
for tag, alpha in (("g", 0.0), ("gd", 0.5)):
    fine = rows(tag + "1e-3")
    ref = dict(zip((r[0] for r in fine), tip([r[0] for r in fine], alpha)))
    err, en = [], []
    for dt in ("2e-3", "1e-3"):
        rs = rows(tag + dt)
        err.append(off(rs, [ref[r[0]] for r in rs]))
        en.append(energy(tag + dt))
    uz = max(abs(r[3]) for r in fine)
    print("3D alpha=%g: tip vs the rigid body %r (ratio %.3g), energy errors %r (ratio %.3g), largest |uz| %.3g"
          % (alpha, err, err[0] / err[1], en, en[0] / en[1], uz), file=sys.stderr)
    if not uz > 0.05: why.append("alpha=%g: the motion stays in its plane: |uz| <= %.3g" % (alpha, uz))
    if not (err[0] < 1e-4 and 3.5 < err[0] / err[1] < 4.5):
        why.append("alpha=%g: tip errors %r vs the rigid body: not O(dt^2) below 1e-4" % (alpha, err))
    if not (3.5 < en[0] / en[1] < 4.6 and en[0] < 5e-5): why.append("alpha=%g: energy errors %r: not O(dt^2)" % (alpha, en))
# central differences: against the implicit method on the same (lumped, flexible) model,
# and the rigid body of the lumped inertia (c = 3/8) within the member's bending
rc, rl = rows("gc"), rows("gl")
il = dict((round(r[0], 9), r) for r in rl)
e_im = max(math.sqrt(sum((r[1 + k] - il[round(r[0], 9)][1 + k]) ** 2 for k in range(3))) for r in rc if round(r[0], 9) in il)
e_rb = off(rc, tip([r[0] for r in rc], 0.0, 3 / 8))
e_en = energy("gc")
print("central: vs the implicit method (dt = 5e-4) %.3g, vs the rigid body %.3g, energy error %.3g, %d rows"
      % (e_im, e_rb, e_en, len(rc)), file=sys.stderr)
if not (e_im < 2e-5 and e_rb < 5e-5 and e_en < 1e-6):
    why.append("central: %.3g off the implicit method, %.3g off the rigid body, energy error %.3g" % (e_im, e_rb, e_en))
print("; ".join(why))
PY
)
    [ -z "$msg" ] || WHY+=("$msg")
fi
finish "a beam pendulum off its principal axes (undamped, damped, central differences): the rigid body's motion, energy to O(dt^2)"

# damping on the rotations: the cantilever with a tip mass (20, beside the beam's 7.85;
# its first mode dominates the tip), released from a small tip deflection (1.27e-4: K_0 at
# the start is the straight beam's; a start deflected by 1e-3 rad sees the axial stiffness
# through that turn and takes 1.3 % more beta damping), by modal and by Rayleigh damping.
# The tip's history fitted with e^{-s t} (a cos w t + b sin w t) (golden sections in w and
# s, least squares in a, b) is the trapezoidal rule's z = e^{(-s + i w) h} per step, whose
# continuous root (2 / h) (z - 1) / (z + 1) has the mode's omega and damping ratio.
cant=tests/models/dynamics/beam_cantilever.cable
for dmp in "modal=0.05 modes=4" "alpha=0.9 beta=5e-4"; do
    k=${dmp%%=*}
    sed -e 's/^node 2 2 0 0$/node 2 2 0 0 mass=20/' -e 's/n=20/n=10/' -e 's/^load 2 0 0 -10/load 2 0 0 -1/' \
        -e 's/^load 2 0 0 10 fn=release/load 2 0 0 1 fn=release/' -e 's/^modes count=3/modes count=1/' \
        -e "s/^dynamics .*/damping $dmp\ndynamics dt=2.8e-3 t_end=1.0 method=genalpha rho_inf=1/" $cant >"$T/k$k.cable"
    "$BIN" solve "$T/k$k.cable" -q -o "$T/k$k" 2>"$T/err"; rc=$?
    [ $rc -eq 0 ] || WHY+=("damped cantilever ($dmp): exit $rc: $(cat "$T/err")")
done
if [ ${#WHY[@]} -eq 0 ] && [ $have_python = 1 ]; then
    msg=$(python3 - "$T" <<'PY'
import cmath, csv, json, math, sys
d = sys.argv[1]
def golden(f, lo, hi, n=40):
    g = (math.sqrt(5) - 1) / 2
    for _ in range(n):
        a, b = hi - g * (hi - lo), lo + g * (hi - lo)
        if f(a) < f(b): hi = b
        else: lo = a
    return (lo + hi) / 2
def fit(name, w0):
    rows = [[float(v) for v in r] for r in list(csv.reader(open("%s/%s/history.csv" % (d, name))))[1:]]
    t, x = [r[0] for r in rows], [r[1] for r in rows]
    def residual(sg, w):
        B = [(math.exp(-sg * s) * math.cos(w * s), math.exp(-sg * s) * math.sin(w * s)) for s in t]
        a11, a12, a22 = (sum(b[i] * b[j] for b in B) for i, j in ((0, 0), (0, 1), (1, 1)))
        r1, r2 = (sum(b[i] * xi for b, xi in zip(B, x)) for i in (0, 1))
        det = a11 * a22 - a12 * a12
        c1, c2 = (r1 * a22 - r2 * a12) / det, (a11 * r2 - a12 * r1) / det
        return sum((xi - c1 * b[0] - c2 * b[1]) ** 2 for b, xi in zip(B, x))
    sg, w = 0.0, w0
    for _ in range(3):
        w = golden(lambda v: residual(sg, v), 0.97 * w0, 1.03 * w0)
        sg = golden(lambda v: residual(v, w), -0.1 * w0, 0.3 * w0)
    h = t[1] - t[0]
    z = cmath.exp(complex(-sg, w) * h)
    s = 2 / h * (z - 1) / (z + 1)
    return abs(s), -s.real / abs(s)
why = []
for k, zeta in (("modal", lambda w: 0.05), ("alpha", lambda w: 0.9 / (2 * w) + 5e-4 * w / 2)):
    w1 = 2 * math.pi * json.load(open("%s/k%s/result.json" % (d, k)))["modes"][0]["frequency"]
    w, z = fit("k" + k, w1)
    print("damped cantilever (%s): omega %.9g (modal %.9g, %.2g), zeta %.9g (%.9g, %.2g)"
          % (k, w, w1, w / w1 - 1, z, zeta(w1), z / zeta(w1) - 1), file=sys.stderr)
    if not (abs(w / w1 - 1) < 1e-4 and abs(z / zeta(w1) - 1) < 1e-3):
        why.append("%s damping: omega %.9g (modal %.9g), zeta %.9g, expected %.9g" % (k, w, w1, z, zeta(w1)))
print("; ".join(why))
PY
)
    [ -z "$msg" ] || WHY+=("$msg")
fi
finish "a damped cantilever (modal, Rayleigh on the rotations too): the mode's damping ratio from the decay"

# reactions with moments: a cantilever of 5 beams (lumped mass, mass-proportional damping)
# from rest under a held tip force and moment, by Newmark's average acceleration. Each
# node's velocity and acceleration follow from its displacements exactly, as the method
# relates them, v(n+1) = 2 (d(n+1) - d(n)) / h - v(n), a(n+1) = 4 (d(n+1) - d(n) - h v(n)) / h^2
# - a(n) (from rest: v(0) = 0, a(0) = M^-1 (F, M) at the tip); the support's force at each
# t_n is then sum m_i (a_i + alpha v_i) - F (the elements' forces sum to zero) to the
# solver's tolerance, and its moment sum x_i x m_i (a_i + alpha v_i) + J_i (alpha_i + alpha
# w_i) - x_tip x F - M (the rotations' rates as the rotation vector's: small rotations).
{
    printf 'material steel E=2.1e11 nu=0.3\nsection tube material=steel A=1e-3 Iy=1e-7 Iz=1e-7 J=2e-7 mass=7.85\n'
    printf 'node 1 0 0 0 fix=xyzrxryrz\n'
    for k in 2 3 4 5 6; do printf 'node %d %s 0 0\n' $k "$(echo "0.4 * ($k - 1)" | bc -l)"; done
    for k in 1 2 3 4 5; do printf 'beam %d %d %d section=tube orient=0,0,1\n' $k $k $((k + 1)); done
    printf 'load 6 0 5 -10\nmoment 6 2 0 0\ndamping alpha=0.3 beta=0\n'
    printf 'dynamics dt=1e-3 t_end=0.3 method=newmark mass=lumped\nrecord node=1 reaction\n'
    for k in 2 3 4 5 6; do printf 'record node=%d dof=ux,uy,uz,rx,ry,rz\n' $k; done
} >"$T/eq.cable"
"$BIN" solve "$T/eq.cable" -q -o "$T/eq" 2>"$T/err"; rc=$?
[ $rc -eq 0 ] || WHY+=("cantilever's reactions: exit $rc: $(cat "$T/err")")
if [ $rc -eq 0 ] && [ $have_python = 1 ]; then
    msg=$(python3 - "$T/eq" <<'PY'
import csv, math, sys
rows = list(csv.reader(open(sys.argv[1] + "/history.csv")))
col = {n: i for i, n in enumerate(rows[0])}
rows = [[float(v) for v in r] for r in rows[1:]]
h, al, F, M = rows[1][0] - rows[0][0], 0.3, (0, 5, -10), (2, 0, 0)
m = {k: 7.85 * (0.2 if k == 6 else 0.4) for k in range(2, 7)}              # half of each element
J = {k: [2 * 7850e-7 * m[k] / 7.85, 7850e-7 * m[k] / 7.85, 7850e-7 * m[k] / 7.85] for k in range(2, 7)}
cr = lambda a, b: (a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0])
Q = ("ux", "uy", "uz", "rx", "ry", "rz")
ef = em = sf = sm = 0.0
def quat(p):
    t = math.sqrt(sum(v * v for v in p)); s = math.sin(t / 2) / t if t > 1e-12 else 0.5
    return (math.cos(t / 2), s * p[0], s * p[1], s * p[2])
def rmat(q):
    w, x, y, z = q
    return [[1-2*(y*y+z*z), 2*(x*y-w*z), 2*(x*z+w*y)], [2*(x*y+w*z), 1-2*(x*x+z*z), 2*(y*z-w*x)], [2*(x*z-w*y), 2*(y*z+w*x), 1-2*(x*x+y*y)]]
def log_rel(a, b):                                      # log(R_a^T R_b): conj(a) b
    w = sum(x * y for x, y in zip(a, b))
    v = [a[0] * b[k + 1] - b[0] * a[k + 1] - (a[(k + 1) % 3 + 1] * b[(k + 2) % 3 + 1] - a[(k + 2) % 3 + 1] * b[(k + 1) % 3 + 1]) for k in range(3)]
    s = math.sqrt(sum(x * x for x in v)); f = 2 * math.atan2(s, w) / s if s > 1e-14 else 2 / w
    return [f * x for x in v]
mv = lambda A, x: [sum(A[i][j] * x[j] for j in range(3)) for i in range(3)]
P = {}
for k in range(2, 7):                                   # the rates, by the method's own relations
    load = list(F) + list(M) if k == 6 else [0.0] * 6
    for i, q in enumerate(Q[:3]):                       # translations: Newmark on d
        d = [r[col["%d.%s" % (k, q)]] for r in rows]
        v, a = [0.0], [load[i] / m[k]]
        for n in range(len(d) - 1):
            v.append(2 * (d[n + 1] - d[n]) / h - v[n])
            a.append(4 * (d[n + 1] - d[n] - h * v[n]) / h ** 2 - a[n])
        P[k, q] = [m[k] * (a[n] + al * v[n]) for n in range(len(d))]
    # rotations: Newmark on the material increment log(R_n^T R_n+1) (body-frame W, A; J
    # diagonal, the member along x), the moment R (J A + W x J W) + alpha R J W
    qs = [quat([r[col["%d.%s" % (k, q)]] for q in Q[3:]]) for r in rows]
    mom = []
    W, A = [0.0] * 3, [load[3 + c] / J[k][c] for c in range(3)]
    for n, r in enumerate(rows):
        if n:
            th = log_rel(qs[n - 1], qs[n])
            A1 = [(th[c] - h * W[c] - h * h / 4 * A[c]) / (h * h / 4) for c in range(3)]
            W = [W[c] + h / 2 * (A[c] + A1[c]) for c in range(3)]
            A = A1
        JW = [J[k][c] * W[c] for c in range(3)]
        body = [J[k][c] * A[c] + W[(c + 1) % 3] * JW[(c + 2) % 3] - W[(c + 2) % 3] * JW[(c + 1) % 3] + al * JW[c] for c in range(3)]
        mom.append(mv(rmat(qs[n]), body))
    for c, q in enumerate(Q[3:]):
        P[k, q] = [x[c] for x in mom]
for n, r in enumerate(rows):
    got = [r[col["1." + q]] for q in ("fx", "fy", "fz", "mx", "my", "mz")]
    xt = (2.0 + r[col["6.ux"]], r[col["6.uy"]], r[col["6.uz"]])
    f, mo = [-F[i] for i in range(3)], [-M[i] - cr(xt, F)[i] for i in range(3)]
    for k in range(2, 7):
        p = [P[k, q][n] for q in Q]
        x = (0.4 * (k - 1) + r[col["%d.ux" % k]], r[col["%d.uy" % k]], r[col["%d.uz" % k]])
        f = [f[i] + p[i] for i in range(3)]
        mo = [mo[i] + cr(x, p[:3])[i] + p[3 + i] for i in range(3)]
    ef, em = max(ef, max(abs(got[i] - f[i]) for i in range(3))), max(em, max(abs(got[3 + i] - mo[i]) for i in range(3)))
    sf, sm = max(sf, max(abs(v) for v in got[:3])), max(sm, max(abs(v) for v in got[3:]))
print("support's force vs the nodes' inertia and the load: %.3g of %.3g; moment %.3g of %.3g" % (ef, sf, em, sm), file=sys.stderr)
why = []
if not (ef < 1e-8 * sf and em < 1e-8 * sm and sm > 10): why.append("force %.3g of %.3g, moment %.3g of %.3g" % (ef, sf, em, sm))
print("; ".join(why))
PY
)
    [ -z "$msg" ] || WHY+=("$msg")
fi
finish "a cantilever's support force and moment in time: equilibrium with the inertia and the loads"

printf 'material s E=1e9 nu=0.3\nsection b material=s A=1 Iy=1 Iz=1 J=1 mass=1\nnode 1 0 0 0 fix=xyzrxryrz\nnode 2 1 0 0\nbeam 1 1 2 section=b\nload 2 0 1 0\ndynamics dt=0.1 t_end=1 method=central\n' >"$T/bad.cable"
"$BIN" solve "$T/bad.cable" -q >/dev/null 2>"$T/err"; rc=$?
[ $rc -eq 2 ] || WHY+=("method=central with beams above the stable step: exit $rc, expected 2")
grep -q "bad.cable:7: dynamics: dt=0.1 is above the stable step of method=central, 1.054.*e-05 s" "$T/err" || WHY+=("message: $(cat "$T/err")")
finish "beams under method=central: a step above the stable one (the rotary inertia's) refused"

cli_summary
