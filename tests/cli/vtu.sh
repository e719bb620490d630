#!/usr/bin/env bash
# tests/cli/vtu.sh CATENA: the ParaView output of `catena solve -o DIR` (docs/format.md,
# "result.vtu"), read back by tests/cli/lib/vtu_check.py (a plain XML reader, and VTK's
# reader when python3-vtk9 is installed) and compared with result.json (every step) and
# with nodes.csv and elements.csv (exactly):
#   - one step (the paper's cable), springs (stress 0), slack members (slack 1), and
#     three steps (result_1..3.vtu and result.pvd);
#   - the checker itself fails on a file with one value changed;
#   - a later one-step run into the same directory removes the earlier result.pvd.
# Prints "N passed, N failed"; exit 1 on any failure.
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init vtu "${1:-}"
PY=/usr/bin/python3
[ -x "$PY" ] || PY=python3
CHECK=tests/cli/lib/vtu_check.py

for f in examples/paper/s250.8777.cable examples/springs/elastic_support.cable \
         examples/robust/net_slack.cable tests/errors/ok_steps_displace.cable; do
    dir=$T/$(basename "$f" .cable)
    "$BIN" solve "$f" -q -o "$dir" 2>"$T/err"; rc=$?
    [ $rc -eq 0 ] || WHY+=("exit $rc: $(head -c 300 "$T/err")")
    [ -s "$dir/result.vtu" ] || WHY+=("no result.vtu")
    "$PY" "$CHECK" "$dir" >"$T/check" 2>&1 || WHY+=("$(head -n 5 "$T/check")")
    finish "$f"
done

dir=$T/ok_steps_displace
n=$(ls "$dir"/result_*.vtu 2>/dev/null | wc -l)
[ "$n" = 3 ] || WHY+=("$n step files, expected 3")
[ -s "$dir/result.pvd" ] || WHY+=("no result.pvd")
finish "three steps: three files and result.pvd"

grep -q '"slack":.true' "$T/net_slack/result.json" || WHY+=("net_slack has no slack member: the slack array is not exercised")
grep -A 200 'Name="slack"' "$T/net_slack/result.vtu" | grep -qx '1' || WHY+=("no slack 1 in result.vtu")
finish "slack members are marked"

cp -r "$T/s250.8777" "$T/bad"
awk '/Name="force"/ { print; getline; $1 = $1 * 1.5 } { print }' "$T/s250.8777/result.vtu" >"$T/bad/result.vtu"
"$PY" "$CHECK" "$T/bad" >"$T/check" 2>&1 && WHY+=("the checker passed a changed force")
grep -q "force" "$T/check" || WHY+=("the checker did not name the force: $(head -n 3 "$T/check")")
finish "the checker sees a changed value"

"$BIN" solve examples/paper/s250.8777.cable -q -o "$dir" 2>"$T/err" || WHY+=("second run failed")
[ -e "$dir/result.pvd" ] && WHY+=("result.pvd of the earlier three-step run left in place")
"$PY" "$CHECK" "$dir" >"$T/check" 2>&1 || WHY+=("$(head -n 3 "$T/check")")
finish "a one-step run over a three-step directory"

cli_summary
