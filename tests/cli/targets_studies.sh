#!/usr/bin/env bash
# tests/cli/targets_studies.sh CATENA: `study` and `convergence` use the length a target
# (sag=, H=, tension=) sets, as `solve` and `compare` do (issue 28, item 13): the paper's
# span with sag=5 instead of a length.
#   - solve finds L0; study marks that L0 and its FEA sag is 5; convergence's span has
#     that L0 (its table's header), and its FEA sags approach 5.
# Prints "N passed, N failed"; exit 1 on any failure.
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init targets_studies "${1:-}"

sed 's/length=250.8777/sag=5/' examples/paper/s250.8777.cable >"$T/sag.cable"
L0=$("$BIN" solve "$T/sag.cable" 2>/dev/null | sed -n 's/.*sag=5 reached.*length found \([0-9.]*\) m.*/\1/p')
[ -n "$L0" ] || WHY+=("solve does not report the length found")
finish solve_finds_the_length

"$BIN" study "$T/sag.cable" --sweep 0 --json >"$T/study.json" 2>"$T/err" || WHY+=("study: exit $?: $(cat "$T/err")")
if [ "$have_python" = 1 ] && [ -n "$L0" ]; then
    msg=$(python3 - "$T/study.json" "$L0" <<'PY'
import json, sys
d, L0 = json.load(open(sys.argv[1])), float(sys.argv[2])
rows = [r for r in d["rows"] if r["marked"]]
if len(rows) != 1: print("%d marked rows" % len(rows)); sys.exit()
r = rows[0]
if abs(r["length"] - L0) > 1e-8 * L0: print("marked length %.10g, solve found %.10g" % (r["length"], L0))
if abs(r["fea"]["sag"] - 5) > 1e-8: print("FEA sag %.12g at the marked length, not 5" % r["fea"]["sag"])
PY
)
    [ -z "$msg" ] || WHY+=("study: $msg")
fi
finish study_marks_the_found_length

"$BIN" convergence "$T/sag.cable" --n 10,20 >"$T/conv" 2>"$T/err" || WHY+=("convergence: exit $?: $(cat "$T/err")")
want=$(printf '%.7f' "${L0:-0}")
grep -q "unstressed length ${want%?}" "$T/conv" || WHY+=("convergence's span is not L0 = $L0: $(grep -m1 'unstressed' "$T/conv")")
finish convergence_uses_the_found_length

cli_summary
