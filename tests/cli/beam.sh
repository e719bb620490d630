#!/usr/bin/env bash
# tests/cli/beam.sh CATENA: beams through `catena solve` (docs/format.md, "beam"):
# - examples/beam/rollup.cable (a cantilever under M = 2 pi EI / L): the tip back at the
#   root (ux = -L, uy = 0 to 1e-9 L), turned by rz = 2 pi, the clamp's moment -M;
# - examples/beam/cantilever.cable: the tip deflection P L^3 / (3 E I) (1e-4: the load is
#   not small), the root element's end_forces_local (shear P, moment P L) in result.json
#   and the same twelve end forces in elements.csv;
# - examples/beam/bend45.cable: the published tip displacement at P = 600 (0.25);
# - examples/beam/portal_design.cable: the girder's combined stress against the box's A
#   and Wy by hand at its elements' ends, utilisation = stress / fy in result.json, in
#   elements.csv and the summary's "beams:" line; the girder's q L^2 / 8; its hinge;
# - examples/structures/footbridge.cable: the reactions carry the weights (w l0 of every
#   member) and the crowd; four increasing frequencies; a buckling factor above 1;
# - examples/structures/transmission_towers.cable: each tower's base holds 2 H of its two
#   conductors (H = 25 by the targets) before the wind; the wind q times the conductors'
#   unstressed length, half at each tower; no moment at the strings' hinges;
# - a cantilever of 1000 beams (L = 10, 0.1 m square steel, elements of 0.01 m whose
#   transverse stiffness 12 E I / l^3 is 100 times E A / l) under P = 0.01 E I / L^2:
#   converged by the default method (its residual at the round-off floor of those
#   elements; it stopped with exit 3 when the floor took E A / l and N alone), the tip
#   at P L^3 / (3 E I) to 1e-4 (the geometric non-linearity is 1e-5).
# Prints "N passed, N failed"; exit 1 on any failure.
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init beam "${1:-}"
PY=/usr/bin/python3
[ -x "$PY" ] || PY=python3

"$BIN" solve examples/beam/rollup.cable --json >"$T/roll.json" 2>"$T/err" || WHY+=("rollup: exit $?: $(head -c 300 "$T/err")")
"$PY" - "$T/roll.json" >"$T/check" 2>&1 <<'PYEOF' || WHY+=("$(head -n 5 "$T/check")")
import json, math, sys
r = json.load(open(sys.argv[1]))
n = {p["id"]: p for p in r["nodes"]}
q = {p["node"]: p for p in r["reactions"]}
assert r["converged"]
assert abs(n[2]["ux"] + 10) < 1e-8 and abs(n[2]["uy"]) < 1e-8, n[2]
assert abs(n[2]["rz"] - 2 * math.pi) < 1e-10, n[2]
assert abs(q[1]["mz"] + 2 * math.pi * 1e4) < 1e-6, q[1]
PYEOF
finish "rollup: a full circle"

"$BIN" solve examples/beam/cantilever.cable -q -o "$T/cant" 2>"$T/err" || WHY+=("cantilever: exit $?: $(head -c 300 "$T/err")")
"$PY" - "$T/cant/result.json" "$T/cant/elements.csv" >"$T/check" 2>&1 <<'PYEOF' || WHY+=("$(head -n 5 "$T/check")")
import csv, json, sys
r = json.load(open(sys.argv[1]))
n = {p["id"]: p for p in r["nodes"]}
P, L, E, I = 100.0, 5.0, 2.1e11, 2e-6
assert abs(n[2]["uz"] + P * L**3 / (3 * E * I)) < 1e-4 * P * L**3 / (3 * E * I), n[2]
e = r["elements"][0]
assert e["type"] == "beam" and e["id"] == 1
f = e["end_forces_local"]
assert abs(f[0][2] - P) < 1e-3 and abs(f[0][4] + P * (L + n[2]["ux"])) < 1e-3, f
rows = list(csv.DictReader(open(sys.argv[2])))
assert float(rows[0]["fz1"]) == f[0][2] and float(rows[0]["my1"]) == f[0][4], rows[0]
assert [r["id"] for r in rows] == ["1", "1000001", "1000002", "1000003"], rows
PYEOF
finish "cantilever: deflection and end forces"

"$BIN" solve examples/beam/bend45.cable --json >"$T/bend.json" 2>"$T/err" || WHY+=("bend45: exit $?: $(head -c 300 "$T/err")")
"$PY" - "$T/bend.json" >"$T/check" 2>&1 <<'PYEOF' || WHY+=("$(head -n 5 "$T/check")")
import json, sys
r = json.load(open(sys.argv[1]))
n = {p["id"]: p for p in r["nodes"]}
for k, v in zip(("ux", "uy", "uz"), (-23.5, -13.4, 53.4)):
    assert abs(n[9][k] - v) < 0.25, (k, n[9][k], v)
PYEOF
finish "bend45: Bathe and Bolourchi at P = 600"

