#!/usr/bin/env bash
# The founding paper's study (its Section 5), reproduced by catena:
#   - the 200 m level span (E = 200 GPa, A = 3.14 cm^2, w = 0.1 kN/m, 20 elements,
#     Green-Lagrange strain, pure Newton from the arc) at the paper's four lengths and a
#     sweep of 64 lengths between the taut and the slack extremes, FEA against the
#     inextensible catenary, with the error-vs-stress table checked against the paper's
#     conclusions (< 1 % below ~50 MPa, ~6 % near 150 MPa, ~30 % near 300 MPa);
#   - the same study on one exact catenary element per length (--element catenary), the
#     20-element mesh beside it;
#   - the comparison of each of the four cables with every closed form;
#   - the mesh convergence of the FEA (engineering strain) to the elastic catenary.
# Figures (gnuplot scripts, data, SVG) go to out/paper/. With DOCS=1 the SVGs are also
# copied to docs/figures/ (the figures of docs/validation.md).
#     bash scripts/paper.sh [build/catena]
set -eu
cli=${1:-build/catena}
case $cli in /*) ;; *) cli=$PWD/$cli ;; esac
cd "$(dirname "$0")/.."
out=out/paper
mkdir -p "$out"
paper=(examples/paper/s200.3340.cable examples/paper/s201.3545.cable examples/paper/s250.8777.cable
       examples/paper/s279.6157.cable)

echo "== The paper's study: FEA against the inextensible catenary =="
"$cli" study "${paper[@]}" --sweep 64 --claims 50:1,150:6,300:30 \
    --claims-title "the paper's conclusions" -o "$out/study"

echo
echo "== The same study on one exact catenary element per length (the 20-element mesh beside it) =="
"$cli" study "${paper[@]}" --sweep 64 --element catenary --claims 50:1,150:6,300:30 \
    --claims-title "the paper's conclusions" -o "$out/study-catenary"

echo
echo "== Every closed form against the FEA, the paper's four cables =="
for f in "${paper[@]}"; do
    name=$(basename "$f" .cable)
    echo
    "$cli" compare "$f" -o "$out/compare-$name" | grep -v "^figure:"
done

echo
echo "== Mesh convergence: FEA with engineering strain against the elastic catenary =="
"$cli" convergence examples/paper/s250.8777.cable -o "$out/convergence" | grep -v "^figure:"

echo
echo "figures (gnuplot scripts, data and SVG): $out/"
if [ "${DOCS:-0}" = 1 ]; then
    mkdir -p docs/figures
    cp "$out"/study/study_{stress_max,stress_min,sag,error}.svg docs/figures/
    for k in error element; do cp "$out/study-catenary/study_$k.svg" "docs/figures/study_catenary_$k.svg"; done
    cp "$out"/convergence/convergence.svg docs/figures/
    for L in 200.3340 201.3545 250.8777 279.6157; do
        for k in shape stress; do cp "$out/compare-s$L/compare_$k.svg" "docs/figures/compare_${k}_s$L.svg"; done
    done
    echo "copied the SVGs to docs/figures/"
fi
