#!/usr/bin/env bash
# tests/cli/cases2.sh CATENA: loads and cases, the rest of issue 27 (docs/format.md):
#   - a case that does not converge: exit 3, top-level JSON "converged" false with
#     "failed_case" naming it, the case's own "converged" false, the summary's
#     "not converged: case 'push'" line; the other case converged;
# Prints "N passed, N failed"; exit 1 on any failure.
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init cases2 "${1:-}"
PY=/usr/bin/python3
[ -x "$PY" ] || PY=python3
M=tests/models/cases2

"$BIN" solve $M/case_fails.cable >"$T/out" 2>"$T/err"; rc=$?
[ $rc -eq 3 ] || WHY+=("exit $rc, expected 3")
grep -q "^not converged: case 'push': maximum iterations reached" "$T/out" || WHY+=("no summary line naming the case")
grep -q "load case 'push' not converged" "$T/err" || WHY+=("stderr does not name the case")
"$BIN" solve $M/case_fails.cable --json >"$T/json" 2>/dev/null; rc=$?
[ $rc -eq 3 ] || WHY+=("--json: exit $rc, expected 3")
"$PY" - "$T/json" <<'PY' || WHY+=("JSON: converged/failed_case wrong")
import json, sys
d = json.load(open(sys.argv[1]))
c = {x["name"]: x["converged"] for x in d["cases"]}
ok = d["converged"] is False and d["failed_case"] == "push" and d["reason"] == "converged"
sys.exit(0 if ok and c == {"push": False, "pull": True} else 1)
PY
finish "a failed case: exit 3, converged false, failed_case"

cli_summary
