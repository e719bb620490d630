#!/usr/bin/env bash
# tests/cli/case_vtu.sh CATENA: a load case's ParaView file is drawn from its installed
# state (docs/format.md "CSV files"; tests/models/cases2/states.cable: a cable and a
# catenary element installed under their weight, a case `cold` from step `install` while
# the run goes on to step `hot`): cases/cold/result.vtu has
#   - its points at the installed state: the reference coordinates plus the displacements
#     of step `install` (the JSON's steps[0] ux, uy, uz), to the last bit;
#   - `displacement` = the JSON case's ux_from, uy_from, uz_from, bit for bit, and
#     `displacement_total` = its ux, uy, uz; points + displacement = reference +
#     displacement_total (1e-12, the sum's rounding);
#   - the run's own result.vtu unchanged: reference points, total displacements, no
#     displacement_total.
# ctest-cost: 2
# Prints "N passed, N failed"; exit 1 on any failure.
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init case_vtu "${1:-}"
PY=/usr/bin/python3
[ -x "$PY" ] || PY=python3

"$BIN" solve tests/models/cases2/states.cable --json -o "$T/o" >"$T/r.json" 2>"$T/err"; rc=$?
[ $rc -eq 0 ] || WHY+=("exit $rc: $(head -c 200 "$T/err")")
"$PY" - "$T/r.json" "$T/o" <<'PY' || WHY+=("cases/cold/result.vtu is not drawn from the installed state")
import json, sys
import xml.etree.ElementTree as ET
d = json.load(open(sys.argv[1]))

def arrays(path):
    root = ET.parse(path).getroot()
    out = {}
    for a in root.iter("DataArray"):
        vals = [float(x) for x in a.text.split()]
        out[a.get("Name")] = [vals[i:i + 3] for i in range(0, len(vals), 3)] if a.get("NumberOfComponents") == "3" else vals
    return out

case = next(c for c in d["cases"] if c["name"] == "cold")
installed = next(s for s in d["steps"] if s["name"] == case["from"])
v = arrays(sys.argv[2] + "/cases/cold/result.vtu")
assert len(v["coordinates"]) == len(case["nodes"]) == 403
worst = 0.0
for k, (n, ni) in enumerate(zip(case["nodes"], installed["nodes"])):
    X = [n["x"], n["y"], n["z"]]
    assert v["coordinates"][k] == [X[c] + ni[u] for c, u in enumerate(("ux", "uy", "uz"))], k
    assert v["displacement"][k] == [n["ux_from"], n["uy_from"], n["uz_from"]], k
    assert v["displacement_total"][k] == [n["ux"], n["uy"], n["uz"]], k
    for c, u in enumerate(("ux", "uy", "uz")):
        worst = max(worst, abs(v["coordinates"][k][c] + v["displacement"][k][c] - X[c] - n[u]))
assert worst <= 1e-12, worst
assert max(abs(x) for p in v["displacement"] for x in p) > 0.1     # the case moved from it
run = arrays(sys.argv[2] + "/result.vtu")
last = d["steps"][-1]["nodes"]
assert "displacement_total" not in run
assert run["coordinates"] == [[n["x"], n["y"], n["z"]] for n in last]
assert run["displacement"] == [[n["ux"], n["uy"], n["uz"]] for n in last]
print("case vtu: installed points, displacement from them; worst sum rounding %.2g" % worst)
PY
finish case_vtu

cli_summary
