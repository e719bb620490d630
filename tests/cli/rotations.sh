#!/usr/bin/env bash
# tests/cli/rotations.sh CATENA: a model with rotations (examples/springs/rotational.cable:
# an rspring clamped at node 1, a moment about z at node 2, a guy cable at node 2) through
# `catena solve --json` and `-o DIR`: the rotation and moment fields of result.json,
# nodes.csv and result.vtu (docs/format.md), their values (rz = M / k = 0.25 at node 2,
# mz = -50 at node 1), and none of those fields for a model without rotations.
# Prints "N passed, N failed"; exit 1 on any failure.
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init rotations "${1:-}"
PY=/usr/bin/python3
[ -x "$PY" ] || PY=python3

f=examples/springs/rotational.cable
"$BIN" solve "$f" -q -o "$T/rot" 2>"$T/err" || WHY+=("exit $?: $(head -c 300 "$T/err")")
"$BIN" solve "$f" --json >"$T/rot.json" 2>"$T/err" || WHY+=("--json: exit $?")
printf '\n' >>"$T/rot/result.json.nl"; cat "$T/rot/result.json" "$T/rot/result.json.nl" >"$T/rot.file.json"
cmp -s "$T/rot.json" "$T/rot.file.json" || WHY+=("--json and result.json differ")
finish "solve with -o and --json"

"$PY" - "$T/rot/result.json" >"$T/check" 2>&1 <<'PYEOF' || WHY+=("$(head -n 5 "$T/check")")
import json, sys
r = json.load(open(sys.argv[1]))
n = {p["id"]: p for p in r["nodes"]}
q = {p["node"]: p for p in r["reactions"]}
assert n[2]["rz"] == 0.25 and n[2]["rx"] == 0 and n[3]["rz"] == 0, n
assert q[1]["mz"] == -50 and q[1]["mx"] == 0 and q[3]["mz"] == 0, q
assert r["elements"][1]["type"] == "rspring"
PYEOF
finish "result.json: rotations and reaction moments"

head -n 1 "$T/rot/nodes.csv" | grep -qx 'id,x,y,z,ux,uy,uz,fix,rx,ry,rz,thx,thy,thz,mx,my,mz' || WHY+=("nodes.csv header: $(head -n 1 "$T/rot/nodes.csv")")
grep -q '^1,0,0,0,0,0,0,xyzrxryrz,.*,0,0,-50$' "$T/rot/nodes.csv" || WHY+=("node 1 row: $(sed -n 2p "$T/rot/nodes.csv")")
grep -q '^2,1,0,0,.*,0,0,0.25,0,0,0$' "$T/rot/nodes.csv" || WHY+=("node 2 row: $(sed -n 3p "$T/rot/nodes.csv")")
finish "nodes.csv: rotations and reaction moments"

grep -q 'Name="rotation"' "$T/rot/result.vtu" || WHY+=("no rotation array in result.vtu")
grep -q 'Name="moment"' "$T/rot/result.vtu" || WHY+=("no moment array in result.vtu")
finish "result.vtu: rotation and moment arrays"

"$BIN" solve examples/springs/elastic_support.cable -q -o "$T/plain" 2>"$T/err" || WHY+=("exit $?")
grep -q '"rz"\|"mz"' "$T/plain/result.json" && WHY+=("rotation keys in a model without rotations")
head -n 1 "$T/plain/nodes.csv" | grep -qx 'id,x,y,z,ux,uy,uz,fix,rx,ry,rz' || WHY+=("nodes.csv header changed")
grep -q 'Name="rotation"\|Name="moment"' "$T/plain/result.vtu" && WHY+=("rotation arrays in a model without rotations")
finish "no rotation fields without rotations"

cli_summary
