#!/usr/bin/env bash
# tests/cli/memlimit.sh CATENA: catena under an address-space limit (issue 28, item 6).
# Debian's OpenBLAS reserves 128 MiB per thread in its constructor, before main, and
# retried forever when that failed: under `ulimit -v 300000` catena spun at 100 % CPU
# before reading its model. Now (app/blas_limit.c):
#   - ulimit -v 300000 (room for one buffer, not for two): the paper's cable solves,
#     exit 0, on one thread, within 20 s;
#   - the smallest limit under which the loader maps catena's libraries (found here: the
#     MPI build's 109 libraries need more than the plain build's 20), which leaves no
#     room for one buffer: exit 4 at once, the message names the limit, nothing on stdout;
#   - no limit: the default thread count (the summary's, as before).
# Skipped for a sanitizer build (AddressSanitizer reserves terabytes of shadow memory and
# cannot run under ulimit -v at all).
# Prints "N passed, N failed"; exit 1 on any failure.
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init memlimit "${1:-}"

if command -v readelf >/dev/null && readelf -s "$BIN" | grep -q __asan_init; then
    echo "memlimit: a sanitizer build: skipped"
    cli_summary
    exit $?
fi
M=examples/paper/s250.8777.cable

(ulimit -v 300000; exec timeout 20 "$BIN" solve "$M") >"$T/out" 2>"$T/err"
rc=$?
[ $rc -eq 0 ] || WHY+=("ulimit -v 300000: exit $rc (124: the BLAS start hung): $(head -c 300 "$T/err")")
grep -q "CPU [0-9.]* s, 1 thread)" "$T/out" || WHY+=("not one thread: $(grep -o 'factorization.*' "$T/out")")
grep -q "^converged" "$T/out" || WHY+=("did not converge")
finish solves_under_a_limit_on_one_thread

# the smallest limit (8 MiB steps) under which the dynamic loader maps catena's libraries
# at all (below it: exit 127 before any of catena's code runs; an MPI build maps 109)
lim=
for kib in $(seq 65536 8192 1048576); do
    (ulimit -v $kib; exec "$BIN" --version) >/dev/null 2>&1
    [ $? -ne 127 ] && { lim=$kib; break; }
done
[ -n "$lim" ] || WHY+=("catena does not load under 1 GiB")
lim=${lim:-100000}
(ulimit -v $lim; exec timeout 20 "$BIN" solve "$M") >"$T/out" 2>"$T/err"
rc=$?
[ $rc -eq 4 ] || WHY+=("ulimit -v $lim: exit $rc, want 4 (124: the BLAS start hung)")
grep -q "address-space limit (ulimit -v $lim)" "$T/err" || WHY+=("message: $(head -c 300 "$T/err")")
[ -s "$T/out" ] && WHY+=("stdout not empty: $(head -c 200 "$T/out")")
finish refuses_a_limit_too_small_with_exit_4

"$BIN" solve "$M" >"$T/out" 2>&1 || WHY+=("no limit: exit $?")
grep -q "CATENA_BLAS_ONE_THREAD" "$T/out" && WHY+=("the marker leaked")
grep -q "^converged" "$T/out" || WHY+=("no limit: did not converge")
finish no_limit_runs_as_before

cli_summary
