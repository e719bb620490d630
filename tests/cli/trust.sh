#!/usr/bin/env bash
# tests/cli/trust.sh CATENA: answers that can be trusted (issue 7), end to end.
#   - an unstable equilibrium (a mast held by two guys in one plane) exits 0 with a
#     warning on stderr containing "unstable", the node and the direction, and JSON
#     "stable": false when the JSON has the key; a stable one warns nothing;
#   - a semi-definite one (a node held only by slack members) is "not stable" with its
#     own wording and the node;
#   - near-rigid members (E = 2e22) never exit 0: exit 3 with the round-off reason.
# Prints "N passed, N failed"; exit 1 on any failure.
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init trust "${1:-}"
M=tests/models/trust

"$BIN" solve "$M/mast_two_guys.cable" -q 2>"$T/err"; rc=$?
[ $rc -eq 0 ] || WHY+=("exit $rc, expected 0")
grep -q "unstable" "$T/err" || WHY+=("no 'unstable' warning: $(cat "$T/err")")
grep -q "node 2, direction y" "$T/err" || WHY+=("the warning does not name node 2, direction y")
finish "unstable mast warns"

"$BIN" solve "$M/mast_two_guys.cable" --json >"$T/out.json" 2>/dev/null
if grep -q '"stable"' "$T/out.json"; then
    grep -q '"stable":[[:space:]]*false' "$T/out.json" || WHY+=("JSON stable is not false")
fi
finish "unstable mast JSON"

"$BIN" solve "$M/mast_four_guys.cable" -q 2>"$T/err"; rc=$?
[ $rc -eq 0 ] || WHY+=("exit $rc")
[ -s "$T/err" ] && WHY+=("a stable mast warned: $(cat "$T/err")")
finish "stable mast is quiet"

"$BIN" solve "$M/slack_held_node.cable" -q 2>"$T/err"; rc=$?
[ $rc -eq 0 ] || WHY+=("exit $rc, expected 0")
grep -q "not stable" "$T/err" || WHY+=("no 'not stable' warning: $(cat "$T/err")")
grep -q "semi-definite" "$T/err" || WHY+=("the warning does not say semi-definite")
grep -q "node 4" "$T/err" || WHY+=("the warning does not name node 4")
finish "slack-held node"

for f in paper_E2e22 mast_rigid_strut; do
    "$BIN" solve "$M/$f.cable" -q 2>"$T/err"; rc=$?
    [ $rc -eq 3 ] || WHY+=("exit $rc, expected 3")
    grep -q "not converged" "$T/err" || WHY+=("no 'not converged': $(cat "$T/err")")
    finish "near-rigid $f"
done
"$BIN" solve "$M/paper_E2e22.cable" 2>/dev/null | grep -q "round-off floor" || WHY+=("the summary does not explain the round-off floor")
finish "near-rigid summary"

"$BIN" solve "$M/strain_absurd.cable" -q 2>"$T/err"; rc=$?
[ $rc -eq 0 ] || WHY+=("exit $rc")
grep -q "warning: element 1 has a strain of 0.37" "$T/err" || WHY+=("no strain warning: $(cat "$T/err")")
finish "absurd strain warns"

"$BIN" solve "$M/span_2e36.cable" -q 2>"$T/err"
grep -q "over 10,000 km" "$T/err" || WHY+=("no size warning: $(cat "$T/err")")
finish "absurd size warns"

"$BIN" solve "$M/determinate.cable" -q 2>"$T/err"; rc=$?
[ $rc -eq 0 ] || WHY+=("exit $rc: $(cat "$T/err")")
[ -s "$T/err" ] && WHY+=("stderr not empty: $(cat "$T/err")")
finish "determinate model solved"

"$BIN" solve "$M/paper_E2e14.cable" 2>/dev/null | grep -q "rejected (shift" || WHY+=("rejected steps not marked in the log")
finish "rejected steps marked"

"$BIN" solve "$M/arclength_singular_start.cable" -q 2>"$T/err"; rc=$?
[ $rc -eq 3 ] || WHY+=("exit $rc, expected 3 (a solver condition, not a bad model): $(cat "$T/err")")
finish "arc-length singular start exits 3"

cli_summary
