# Shared by the CLI test scripts (tests/cli/*.sh), sourced, not run: the catena binary,
# a temporary directory, and the case bookkeeping.
#   cli_init NAME BINARY   check BINARY, cd to the project root, make $T, reset counters
#   WHY+=("...")           record a problem in the current case
#   finish CASE            count the case: passed if WHY is empty, else print why
#   cli_summary            print "N passed, N failed" (and the failed names); status
#   cli_shard NAME K/N     set SHARD_K, SHARD_N (1/1 without K/N) for a script that ctest
#                          runs as N tests ("# ctest-shards: N", CMakeLists.txt)

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
