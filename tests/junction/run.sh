#!/usr/bin/env bash
# tests/junction/run.sh CATENA DIR: solve every DIR/*.cable with the default method and
# print "name exit-code iterations" per model, then the count of each exit code.
# The corpus: python3 tests/junction/corpus.py DIR (meshed cables meeting at a free
# loaded node, 768 models), or python3 tests/junction/corpus.py DIR catenary (the same
# junctions with one catenary element per cable).
set -u
C=$1; D=$2
for f in "$D"/*.cable; do
    out=$(timeout 120 "$C" solve "$f" 2>&1); rc=$?
    it=$(printf '%s\n' "$out" | sed -n 's/.* after \([0-9]*\) iterations.*/\1/p' | head -1)
    echo "$(basename "$f" .cable) $rc ${it:-?}"
done | tee /dev/stderr | awk '{n[$2]++; if ($2 == 0) { s += $3; c++ } } END { for (k in n) printf "exit %s: %d models\n", k, n[k]; if (c) printf "mean iterations of the converged: %.1f\n", s / c }'
