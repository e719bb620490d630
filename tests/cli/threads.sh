#!/usr/bin/env bash
# tests/cli/threads.sh CATENA: the threads the catena command starts (core/threads.h),
# counted by strace (clone and clone3 calls of the whole process), on the K = 85 hypar
# net of bench/hypar_net.py (21 168 DOFs: its ordering crosses CTN_THR_ORDER's
# threshold, its factorization is supernodal, with CHOLMOD's OpenMP loops):
#   - threads=1: no thread at all (OpenMP's included);
#   - threads=2: at most 8 (the context's helpers and the OpenMP team of the
#     factorization; on the K = 100 net, 1 224 before the pool and the per-thread
#     OpenMP limit, 2 after);
#   - threads=0 (the default): the results of threads=1 (the factorization's OpenMP
#     threads, threads=2, change its rounding).
# Skipped (passed) without strace or python3.
# Prints "N passed, N failed"; exit 1 on any failure.
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init threads "${1:-}"

if ! command -v strace >/dev/null 2>&1 || [ "$have_python" -eq 0 ] ||
   ! strace -f -o /dev/null true >/dev/null 2>&1; then
    echo "threads.sh: no strace (or python3, or ptrace here): skipped"
    finish skipped
    cli_summary
    exit
fi

python3 bench/hypar_net.py 85 --issue10 > "$T/net.cable"
clones() {   # clones THREADS: the clone calls of one solve with that threads= line
    sed "\$a solve threads=$1" "$T/net.cable" > "$T/net$1.cable"
    strace -f -e trace=clone,clone3 -o "$T/trace$1" "$BIN" solve "$T/net$1.cable" -q -o "$T/out$1" > /dev/null 2>&1 ||
        WHY+=("threads=$1: the solve failed")
    # threads only (CLONE_THREAD: not a child process, nor LeakSanitizer's tracer at
    # exit), each counted once (a call strace splits into unfinished/resumed lines
    # names its flags once)
    grep -c 'CLONE_THREAD' "$T/trace$1"
}

n=$(clones 1)
[ "$n" -eq 0 ] || WHY+=("threads=1: $n threads started (expected none)")
finish one_thread

n=$(clones 2)
[ "$n" -le 8 ] || WHY+=("threads=2: $n threads started (expected at most 8)")
finish two_threads

n=$(clones 0)
[ "$n" -le 2 ] || WHY+=("threads=0: $n threads started (expected at most the 2 helpers)")
for f in result.json nodes.csv elements.csv; do
    cmp -s "$T/out1/$f" "$T/out0/$f" || WHY+=("$f differs between threads=1 and threads=0")
done
finish same_results

cli_summary
