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
#     at dt = 2e-3 and 1e-3: the energy balance's error falls by 3.5 to 4.6 (the
#     gyroscopic term W x J W of Euler's equations is needed for it).
# Prints "N passed, N failed"; exit 1 on any failure.
# ctest-cost: 4
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

for dt in 2e-3 1e-3; do
    sed "s/^dynamics dt=2e-3/dynamics dt=$dt/" tests/models/dynamics/beam_top.cable >"$T/g$dt.cable"
    "$BIN" solve "$T/g$dt.cable" -q -o "$T/g$dt" 2>"$T/err"; rc=$?
    [ $rc -eq 0 ] || WHY+=("3D pendulum dt=$dt: exit $rc: $(cat "$T/err")")
done
if [ ${#WHY[@]} -eq 0 ] && [ $have_python = 1 ]; then
    msg=$(python3 - "$T" <<'PY'
import csv, json, sys
d = sys.argv[1]
err = [json.load(open("%s/g%s/result.json" % (d, dt)))["dynamics"]["energy_error"] for dt in ("2e-3", "1e-3")]
rows = [[float(v) for v in r] for r in list(csv.reader(open("%s/g1e-3/history.csv" % d)))[1:]]
uz = max(abs(r[3]) for r in rows)
print("3D: energy errors %r (ratio %.3g), largest |uz| %.3g" % (err, err[0] / err[1], uz), file=sys.stderr)
why = []
if not uz > 0.05: why.append("the motion stays in its plane: |uz| <= %.3g" % uz)
if not (3.5 < err[0] / err[1] < 4.6 and err[0] < 5e-5): why.append("energy errors %r: not O(dt^2)" % err)
print("; ".join(why))
PY
)
    [ -z "$msg" ] || WHY+=("$msg")
fi
finish "a beam pendulum off its principal axes leaves its plane: energy to O(dt^2)"

printf 'material s E=1e9 nu=0.3\nsection b material=s A=1 Iy=1 Iz=1 J=1 mass=1\nnode 1 0 0 0 fix=xyzrxryrz\nnode 2 1 0 0\nbeam 1 1 2 section=b\nload 2 0 1 0\ndynamics dt=0.1 t_end=1 method=central\n' >"$T/bad.cable"
"$BIN" solve "$T/bad.cable" -q >/dev/null 2>"$T/err"; rc=$?
[ $rc -eq 2 ] || WHY+=("method=central with beams: exit $rc, expected 2")
grep -q "bad.cable:7: dynamics: method=central does not take rotations" "$T/err" || WHY+=("message: $(cat "$T/err")")
sed -i 's/method=central/method=genalpha\ndamping alpha=0.1 beta=0/' "$T/bad.cable"
"$BIN" solve "$T/bad.cable" -q >/dev/null 2>"$T/err"; rc=$?
[ $rc -eq 2 ] || WHY+=("damping with beams: exit $rc, expected 2")
grep -q "dynamics: damping of a model with rotations (beam, rspring) is not supported yet" "$T/err" || WHY+=("message: $(cat "$T/err")")
finish "beams refused by method=central and with damping"

cli_summary
