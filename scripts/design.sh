#!/usr/bin/env bash
# The design examples of docs/validation.md ("Designing cable systems"): each is solved
# by catena, its per-step results are read from the JSON and drawn with gnuplot.
#   examples/design/transmission_line.cable  conductor profiles at 15 C (sag set), -20 C
#                                             with ice, +60 C
#   examples/design/guyed_mast.cable          the guys' tensions before and under wind
#   examples/design/hypar_snow.cable          the force-density hypar net under snow and cold
# Figures (data, gnuplot scripts, SVG) go to out/design/; with DOCS=1 the SVGs are also
# copied to docs/figures/.
#     bash scripts/design.sh [build/catena]
set -eu
cli=${1:-build/catena}
case $cli in /*) ;; *) cli=$PWD/$cli ;; esac
cd "$(dirname "$0")/.."
out=out/design
mkdir -p "$out"

# per-step node positions (x z) and element forces of a result.json, one block per step
extract() {
    python3 - "$1" "$2" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
steps = r.get("steps") or [dict(name="", nodes=r["nodes"], elements=r["elements"])]
with open(sys.argv[2] + ".nodes.dat", "w") as f:
    for s in steps:
        f.write("# %s\n" % s["name"])
        for n in s["nodes"]:
            f.write("%.10g %.10g %.10g\n" % (n["x"] + n["ux"], n["y"] + n["uy"], n["z"] + n["uz"]))
        f.write("\n\n")
with open(sys.argv[2] + ".forces.dat", "w") as f:
    for s in steps:
        f.write("# %s\n" % s["name"])
        for i, e in enumerate(s["elements"]):
            f.write("%d %.10g %s\n" % (e["id"], e["force"], e.get("utilisation", 0)))
        f.write("\n\n")
for c in r["cables"]:
    t = c.get("target")
    if t:
        print("cable %d-%d: %s=%g reached %.12g with length %.12g" % (c["node1"], c["node2"], t["kind"], t["value"], t["achieved"], c["length"]))
for g in r.get("groups", []):
    print("group %s: max force %.6g, max utilisation %.4f" % (g["name"], g["max_force"], g.get("max_utilisation", 0)))
PY
}

echo "== Transmission line: sag set at 15 C, checked at -20 C with ice and at +60 C =="
"$cli" solve examples/design/transmission_line.cable --json > "$out/line.json"
extract "$out/line.json" "$out/line"
cat > "$out/line.gp" <<GP
set terminal svg size 800,420 font "sans,12"
set output "$out/design_line.svg"
set title "350 m conductor span set by sag = 10.5 m at 15 °C"
set xlabel "x [m]"; set ylabel "z [m]"; set key bottom right; set grid
plot "$out/line.nodes.dat" index 0 using 1:3 with lines lw 2 title "15 °C (sag set)", \
     "" index 1 using 1:3 with lines lw 2 title "-20 °C with 12.5 mm ice", \
     "" index 2 using 1:3 with lines lw 2 title "+60 °C", \
     "" index 0 using 1:(\$1 * 12 / 350) with lines dt 2 lc rgb "gray" title "chord"
GP
gnuplot "$out/line.gp"

echo
echo "== Guyed mast: three guys pretensioned to 25 kN, then 8 kN of wind at the top =="
"$cli" solve examples/design/guyed_mast.cable --json > "$out/mast.json"
extract "$out/mast.json" "$out/mast"
cat > "$out/mast.gp" <<GP
set terminal svg size 800,420 font "sans,12"
set output "$out/design_mast.svg"
set title "Guy tensions (element order: windward guy, then the two leeward guys)"
set xlabel "element id"; set ylabel "tension [kN]"; set key top left; set grid
set xrange [1.5:49.5]
plot "$out/mast.forces.dat" index 0 using 1:2 with linespoints pt 7 ps 0.5 title "pretension (targets 25 kN)", \
     "" index 1 using 1:2 with linespoints pt 7 ps 0.5 title "with wind"
GP
gnuplot "$out/mast.gp"

echo
echo "== Hypar net found by force density: prestress, snow 0.8 kN/m2, snow at -30 K =="
"$cli" solve examples/design/hypar_snow.cable --json > "$out/hypar.json"
extract "$out/hypar.json" "$out/hypar"
python3 - "$out/hypar.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
for s in r["steps"]:
    print("%-11s" % s["name"], "  ".join("%s: max force %.2f kN, utilisation %.3f, %d slack" % (g["name"], g["max_force"], g.get("max_utilisation", 0), g["slack"]) for g in s["groups"]))
PY
cat > "$out/hypar.gp" <<GP
set terminal svg size 800,420 font "sans,12"
set output "$out/design_hypar.svg"
set title "Hypar net: member utilisation (strands 1-576, edge cables 577-624)"
set xlabel "element id"; set ylabel "utilisation N / (mbl / safety)"; set key top left; set grid
plot "$out/hypar.forces.dat" index 0 using 1:3 with points pt 7 ps 0.3 title "prestress", \
     "" index 1 using 1:3 with points pt 7 ps 0.3 title "snow 0.8 kN/m²", \
     "" index 2 using 1:3 with points pt 7 ps 0.3 title "snow, -30 K"
GP
gnuplot "$out/hypar.gp"

echo
echo "figures: $out/design_line.svg $out/design_mast.svg $out/design_hypar.svg"
if [ "${DOCS:-0}" = 1 ]; then
    cp "$out"/design_*.svg docs/figures/
fi
