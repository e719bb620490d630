#!/usr/bin/env bash
# tests/cli/cases2.sh CATENA: loads and cases, the rest of issue 27 (docs/format.md):
#   - a case that does not converge: exit 3, top-level JSON "converged" false with
#     "failed_case" naming it, the case's own "converged" false, the summary's
#     "not converged: case 'push'" line; the other case converged;
#   - reference states: a case's ux_from, uy_from, uz_from are its displacements less its
#     installed state's; the summary's largest displacement per step and case agrees
#     with the JSON (value and node);
#   - -o DIR writes cases/NAME/nodes.csv, elements.csv, result.vtu for each case, equal
#     to the JSON's case entry;
#   - set, load set=, load cable= at=, include: the same state as the loads by ids;
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

# Reference states: each case node's ux_from = ux - the installed state's ux; the
# summary's largest displacement per step and case is the JSON's largest |u| (steps) and
# |u_from| (cases), at the same node.
"$BIN" solve $M/states.cable >"$T/out" 2>"$T/err"; rc=$?
[ $rc -eq 0 ] || WHY+=("states: exit $rc")
"$BIN" solve $M/states.cable --json >"$T/json" 2>/dev/null
"$PY" - "$T/json" "$T/out" <<'PY' || WHY+=("ux_from or the summary's largest displacement wrong")
import json, math, sys
d = json.load(open(sys.argv[1]))
steps = {s["name"]: s for s in d["steps"]}
ok = True
rows = {}
for line in open(sys.argv[2]):
    w = line.split()
    if len(w) >= 5 and w[0] in ("step", "case", "combination") and w[4] == "the":
        rows[w[1]] = (float(w[2]), int(w[3]))
def big(nodes, keys):
    u = max(nodes, key=lambda n: math.sqrt(sum(n[k] ** 2 for k in keys)))
    return math.sqrt(sum(u[k] ** 2 for k in keys)), u["id"]
for name, s in steps.items():
    u, node = big(s["nodes"], ("ux", "uy", "uz"))
    ok = ok and name in rows and abs(rows[name][0] - u) <= 1e-9 * u and rows[name][1] == node
for c in d["cases"]:
    base = {n["id"]: n for n in steps[c["from"]]["nodes"]}
    for n in c["nodes"]:
        for a in "xyz":
            ok = ok and abs(n["u" + a + "_from"] - (n["u" + a] - base[n["id"]]["u" + a])) <= 1e-15 * (1 + abs(n["u" + a]))
    u, node = big(c["nodes"], ("ux_from", "uy_from", "uz_from"))
    ok = ok and c["name"] in rows and abs(rows[c["name"]][0] - u) <= 1e-9 * u and rows[c["name"]][1] == node
sys.exit(0 if ok and len(rows) == 3 else 1)
PY
finish "reference states: ux_from and the largest displacements"

# -o DIR: cases/NAME/nodes.csv, elements.csv, result.vtu per case, each the case's state
# (the JSON's case entry); the run's files as before.
"$BIN" solve $M/states.cable -q -o "$T/o" >/dev/null 2>&1; rc=$?
[ $rc -eq 0 ] || WHY+=("-o: exit $rc")
for f in result.json nodes.csv elements.csv result.vtu result.pvd cases/cold/nodes.csv cases/cold/elements.csv \
    cases/cold/result.vtu; do
    [ -s "$T/o/$f" ] || WHY+=("no $f")
done
"$PY" - "$T/o" <<'PY' || WHY+=("cases/cold/*.csv disagree with the JSON's case")
import csv, json, sys
d = json.load(open(sys.argv[1] + "/result.json"))
c = d["cases"][0]
nodes = {int(r["id"]): r for r in csv.DictReader(open(sys.argv[1] + "/cases/cold/nodes.csv"))}
els = {int(r["id"]): r for r in csv.DictReader(open(sys.argv[1] + "/cases/cold/elements.csv"))}
ok = len(nodes) == len(c["nodes"]) and len(els) == len(c["elements"])
ok = ok and all(float(nodes[n["id"]][k]) == n[k] for n in c["nodes"] for k in ("ux", "uy", "uz"))
ok = ok and all(float(els[e["id"]]["force"]) == e["force"] for e in c["elements"])
sys.exit(0 if ok else 1)
PY
grep -q 'DataArray' "$T/o/cases/cold/result.vtu" || WHY+=("cases/cold/result.vtu has no data")
finish "-o: the files of each case"

# Selection: sets.cable (include, node and element sets by box and cable, load set=,
# load cable= at=, lineload and temperature on sets) gives, bit for bit, the state of
# sets_explicit.cable, which names the same nodes and elements by id.
"$BIN" solve $M/sets.cable --json >"$T/sa.json" 2>"$T/err"; rc=$?
[ $rc -eq 0 ] || WHY+=("sets: exit $rc: $(head -c 200 "$T/err")")
"$BIN" solve $M/sets_explicit.cable --json >"$T/sb.json" 2>/dev/null
"$PY" - "$T/sa.json" "$T/sb.json" <<'PY' || WHY+=("sets.cable and sets_explicit.cable differ")
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
ok = a["nodes"] == b["nodes"] and a["reactions"] == b["reactions"]
ok = ok and [e["force"] for e in a["elements"]] == [e["force"] for e in b["elements"]]
sys.exit(0 if ok else 1)
PY
finish "sets, load at= and include against explicit ids"

cli_summary