"$BIN" solve examples/beam/portal_design.cable -o "$T/portal" >"$T/portal.txt" 2>"$T/err" || WHY+=("portal: exit $?: $(head -c 300 "$T/err")")
"$PY" - "$T/portal/result.json" "$T/portal/elements.csv" "$T/portal.txt" >"$T/check" 2>&1 <<'PYEOF' || WHY+=("$(head -n 5 "$T/check")")
import csv, json, sys
r = json.load(open(sys.argv[1]))
rows = {int(x["id"]): x for x in csv.DictReader(open(sys.argv[2]))}
text = open(sys.argv[3]).read()
A = 0.15 * 0.4 - 0.13 * 0.38                       # the girder's box, by hand
Wy = (0.15 * 0.4**3 - 0.13 * 0.38**3) / 12 / 0.2
worst = max(r["elements"], key=lambda e: e["utilisation"])
for e in r["elements"]:
    f = e["end_forces_local"]
    if e.get("group") != "girder":
        continue
    ends = [abs(f[0][0]) / A + abs(f[0][4]) / Wy, abs(f[1][0]) / A + abs(f[1][4]) / Wy]
    assert e["stress_combined"] >= max(ends) * (1 - 1e-12), (e["id"], e["stress_combined"], ends)
    assert abs(e["utilisation"] - e["stress_combined"] / 355e3) < 1e-12, e
    assert float(rows[e["id"]]["utilisation"]) == e["utilisation"], rows[e["id"]]
assert f"beams: max utilisation {worst['utilisation']:.4f} at element {worst['id']}" in text, text
assert abs(max(abs(x) for x in [worst["moment_max"]]) - 20 * 8**2 / 8) < 1e-2 * 160, worst   # q L^2 / 8, P-delta 1e-3
assert r["elements"][8]["end_forces_local"][0][4] == 0, r["elements"][8]                         # the hinge
PYEOF
finish "portal_design: hinged girder, deck load, utilisation against fy"

"$BIN" solve examples/structures/footbridge.cable --json >"$T/foot.json" 2>"$T/err" || WHY+=("footbridge: exit $?: $(head -c 300 "$T/err")")
"$PY" - "$T/foot.json" >"$T/check" 2>&1 <<'PYEOF' || WHY+=("$(head -n 5 "$T/check")")
import json, sys
r = json.load(open(sys.argv[1]))
assert r["converged"] and r["stable"], r["reason"]
w = {"deck": 4.0, "pylon": 3.8, "stays": 0.12}
load = sum(w[e["group"]] * e["l0"] for e in r["elements"]) + 10 * 40     # weights and the crowd
fz = sum(q["fz"] for q in r["reactions"])
assert abs(fz - load) < 1e-8 * load, (fz, load)
f = [m["frequency"] for m in r["modes"]]
assert len(f) == 4 and all(0 < a < b for a, b in zip(f, f[1:])), f
assert len(r["buckling"]) == 1 and r["buckling"][0]["factor"] > 1, r["buckling"]
PYEOF
finish "footbridge: weights and crowd carried, modes, buckling"

sed '/^step wind/,$d' examples/structures/transmission_towers.cable >"$T/still.cable"
"$BIN" solve "$T/still.cable" --json >"$T/still.json" 2>"$T/err" || WHY+=("towers (still): exit $?: $(head -c 300 "$T/err")")
"$BIN" solve examples/structures/transmission_towers.cable --json >"$T/wind.json" 2>"$T/err" || WHY+=("towers: exit $?: $(head -c 300 "$T/err")")
"$PY" - "$T/still.json" "$T/wind.json" >"$T/check" 2>&1 <<'PYEOF' || WHY+=("$(head -n 5 "$T/check")")
import json, sys
s, w = (json.load(open(a)) for a in sys.argv[1:3])
q = {p["node"]: p for p in s["reactions"]}
assert abs(q[1]["fx"] + 2 * 25) < 1e-6 and abs(q[11]["fx"] - 2 * 25) < 1e-6, q    # each base: the two conductors' H
q = {p["node"]: p for p in w["reactions"]}
L0 = sum(e["l0"] for e in w["elements"] if e.get("group") == "conductors")
assert abs(q[1]["fy"] + q[11]["fy"] + 0.01686 * L0) < 1e-8, (q, L0)               # the wind per unstressed length
assert abs(q[1]["fy"] - q[11]["fy"]) < 1e-6, q                                      # shared by symmetry
ins = [e for e in w["elements"] if e.get("group") == "insulators"]
assert all(e["end_forces_local"][0][4] == 0 and e["end_forces_local"][0][5] == 0 for e in ins), ins   # the hinges
PYEOF
finish "transmission_towers: 2 H at each base, the wind shared, hinged strings"

"$PY" - >"$T/fine.cable" <<'PYEOF'
E, b, n, L = 2.1e8, 0.1, 1000, 10.0
I = b ** 4 / 12
print("units kN m\nmaterial steel E=%.17g nu=0.3" % E)
print("section sq material=steel A=%.17g Iy=%.17g Iz=%.17g J=%.17g" % (b * b, I, I, 0.1406 * b ** 4))
print("node 1 0 0 0 fix=xyzrxryrz\nnode 2 %.17g 0 0\nbeam 1 1 2 section=sq orient=0,0,1 n=%d" % (L, n))
print("load 2 0 0 %.17g" % (-0.01 * E * I / L ** 2))
PYEOF
"$BIN" solve "$T/fine.cable" --json >"$T/fine.json" 2>"$T/err" || WHY+=("fine cantilever: exit $?: $(head -c 300 "$T/err")")
"$PY" - "$T/fine.json" >"$T/check" 2>&1 <<'PYEOF' || WHY+=("$(head -n 5 "$T/check")")
import json, sys
r = json.load(open(sys.argv[1]))
n = {p["id"]: p for p in r["nodes"]}
E, I, L = 2.1e8, 0.1 ** 4 / 12, 10.0
P = 0.01 * E * I / L ** 2
assert r["converged"], r["reason"]
assert abs(n[2]["uz"] + P * L ** 3 / (3 * E * I)) < 1e-4 * P * L ** 3 / (3 * E * I), n[2]
PYEOF
finish "1000 short beams: converged at their round-off floor, P L^3 / (3 E I)"

cli_summary
