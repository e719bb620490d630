#!/usr/bin/env bash
# tests/cli/scale.sh CATENA: linear algebra at scale (issue 10), end to end.
#   - a model whose factor cannot fit in memory (a hub tied to 60000 free nodes, in the
#     natural ordering: eliminating the hub first fills the whole factor, ~1.6e10
#     non-zeros, 130 GB) stops with exit 4 and says how much it needed, before trying;
#   - the same model with the default ordering solves (AMD or METIS put the hub last:
#     no fill), and the summary names the ordering, the BLAS and the threads;
#   - the JSON carries ordering, blas, threads, factorizations and reused_factorizations.
# Prints "N passed, N failed"; exit 1 on any failure.
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init scale "${1:-}"

# hub (free) - leaf i (free) - anchor i (fixed), straight and prestressed, leaves spread
# over a sphere (golden spiral); the hub carries a small load.
star() {   # star N SOLVE_LINE
    awk -v n="$1" -v solve="$2" 'BEGIN {
        print "units kN m\nmaterial steel E=2e8\nsection s material=steel A=1e-4"
        print "node 1 0 0 0"
        for (i = 0; i < n; i++) {
            z = 1 - (2 * i + 1) / n; r = sqrt(1 - z * z); a = 2.399963229728653 * i
            x = r * cos(a); y = r * sin(a)
            printf "node %d %.12g %.12g %.12g\n", 2 + i, 10 * x, 10 * y, 10 * z
            printf "node %d %.12g %.12g %.12g fix=xyz\n", 2 + n + i, 20 * x, 20 * y, 20 * z
        }
        for (i = 0; i < n; i++) {
            printf "element %d 1 %d section=s eps0=1e-3\n", 1 + 2 * i, 2 + i
            printf "element %d %d %d section=s eps0=1e-3\n", 2 + 2 * i, 2 + i, 2 + n + i
        }
        print "load 1 0 0 -1"
        print solve
    }'
}

star 60000 "solve ordering=natural" >"$T/star.cable"
"$BIN" solve "$T/star.cable" -q -o "$T/out" 2>"$T/err"; rc=$?
[ $rc -eq 4 ] || WHY+=("exit $rc, expected 4")
grep -q "needs [0-9.]* GB" "$T/err" || WHY+=("the message does not say how much it needs: $(cat "$T/err")")
[ -e "$T/out" ] && WHY+=("an output directory was written")
finish "too big for memory: exit 4 and what it needs"

star 2000 "solve" >"$T/star2.cable"
"$BIN" solve "$T/star2.cable" >"$T/sum" 2>"$T/err"; rc=$?
[ $rc -eq 0 ] || WHY+=("exit $rc: $(cat "$T/err")")
grep -q "ordering \(amd\|metis\)" "$T/sum" || WHY+=("not ordered by AMD or METIS: $(grep ordering "$T/sum")")
grep -q "thread" "$T/sum" || WHY+=("no thread count in the timing line")
grep -q "BLAS " "$T/sum" || WHY+=("no BLAS named")
finish "the star by the default ordering"

"$BIN" solve "$T/star2.cable" --json >"$T/out.json" 2>/dev/null
for key in ordering blas threads factorizations reused_factorizations factor_nonzeros factor_flops; do
    grep -q "\"$key\"" "$T/out.json" || WHY+=("no \"$key\" in the JSON")
done
finish "JSON keys of the linear algebra"

cli_summary
