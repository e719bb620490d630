#!/usr/bin/env bash
# tests/cli/dynamics.sh CATENA: the dynamics analysis end to end (issue 26).
#   - history.csv with -o DIR: the header "t,2.ux,2.uy,2.uz" of `record node=2`, one row
#     per time step from t = 0 (zeros: displacements from the start geometry), t in
#     steps of dt; the pendulum's period from the zero crossings of x against 4 sqrt(L/g)
#     K(sin(theta0/2)) (K by the arithmetic-geometric mean) to 1e-5;
#   - --json: the "dynamics" object (method, dt, steps, t, histories by column name,
#     energy: kinetic + strain - work + damping stays at 0 to 1e-4 of m g L);
#   - after a static step: the equilibrium (uy = -W/k) held with the loads, the spring's
#     force W (`record element=1 force`);
#   - Rayleigh damping: the SDOF against x0 e^(-zeta w t)(cos wd t + zeta/sqrt(1-zeta^2)
#     sin wd t) to 1e-4 of x0 with dt = 5 ms;
#   - a `function NAME table FILE` read beside the model; a table whose times do not
#     increase: exit 2 at the table's file:line;
#   - the summary's dynamics lines; no history.csv without a dynamics line.
# Prints "N passed, N failed"; exit 1 on any failure.
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init dynamics "${1:-}"
M=tests/models/dynamics

"$BIN" solve "$M/pendulum.cable" -q -o "$T/pend" 2>"$T/err"; rc=$?
[ $rc -eq 0 ] || WHY+=("exit $rc: $(cat "$T/err")")
[ -f "$T/pend/history.csv" ] || WHY+=("no history.csv")
[ "$(head -1 "$T/pend/history.csv" 2>/dev/null)" = "t,2.ux,2.uy,2.uz" ] || WHY+=("header: $(head -1 "$T/pend/history.csv" 2>/dev/null)")
[ "$(sed -n 2p "$T/pend/history.csv" 2>/dev/null)" = "0,0,0,0" ] || WHY+=("first row is not t = 0 at rest")
[ "$(wc -l <"$T/pend/history.csv" 2>/dev/null)" = 5602 ] || WHY+=("rows: $(wc -l <"$T/pend/history.csv") lines, expected 5602")
if [ $have_python = 1 ]; then
    msg=$(python3 - "$T/pend/history.csv" <<'PY'
import csv, math, sys
rows = [[float(v) for v in r] for r in list(csv.reader(open(sys.argv[1])))[1:]]
why = []
for k, r in enumerate(rows):
    if abs(r[0] - k * 5e-4) > 1e-12: why.append("t of row %d is %r" % (k, r[0])); break
th = math.pi / 3
x = [math.sin(th) + r[1] for r in rows]
z = [rows[i - 1][0] + (rows[i][0] - rows[i - 1][0]) * x[i - 1] / (x[i - 1] - x[i])
     for i in range(1, len(x)) if (x[i - 1] > 0) != (x[i] > 0)]
a, b = 1.0, math.cos(th / 2)
for _ in range(40): a, b = (a + b) / 2, math.sqrt(a * b)
T = 4 * math.sqrt(1 / 9.81) * math.pi / (2 * a)
if len(z) < 3 or abs(z[2] - z[0] - T) > 1e-5 * T: why.append("period %r, expected %r" % (z[2] - z[0] if len(z) > 2 else None, T))
print("; ".join(why))
PY
)
    [ -z "$msg" ] || WHY+=("$msg")
fi
finish "pendulum history.csv and period"

"$BIN" solve "$M/pendulum.cable" --json >"$T/pend.json" 2>"$T/err"; rc=$?
[ $rc -eq 0 ] || WHY+=("exit $rc: $(cat "$T/err")")
if [ $have_python = 1 ]; then
    msg=$(python3 - "$T/pend.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1])).get("dynamics")
why = []
if not d: print("no dynamics object"); sys.exit()
for k in ("method", "dt", "steps", "t", "histories", "energy", "converged", "rho_inf", "energy_error"):
    if k not in d: why.append("dynamics lacks " + k)
if d.get("method") != "genalpha" or d.get("dt") != 5e-4 or d.get("steps") != 5600 or d.get("converged") is not True:
    why.append("method, dt, steps or converged")
h = d.get("histories", {})
if sorted(h) != ["2.ux", "2.uy", "2.uz"] or any(len(v) != 5601 for v in h.values()): why.append("histories")
e = d.get("energy", {})
bal = [k + s - w + dd for k, s, w, dd in zip(e["kinetic"], e["strain"], e["work"], e["damping"])]
if len(bal) != 5601 or max(abs(b) for b in bal) > 1e-4 * 9.81: why.append("energy balance %g" % max(abs(b) for b in bal))
print("; ".join(why))
PY
)
    [ -z "$msg" ] || WHY+=("$msg")
