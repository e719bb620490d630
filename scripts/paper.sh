#!/usr/bin/env bash
# The founding paper's study: the four cables of a 200 m span, solved by catena.
set -eu
cli=${1:-build/catena}
cd "$(dirname "$0")/.."
if "$cli" help | grep -q "^  study"; then
  exec "$cli" study examples/paper/study.cable -o out/paper
fi
printf "%-10s %6s %12s %14s %14s\n" "length[m]" "iters" "sag[m]" "max[MPa]" "min[MPa]"
for L in 200.3340 201.3545 250.8777 279.6157; do
  out=$("$cli" solve "examples/paper/s$L.cable")
  it=$(echo "$out" | sed -n 's/^converged after \([0-9]*\) iterations.*/\1/p')
  sag=$(echo "$out" | sed -n 's/.*mid-span sag \([0-9.eE+-]*\).*/\1/p')
  smax=$(echo "$out" | sed -n 's/^max tension.*stress *\([0-9.eE+-]*\) MPa.*/\1/p')
  smin=$(echo "$out" | sed -n 's/^min tension.*stress *\([0-9.eE+-]*\) MPa.*/\1/p')
  printf "%-10s %6s %12.4f %14.3f %14.3f\n" "$L" "$it" "$sag" "$smax" "$smin"
done
