#!/usr/bin/env bash
# tests/cli/dynamics_output.sh CATENA: a dynamics analysis's output in time and its
# support reactions (issue 26), one run of tests/models/dynamics/driven_bar.cable -o DIR:
#   - output_every=30 over 2000 steps: rows at t = 0, every 30th step and the last
#     (t = 10), 68 in history.csv and in result.json's "t" (the same numbers);
#   - the VTU series: dynamics.pvd (read by python3's XML parser) lists one
#     dynamics/frame_K.vtu per row with the row's time; each frame parses, holds
#     TimeValue = its time, displacement, velocity, reaction (points) and force (cells),
#     and its node 2 ux, node 1 reaction fx and element force are the history's numbers
#     exactly (%.17g both);
#   - against the closed form of the driven bar (z = x2 - u_g: (M + m'l/3) z'' + beta k z'
#     + k z = (M + m'l/2) A W^2 sin W t, z(0) = 0, z'(0) = -A W; the reaction at node 1
#     R = (m'l/3 + m1) u_g'' + (m'l/6) x2'' - beta k z' - k z): x2 and R to 2e-4 of their
#     scale (genalpha rho_inf = 1 at W dt = 0.0065: O(dt^2) ~ 1e-5); leaving out the
#     support's inertia (m1 u_g'' is 8e-3) or the damping (beta k z' about 3e-3) fails.
# Prints "N passed, N failed"; exit 1 on any failure.
# ctest-cost: 2
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init dynamics_output "${1:-}"

"$BIN" solve tests/models/dynamics/driven_bar.cable -q -o "$T/out" 2>"$T/err"; rc=$?
[ $rc -eq 0 ] || WHY+=("exit $rc: $(cat "$T/err")")
[ "$(head -1 "$T/out/history.csv" 2>/dev/null)" = "t,2.ux,1.fx,1.fy,1.fz,1.force" ] ||
    WHY+=("header: $(head -1 "$T/out/history.csv" 2>/dev/null)")
[ "$(wc -l <"$T/out/history.csv" 2>/dev/null)" = 69 ] || WHY+=("history.csv: $(wc -l <"$T/out/history.csv") lines, expected 69")
if [ $have_python = 1 ]; then
    msg=$(python3 - "$T/out" <<'PY'
import csv, json, os, sys
import xml.etree.ElementTree as ET
d = sys.argv[1]
rows = [[float(v) for v in r] for r in list(csv.reader(open(d + "/history.csv")))[1:]]
why = []
steps = list(range(0, 2000, 30)) + [2000]
if [r[0] for r in rows] != [0.0] + [k * 0.005 for k in steps[1:-1]] + [10.0]:
    why.append("row times %r ..." % [r[0] for r in rows][:4])
js = json.load(open(d + "/result.json"))["dynamics"]
if js["t"] != [r[0] for r in rows] or js["histories"]["1.fx"] != [r[2] for r in rows]:
    why.append("result.json's t or 1.fx differ from history.csv")
root = ET.parse(d + "/dynamics.pvd").getroot()
sets = root.find("Collection").findall("DataSet")
if root.get("type") != "Collection" or len(sets) != len(rows):
    why.append("dynamics.pvd: %d data sets for %d rows" % (len(sets), len(rows)))
for ds, r in zip(sets, rows):
    if float(ds.get("timestep")) != r[0]:
        why.append("pvd timestep %s for t %r" % (ds.get("timestep"), r[0])); break
    g = ET.parse(os.path.join(d, ds.get("file"))).getroot().find("UnstructuredGrid")
    arrays = {a.get("Name"): [float(x) for x in a.text.split()] for a in g.iter("DataArray")}
    piece = g.find("Piece")
    if (piece.get("NumberOfPoints"), piece.get("NumberOfCells")) != ("2", "1"):
        why.append("%s: points, cells" % ds.get("file")); break
    if sorted(arrays) != ["TimeValue", "connectivity", "coordinates", "displacement", "force", "offsets", "reaction",
                          "types", "velocity"]:
        why.append("%s: arrays %s" % (ds.get("file"), sorted(arrays))); break
    if (arrays["TimeValue"] != [r[0]] or arrays["displacement"][3] != r[1] or arrays["reaction"][0] != r[2]
            or arrays["force"] != [r[5]]):
        why.append("%s: not the history's row at t = %r" % (ds.get("file"), r[0])); break
# the closed form
import math
A, W, k, M, ml, m1, beta = 0.01, 2 * math.pi * 0.20690142964317865, 4.0, 1.0, 0.6, 0.5, 0.05
Me, c = M + ml / 3, beta * k
F0 = (Me + ml / 6) * A * W * W
wn = math.sqrt(k / Me); zeta = c / (2 * Me * wn); wd = wn * math.sqrt(1 - zeta * zeta)
D = (k - Me * W * W) ** 2 + (c * W) ** 2
P, Q = F0 * (k - Me * W * W) / D, -F0 * c * W / D
c1 = -Q
c2 = (-A * W - P * W + zeta * wn * c1) / wd
ex, er = 0.0, 0.0
for r in rows:
    t = r[0]
    e = math.exp(-zeta * wn * t); C, S = math.cos(wd * t), math.sin(wd * t)
    z = e * (c1 * C + c2 * S) + P * math.sin(W * t) + Q * math.cos(W * t)
    zd = e * ((-zeta * wn * c1 + wd * c2) * C + (-zeta * wn * c2 - wd * c1) * S) + W * (P * math.cos(W * t) - Q * math.sin(W * t))
    zdd = (F0 * math.sin(W * t) - c * zd - k * z) / Me
    ug, ugdd = A * math.sin(W * t), -A * W * W * math.sin(W * t)
    R = (ml / 3 + m1) * ugdd + ml / 6 * (zdd + ugdd) - c * zd - k * z
    ex, er = max(ex, abs(r[1] - (z + ug))), max(er, abs(r[2] - R))
print("x2 %.3g R %.3g" % (ex / A, er / (k * A + F0)), file=sys.stderr)
if ex > 2e-4 * A or er > 2e-4 * (k * A + F0):
    why.append("closed form: x2 off by %.3g (of A), R by %.3g (of k A + F0)" % (ex / A, er / (k * A + F0)))
print("; ".join(why))
PY
)
    [ -z "$msg" ] || WHY+=("$msg")
fi
finish "output_every, the VTU series and the reactions of a driven bar"

printf 'node 1 0 0 0 fix=yz\nnode 2 1 0 0 fix=xyz\nnode 3 2 0 0 mass=1 fix=yz\nspring 1 1 3 k=1\nspring 2 2 3 k=1\nload 3 1 0 0\ndynamics dt=0.1 t_end=1\nrecord node=1 dof=ux reaction\n' >"$T/bad.cable"
"$BIN" solve "$T/bad.cable" -q >/dev/null 2>"$T/err"; rc=$?
[ $rc -eq 2 ] || WHY+=("a reaction of a free direction: exit $rc, expected 2")
grep -q "bad.cable:8: record: node 1 is not fixed in ux: it has no reaction there" "$T/err" || WHY+=("message: $(cat "$T/err")")
finish "a reaction recorded where the node is free"

cli_summary