fi
finish "JSON dynamics object"

"$BIN" solve "$M/hanging_step.cable" -q -o "$T/hang" 2>"$T/err"; rc=$?
[ $rc -eq 0 ] || WHY+=("exit $rc: $(cat "$T/err")")
if [ $have_python = 1 ]; then
    python3 - "$T/hang/history.csv" <<'PY' || WHY+=("the static equilibrium is not held: $(head -3 "$T/hang/history.csv")")
import csv, sys
r = list(csv.reader(open(sys.argv[1])))
ok = r[0] == ["t", "2.uy", "1.force"] and len(r) == 52
ok = ok and all(abs(float(x[1]) + 0.5) < 1e-9 and abs(float(x[2]) - 20) < 1e-7 for x in r[1:])
sys.exit(0 if ok else 1)
PY
fi
finish "dynamics after a static step"

"$BIN" solve "$M/sdof_damped.cable" -q -o "$T/damp" 2>"$T/err"; rc=$?
[ $rc -eq 0 ] || WHY+=("exit $rc: $(cat "$T/err")")
if [ $have_python = 1 ]; then
    msg=$(python3 - "$T/damp/history.csv" <<'PY'
import csv, math, sys
rows = [[float(v) for v in r] for r in list(csv.reader(open(sys.argv[1])))[1:]]
w, a, b, x0 = 3.0, 0.3, 0.02, 1e-3
z = a / (2 * w) + b * w / 2
wd = w * math.sqrt(1 - z * z)
err = max(abs(x0 + r[1] - x0 * math.exp(-z * w * r[0]) * (math.cos(wd * r[0]) + z / math.sqrt(1 - z * z) * math.sin(wd * r[0])))
          for r in rows)
print("" if err < 1e-4 * x0 else "error %g of x0" % (err / x0))
PY
)
    [ -z "$msg" ] || WHY+=("$msg")
fi
finish "Rayleigh damping decay"

printf 'node 1 0 0 0 fix=xyz\nnode 2 1 0 0 mass=1\nspring 1 1 2 k=4\nfunction r table steps.csv\n' >"$T/table.cable"
printf '# t, value\n0, 0\n1, 1\n0.5, 2\n' >"$T/steps.csv"
"$BIN" solve "$T/table.cable" -q >/dev/null 2>"$T/err"; rc=$?
[ $rc -eq 2 ] || WHY+=("a table not increasing: exit $rc, expected 2")
grep -q "^catena: $T/steps.csv:4: table times must increase: t=0.5 is not after t=1 (function r, line 4 of $T/table.cable)" "$T/err" ||
    WHY+=("message: $(cat "$T/err")")
printf '0 0\n1 1\n3 1\n' >"$T/steps.csv"
printf 'load 2 1 0 0 fn=r\ndynamics dt=0.01 t_end=0.1\nrecord node=2\n' >>"$T/table.cable"
"$BIN" solve "$T/table.cable" -q -o "$T/tab" 2>"$T/err" || WHY+=("a table beside the model: $(cat "$T/err")")
[ "$(wc -l <"$T/tab/history.csv" 2>/dev/null)" = 12 ] || WHY+=("a table's run: no 11 rows")
finish "table functions: beside the model, times not increasing (the table's file:line)"

"$BIN" solve "$M/sdof_damped.cable" >"$T/sum.txt" 2>"$T/err"
grep -q "^dynamics (genalpha, dt 0.005 s, consistent mass): 1257 steps to t = 6.28319 s" "$T/sum.txt" || WHY+=("no dynamics line: $(grep dynamics "$T/sum.txt")")
grep -q "Rayleigh damping: alpha 0.3 1/s, beta 0.02 s" "$T/sum.txt" || WHY+=("no damping line")
grep -q "balance error" "$T/sum.txt" || WHY+=("no energy line")
"$BIN" solve tests/models/buckling/bar_springs.cable -q -o "$T/static" 2>/dev/null
[ ! -e "$T/static/history.csv" ] || WHY+=("history.csv without a dynamics line")
finish "summary"

cli_summary
