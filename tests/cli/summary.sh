#!/usr/bin/env bash
# tests/cli/summary.sh CATENA: the summary of a big model (issue 10, item 6), on the
# 10 x 10 hypar net of bench/hypar_net.py (40 supported nodes):
#   - by default 20 reaction rows, then "(20 of 40 supported nodes listed; ...)", the sum
#     over all 40 and the largest by |r|, the node that result.json says is largest;
#   - --reactions all: 40 rows and no "largest"; --reactions 5: 5 rows;
#   - --reactions with a bad count is a usage error (exit 1);
#   - stderr stays empty (no progress line when stderr is not a terminal).
# Prints "N passed, N failed"; exit 1 on any failure.
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init summary "${1:-}"
PY=/usr/bin/python3
[ -x "$PY" ] || PY=python3
"$PY" bench/hypar_net.py 10 >"$T/net.cable" || { echo "summary.sh: cannot generate the net" >&2; exit 1; }

rows() { awk '/^reactions/ { on = 1; next } on && $1 ~ /^[0-9]+$/ { n++ } END { print n + 0 }' "$1"; }

"$BIN" solve "$T/net.cable" >"$T/out" 2>"$T/err"; rc=$?
[ $rc -eq 0 ] || WHY+=("exit $rc")
[ -s "$T/err" ] && WHY+=("stderr not empty: $(head -c 200 "$T/err")")
[ "$(rows "$T/out")" = 20 ] || WHY+=("$(rows "$T/out") reaction rows, expected 20")
grep -q "(20 of 40 supported nodes listed; --reactions all lists every one)" "$T/out" || WHY+=("no count line")
"$BIN" solve "$T/net.cable" --json >"$T/json" 2>/dev/null
largest=$(awk '$1 == "largest" { print $2 }' "$T/out")
"$PY" - "$T/json" "$largest" "$T/out" <<'PY' || WHY+=("sum or largest disagree with result.json")
import json, math, sys
d = json.load(open(sys.argv[1]))
r = d["reactions"]
big = max(r, key=lambda x: math.hypot(x["fx"], x["fy"], x["fz"]))
ok = str(big["node"]) == sys.argv[2]
line = [l.split() for l in open(sys.argv[3]) if l.split()[:1] == ["sum"]][0]
sums = [sum(x[k] for x in r) for k in ("fx", "fy", "fz")]
scale = max(abs(x[k]) for x in r for k in ("fx", "fy", "fz"))
ok = ok and all(abs(float(a) - b) <= 1e-5 * scale for a, b in zip(line[1:], sums))
sys.exit(0 if ok else 1)
PY
finish "default: 20 rows, the count, the sum and the largest"

"$BIN" solve "$T/net.cable" --reactions all >"$T/out" 2>&1
[ "$(rows "$T/out")" = 40 ] || WHY+=("$(rows "$T/out") rows, expected 40")
grep -q "^ *largest" "$T/out" && WHY+=("a largest row although every reaction is listed")
"$BIN" solve --reactions 5 "$T/net.cable" >"$T/out" 2>&1
[ "$(rows "$T/out")" = 5 ] || WHY+=("--reactions 5: $(rows "$T/out") rows")
finish "--reactions all and N"

for bad in x -1 "" 1e3; do
    "$BIN" solve "$T/net.cable" --reactions "$bad" >/dev/null 2>"$T/err"; rc=$?
    [ $rc -eq 1 ] || WHY+=("--reactions '$bad': exit $rc, expected 1")
    grep -q "reactions" "$T/err" || WHY+=("--reactions '$bad': no message")
done
finish "--reactions with a bad count"

cli_summary
