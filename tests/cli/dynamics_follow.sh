#!/usr/bin/env bash
# tests/cli/dynamics_follow.sh CATENA: follower loads in a dynamics analysis (issue 26):
# an `hload` on the deformed projection, its non-symmetric tangent solved by GMRES on
# the factorization of the effective tangent (src/analysis/static/follow.c).
#   - tests/models/dynamics/follow_pendulum.cable at dt = 2e-3 and 1e-3 against the rigid
#     rod's equation of motion integrated by RK4 (h = 2e-4, its error ~1e-13) at every
#     row: the node's path within 1e-4 (of L = 1) at 2e-3, the error falling by 3.5 to 4.5
#     when dt halves (O(dt^2)); leaving the load out (or taking it on the reference
#     projection, a dead load) moves the path by 0.1;
#   - the energy balance closes with the follower load's work in W (below 1e-4).
# Prints "N passed, N failed"; exit 1 on any failure.
# ctest-cost: 1
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init dynamics_follow "${1:-}"

for dt in 2e-3 1e-3; do
    sed "s/^dynamics dt=2e-3/dynamics dt=$dt/" tests/models/dynamics/follow_pendulum.cable >"$T/f$dt.cable"
    "$BIN" solve "$T/f$dt.cable" -q -o "$T/f$dt" 2>"$T/err"; rc=$?
    [ $rc -eq 0 ] || WHY+=("dt=$dt: exit $rc: $(cat "$T/err")")
done
if [ ${#WHY[@]} -eq 0 ] && [ $have_python = 1 ]; then
    msg=$(python3 - "$T" <<'PY'
import csv, json, math, sys
d = sys.argv[1]
g, q, m, L, th0 = 9.81, 10.0, 1.0, 1.0, math.pi / 3

def f(s):
    return (s[1], -math.sin(s[0]) / L * (g + q * L / (2 * m) * abs(math.sin(s[0]))))

def path(times):
    s, t, h, out = (th0, 0.0), 0.0, 2e-4, []
    for tr in times:
        while t < tr - 1e-12:
            hh = min(h, tr - t)
            k1 = f(s)
            k2 = f((s[0] + hh / 2 * k1[0], s[1] + hh / 2 * k1[1]))
            k3 = f((s[0] + hh / 2 * k2[0], s[1] + hh / 2 * k2[1]))
            k4 = f((s[0] + hh * k3[0], s[1] + hh * k3[1]))
            s = tuple(s[i] + hh / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]) for i in range(2))
            t += hh
        out.append((L * math.sin(s[0]) - L * math.sin(th0), -L * math.cos(s[0]) + L * math.cos(th0)))
    return out

why, err = [], []
for dt in ("2e-3", "1e-3"):
    rows = [[float(v) for v in r] for r in list(csv.reader(open("%s/f%s/history.csv" % (d, dt))))[1:]]
    ref = path([r[0] for r in rows])
    err.append(max(math.hypot(r[1] - u[0], r[2] - u[1]) for r, u in zip(rows, ref)))
    e = json.load(open("%s/f%s/result.json" % (d, dt)))["dynamics"]["energy_error"]
    if not e < 1e-4: why.append("dt=%s: energy balance error %.3g" % (dt, e))
print("path errors %r (ratio %.3g)" % (err, err[0] / err[1]), file=sys.stderr)
if not (err[0] < 1e-4 and 3.5 < err[0] / err[1] < 4.5): why.append("path errors %r: not O(dt^2) below 1e-4" % err)
print("; ".join(why))
PY
)
    [ -z "$msg" ] || WHY+=("$msg")
fi
finish "a pendulum under an hload that follows the geometry vs its equation of motion"

cli_summary
