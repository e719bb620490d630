#!/usr/bin/env bash
# The modal analysis's validation study (docs/validation.md, "Modal analysis"):
#   (a) the taut string against f_n = n/(2L) sqrt(T/m'), both mass matrices, O(h^2);
#   (b) Irvine's suspended cable across the crossover lambda^2 = 4 pi^2, and where the
#       shallow theory departs (sag/span up to 1/4);
#   (c) the founding paper's four cables against Irvine's predictions;
#   (d) a prestressed hypar net: mesh convergence of its lowest frequencies.
# Tables (markdown) on stdout; figures (gnuplot scripts, data, SVG) in out/modal/. With
# DOCS=1 the SVGs are also copied to docs/figures/.
#     bash scripts/modal.sh [build]
set -eu
build=${1:-build}
case $build in /*) ;; *) build=$PWD/$build ;; esac
cd "$(dirname "$0")/.."
if [ ! -x "$build/modal_study" ]; then
    echo "modal.sh: $build/modal_study not found; build first (make)" >&2
    exit 1
fi
out=out/modal
mkdir -p "$out"
"$build/modal_study" . "$out"
if [ "${DOCS:-0}" = 1 ]; then
    cp "$out"/modal_*.svg docs/figures/
    echo "copied the SVGs to docs/figures/"
fi
