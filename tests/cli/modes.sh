#!/usr/bin/env bash
# tests/cli/modes.sh CATENA: the modal analysis end to end (issue 12).
#   - JSON: "modal" and "modes" with the keys of docs/format.md, frequencies sorted and
#     f = omega / (2 pi), T = 1 / f, a shape entry for every node, 0 on fixed DOFs; with
#     every mode asked for (a 4 x 4 net, lumped), the effective masses sum to the moving
#     mass along x, y and z (completeness of the M-orthonormal modes);
#   - the summary's table; modes.csv in -o DIR (one row per mode, the JSON's numbers),
#     and no modes.csv without modes;
#   - a node held only by slack members: zero modes naming it, in the JSON and the summary.
# Prints "N passed, N failed"; exit 1 on any failure.
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init modes "${1:-}"
M=tests/models/modes

"$BIN" solve "$M/net4.cable" --json >"$T/net.json" 2>"$T/err"; rc=$?
[ $rc -eq 0 ] || WHY+=("exit $rc: $(cat "$T/err")")
if [ $have_python = 1 ]; then
    msg=$(python3 - "$T/net.json" <<'PY'
import json, math, sys
d = json.load(open(sys.argv[1]))
why = []
ms, modes = d.get("modal"), d.get("modes")
if not ms or not modes: print("no modal or modes"); sys.exit()
for k in ("count", "mass", "shift", "sigma", "total_mass", "zero_modes", "unstable_modes",
          "lanczos_restarts", "factorizations", "solves", "max_residual"):
    if k not in ms: why.append("modal lacks " + k)
if ms["count"] != 27 or len(modes) != 27 or ms["mass"] != "lumped": why.append("count or mass")
if not ms["max_residual"] <= 1e-10: why.append("residual %g" % ms["max_residual"])
f = [m["frequency"] for m in modes]
if f != sorted(f): why.append("not sorted")
nn = len(d["nodes"])
for m in modes:
    if abs(m["angular_frequency"] - 2 * math.pi * m["frequency"]) > 1e-12 * m["angular_frequency"]: why.append("omega")
    if abs(m["period"] * m["frequency"] - 1) > 1e-12: why.append("period")
    if abs(m["eigenvalue"] - m["angular_frequency"] ** 2) > 1e-10 * m["eigenvalue"]: why.append("eigenvalue")
    if len(m["shape"]) != nn or m["kind"] != "vibration": why.append("shape or kind")
    for s in m["shape"]:
        if s["node"] in (1, 5, 21, 25) and (s["ux"], s["uy"], s["uz"]) != (0, 0, 0): why.append("moving support")
for ax in "xyz":
    tot = sum(m["effective_mass"][ax] for m in modes)
    if abs(tot - ms["total_mass"][ax]) > 1e-9 * ms["total_mass"][ax]:
        why.append("effective masses %s sum to %r, total %r" % (ax, tot, ms["total_mass"][ax]))
print("; ".join(sorted(set(why))))
PY
)
    [ -z "$msg" ] || WHY+=("$msg")
fi
finish "JSON modes of a net, all of them"

"$BIN" solve "$M/net4.cable" >"$T/sum.txt" 2>"$T/err"
grep -q "^modes (lumped mass, 27 lowest): 0 factorization(s)" "$T/sum.txt" || WHY+=("no modal header in the summary")
grep -q "^shift-invert: sigma = 0 on the stability check's factor of K_T" "$T/sum.txt" || WHY+=("the static factor not reused")
grep -q "^eigen-solver: arpack" "$T/sum.txt" || WHY+=("no eigen-solver line (auto: ARPACK on a small net)")
grep -q "frequency \[Hz\]" "$T/sum.txt" || WHY+=("no table header")
[ "$(grep -c "^ *[0-9][0-9]* *[0-9.e+-]* *[0-9.e+-]* *[0-9.e+-]* " "$T/sum.txt")" -ge 27 ] || WHY+=("fewer than 27 rows")
finish "summary table"

rm -rf "$T/out"
"$BIN" solve "$M/net4.cable" -q -o "$T/out" 2>"$T/err" || WHY+=("-o failed: $(cat "$T/err")")
[ -f "$T/out/modes.csv" ] || WHY+=("no modes.csv")
[ "$(wc -l <"$T/out/modes.csv")" -eq 28 ] || WHY+=("modes.csv has $(wc -l <"$T/out/modes.csv") lines, expected 28")
head -1 "$T/out/modes.csv" | grep -q "^mode,kind,frequency,period,angular_frequency,eigenvalue," || WHY+=("modes.csv header")
if [ $have_python = 1 ]; then
    python3 - "$T/out/modes.csv" "$T/net.json" <<'PY' || WHY+=("modes.csv differs from the JSON")
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1])))
modes = json.load(open(sys.argv[2]))["modes"]
# The JSON prints numbers as cJSON does (15 digits when they read back within one ulp),
# the CSV with %.17g: equal within 2 ulps.
same = lambda a, b: abs(a - b) <= 4.5e-16 * max(abs(a), abs(b))
ok = len(rows) == len(modes) and all(same(float(r["frequency"]), m["frequency"]) and int(r["node"]) == m["node"]
                                     and same(float(r["effective_mass_z"]), m["effective_mass"]["z"])
                                     for r, m in zip(rows, modes))
sys.exit(0 if ok else 1)
PY
fi
rm -rf "$T/plain"
"$BIN" solve examples/paper/s250.8777.cable -q -o "$T/plain" 2>/dev/null
[ -e "$T/plain/modes.csv" ] && WHY+=("modes.csv written without modes")
finish "modes.csv"

"$BIN" solve "$M/slack_node.cable" --json >"$T/slack.json" 2>/dev/null; rc=$?
[ $rc -eq 0 ] || WHY+=("exit $rc")
if [ $have_python = 1 ]; then
    msg=$(python3 - "$T/slack.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
m = d["modes"]
ok = d["modal"]["zero_modes"] == 3 and all(x["kind"] == "zero" and x["nodes"] == [10] and x["moving_nodes"] == 1
                                           and x["frequency"] == 0 for x in m[:3]) and m[3]["kind"] == "vibration"
print("" if ok else "zero modes: %r" % [(x["kind"], x.get("nodes")) for x in m[:4]])
PY
)
    [ -z "$msg" ] || WHY+=("$msg")
fi
"$BIN" solve "$M/slack_node.cable" 2>/dev/null | grep -q "a mechanism or rigid-body motion: 1 node(s) move: 10" ||
    WHY+=("the summary does not name node 10")
finish "zero modes of a slack-held node"

cli_summary
