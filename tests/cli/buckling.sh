#!/usr/bin/env bash
# tests/cli/buckling.sh CATENA: the linear buckling analysis end to end (issue 23 item 4).
#   - JSON: "buckling_analysis" and "buckling" (factor, node, residual, shape) of a stiff
#     pinned bar held by lateral springs: kx L / P and ky L / P to 1e-6, lowest first,
#     each shape along its spring, 0 at the supports;
#   - the factor is on the last step's total load (two steps of P each: kx L / 2P);
#   - the summary's table; buckling.csv in -o DIR (the JSON's numbers) and buckling_1,
#     buckling_2 in result.vtu; neither without a `buckling` line.
# Prints "N passed, N failed"; exit 1 on any failure.
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init buckling "${1:-}"
M=tests/models/buckling

"$BIN" solve "$M/bar_springs.cable" --json >"$T/bar.json" 2>"$T/err"; rc=$?
[ $rc -eq 0 ] || WHY+=("exit $rc: $(cat "$T/err")")
if [ $have_python = 1 ]; then
    msg=$(python3 - "$T/bar.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
why = []
ba, b = d.get("buckling_analysis"), d.get("buckling")
if not ba or not b: print("no buckling_analysis or buckling"); sys.exit()
for k in ("count", "asked", "ndof", "h", "load_norm"):
    if k not in ba: why.append("buckling_analysis lacks " + k)
if ba["count"] != 2 or len(b) != 2 or ba["ndof"] != 3: why.append("count or ndof")
L, kx, ky, P = 10.0, 2.0, 3.0, 1.0
for m, want, axis in ((b[0], kx * L / P, "ux"), (b[1], ky * L / P, "uy")):
    if abs(m["factor"] - want) > 1e-6 * want: why.append("factor %r, expected %r" % (m["factor"], want))
    if m["node"] != 2 or not m["residual"] < 1e-12: why.append("node or residual")
    sh = {s["node"]: s for s in m["shape"]}
    if len(sh) != 4 or abs(sh[2][axis] - 1) > 1e-12: why.append("shape at node 2")
    for n in (1, 3, 4):
        if (sh[n]["ux"], sh[n]["uy"], sh[n]["uz"]) != (0, 0, 0): why.append("a support moves")
print("; ".join(sorted(set(why))))
PY
)
    [ -z "$msg" ] || WHY+=("$msg")
fi
finish "JSON buckling of a bar on springs"

"$BIN" solve "$M/bar_steps.cable" --json >"$T/steps.json" 2>"$T/err"; rc=$?
[ $rc -eq 0 ] || WHY+=("exit $rc: $(cat "$T/err")")
if [ $have_python = 1 ]; then
    python3 - "$T/steps.json" <<'PY' || WHY+=("the factor is not on the last step's total load")
import json, sys
b = json.load(open(sys.argv[1]))["buckling"]
sys.exit(0 if len(b) == 1 and abs(b[0]["factor"] - 2.0 * 10 / 2) < 1e-6 * 10 else 1)
PY
fi
finish "the last step's loads"

"$BIN" solve "$M/bar_springs.cable" >"$T/sum.txt" 2>"$T/err"
grep -q "^buckling (linear, about the last step's state, 3 free DOFs): 2 of 2 factor(s) asked" "$T/sum.txt" ||
    WHY+=("no buckling header in the summary")
grep -q "load factor" "$T/sum.txt" || WHY+=("no table header")
grep -Eq "^ +1 +19\.99999[0-9]* +2 " "$T/sum.txt" || WHY+=("no first row (20 at node 2)")
grep -Eq "^ +2 +29\.99999[0-9]* +2 " "$T/sum.txt" || WHY+=("no second row (30 at node 2)")
finish "summary table"

rm -rf "$T/out"
"$BIN" solve "$M/bar_springs.cable" -o "$T/out" -q 2>"$T/err" || WHY+=("-o: $(cat "$T/err")")
[ -f "$T/out/buckling.csv" ] || WHY+=("no buckling.csv")
head -1 "$T/out/buckling.csv" 2>/dev/null | grep -q "^mode,factor,node,residual$" || WHY+=("buckling.csv header")
[ "$(grep -c 'Name="buckling_[12]"' "$T/out/result.vtu" 2>/dev/null)" = 2 ] || WHY+=("result.vtu lacks buckling_1, buckling_2")
if [ $have_python = 1 ] && [ -f "$T/out/buckling.csv" ]; then
    python3 - "$T/out/buckling.csv" "$T/bar.json" <<'PY' || WHY+=("buckling.csv differs from the JSON")
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1])))
b = json.load(open(sys.argv[2]))["buckling"]
ok = len(rows) == len(b) and all(float(r["factor"]) == m["factor"] and int(r["node"]) == m["node"]
                                 for r, m in zip(rows, b))
sys.exit(0 if ok else 1)
PY
fi
grep -v '^buckling' "$M/bar_springs.cable" >"$T/plain.cable"
"$BIN" solve "$T/plain.cable" -o "$T/plain" -q 2>"$T/err" || WHY+=("plain: $(cat "$T/err")")
[ -e "$T/plain/buckling.csv" ] && WHY+=("buckling.csv written without buckling")
grep -q 'Name="buckling_' "$T/plain/result.vtu" && WHY+=("buckling arrays written without buckling")
"$BIN" solve "$T/plain.cable" --json 2>/dev/null | grep -q '"buckling' && WHY+=("JSON buckling without buckling")
finish "buckling.csv and VTU"

cli_summary
