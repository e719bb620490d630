#!/usr/bin/env bash
# tests/cli/blas.sh CATENA: the BLAS catena runs on is OpenBLAS's OpenMP build, linked by
# its own file name ahead of CHOLMOD (CMakeLists.txt), not whatever Debian's libblas.so.3
# alternative gives every program (issue 28, item 7):
#   - where libopenblas0-openmp is installed, catena's NEEDED list names libopenblas.so.0
#     before libcholmod.so.3, and the summary names "OpenBLAS ... (OpenMP)";
#   - scripts/deps.sh puts the alternatives back when it installs the package (read
#     here: it queries them before and sets them after).
# Prints "N passed, N failed"; exit 1 on any failure.
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init blas "${1:-}"

arch=$(gcc -print-multiarch 2>/dev/null || echo x86_64-linux-gnu)
if [ -e "/usr/lib/$arch/openblas-openmp/libopenblas.so.0" ] && command -v readelf >/dev/null; then
    needed=$(readelf -d "$BIN" | sed -n 's/.*NEEDED.*\[\(.*\)\]/\1/p' | tr '\n' ' ')
    case $needed in
    *libopenblas.so.0*libcholmod*) ;;
    *) WHY+=("NEEDED: $needed (libopenblas.so.0 must come before libcholmod)") ;;
    esac
    "$BIN" solve examples/paper/s250.8777.cable >"$T/out" 2>&1 || WHY+=("the paper's cable does not solve")
    grep -q "BLAS OpenBLAS .* (OpenMP)" "$T/out" || WHY+=("the summary's BLAS: $(grep BLAS "$T/out")")
fi
finish openblas_linked_by_name

grep -q 'update-alternatives --query' scripts/deps.sh && grep -q 'update-alternatives --set' scripts/deps.sh ||
    WHY+=("scripts/deps.sh does not put the BLAS alternatives back")
finish deps_keeps_the_alternatives

cli_summary
