# Shared by the CLI test scripts (tests/cli/*.sh), sourced, not run: the catena binary,
# a temporary directory, and the case bookkeeping.
#   cli_init NAME BINARY   check BINARY, cd to the project root, make $T, reset counters
#   WHY+=("...")           record a problem in the current case
#   finish CASE            count the case: passed if WHY is empty, else print why
#   cli_summary            print "N passed, N failed" (and the failed names); status
#   cli_shard NAME K/N     set SHARD_K, SHARD_N (1/1 without K/N) for a script that ctest
#                          runs as N tests ("# ctest-shards: N", CMakeLists.txt)

# python3 in the scripts is Debian's interpreter when there is one (the one scripts/deps.sh
# installs numpy and pytest for): a version manager's shim first in PATH (pyenv's, on
# this project's machines) is a shell script that costs ~0.5 s of CPU per call, and the
# scripts call python3 hundreds of times. tests/cli/python.sh still tests the first
# python3 in PATH (type -P) besides Debian's.
if [ -x /usr/bin/python3 ]; then
    python3() { /usr/bin/python3 "$@"; }
fi

cli_init() {
    local name=$1
    BIN=${2:?usage: tests/cli/$name.sh PATH/TO/catena}
    case $BIN in /*) ;; *) BIN=$PWD/$BIN ;; esac
    [ -x "$BIN" ] || { echo "$name.sh: $BIN is not an executable" >&2; exit 1; }
    cd "$(dirname "$0")/../.." || exit 1
    T=$(mktemp -d "${TMPDIR:-/tmp}/catena-$name.XXXXXX") || exit 1
    trap 'rm -rf "$T"' EXIT
    PASS=0
    FAIL=0
    FAILED_NAMES=()
    WHY=()
    have_python=0
    command -v python3 >/dev/null 2>&1 && have_python=1
    have_gnuplot=0
    command -v gnuplot >/dev/null 2>&1 && have_gnuplot=1
    return 0
}

finish() {
    if [ ${#WHY[@]} -eq 0 ]; then
        PASS=$((PASS + 1))
    else
        FAIL=$((FAIL + 1))
        FAILED_NAMES+=("$1")
        echo "FAIL $1"
        local w
        for w in "${WHY[@]}"; do echo "     $w"; done
    fi
    WHY=()
}

cli_summary() {
    echo "${PASS} passed, ${FAIL} failed"
    [ "$FAIL" -eq 0 ] && return 0
    echo "failed: ${FAILED_NAMES[*]}"
    return 1
}

cli_shard() {
    local spec=${2:-1/1}
    if ! [[ $spec =~ ^([0-9]+)/([0-9]+)$ ]] || [ "${BASH_REMATCH[1]}" -lt 1 ] ||
        [ "${BASH_REMATCH[1]}" -gt "${BASH_REMATCH[2]}" ]; then
        echo "$1.sh: shard '$spec' is not K/N with 1 <= K <= N" >&2
        return 1
    fi
    SHARD_K=${BASH_REMATCH[1]}
    SHARD_N=${BASH_REMATCH[2]}
}

# The command run in one process (tests/corpus_runner.c) in a sanitizer build, where a
# process start and its leak check cost ~0.1 s each: cli_runner_start starts the runner
# built beside $BIN when that build is sanitized (CTN_SANITIZE) and sets RUNNER_ON=1;
# crun OUT ERR ARGS... runs `catena ARGS >OUT 2>ERR` through it (as a process when there
# is no runner) and sets RC. A run that ends the runner (a sanitizer's abort, a crash)
# gets the runner's exit status as RC, its report in ERR, and a new runner for the next;
# so does a run after which the runner's leak check found a leak (its report in ERR).
# cli_runner_stop ends the runner: 0, or its exit status (a leak found at its exit).
RUNNER_ON=0
cli_runner_start() {
    local dir
    dir=$(cd "$(dirname "$BIN")" && pwd)
    [ -x "$dir/corpus_runner" ] || return 0
    grep -Eq '^CTN_SANITIZE:BOOL=ON' "$dir/CMakeCache.txt" 2>/dev/null || return 0
    RUNNER_BIN=$dir/corpus_runner
    cli_runner_spawn
}
cli_runner_spawn() {
    coproc RUNNER { exec "$RUNNER_BIN" 3<&0 4>&1 </dev/null >/dev/null; }
    RUNNER_IN=${RUNNER[1]}
    RUNNER_OUT=${RUNNER[0]}
    RUNNER_CHILD=$RUNNER_PID
    RUNNER_ON=1
}
crun() {
    local out=$1 err=$2
    shift 2
    if [ "$RUNNER_ON" = 0 ]; then
        "$BIN" "$@" >"$out" 2>"$err"
        RC=$?
        return 0
    fi
    # (SIGPIPE ignored for the write: a runner that has ended must not end this script)
    local sent=0
    trap '' PIPE
    printf '%s\0' "$out" "$err" "$#" "$@" >&"$RUNNER_IN" 2>/dev/null && sent=1
    trap - PIPE
    local ended=0
    if [ "$sent" = 1 ] && read -r RC ended <&"$RUNNER_OUT"; then
        if [ "$ended" = 1 ]; then           # a leak, reported: a new runner for the next
            wait "$RUNNER_CHILD"
            cli_runner_spawn
        fi
        return 0
    fi
    wait "$RUNNER_CHILD"
    RC=$?
    [ "$RC" = 0 ] && RC=125                  # it ended cleanly in the middle of a run
    cli_runner_spawn
}
cli_runner_stop() {
    [ "$RUNNER_ON" = 1 ] || return 0
    RUNNER_ON=0
    exec {RUNNER_IN}>&-
    wait "$RUNNER_CHILD"
}
