#!/usr/bin/env bash
# tests/cli/python.sh CATENA: the Python package (python/, docs/python.md), as a user
# installs it from this build tree with no Python index reachable.
#
#   - for every distinct python3 (the first in PATH, and Debian's /usr/bin/python3):
#     `python3 -m pip install --no-build-isolation --no-deps --target DIR ./python`
#     (CATENA_BUILD: the directory of CATENA), then, from another directory with
#     PYTHONPATH=DIR, `import catena` reads and solves the paper's cable;
#   - the pytest suite python/tests/ (Debian's python3-pytest) with the first of those
#     pythons that has pytest: the paper's four cables against `catena solve --json` bit
#     for bit, errors with file:line (the corpus of tests/errors/), models from arrays
#     written to .cable and read back, built in bulk (test_bulk.py), threads, Ctrl-C,
#     modes, steps, the examples; to_dataframe() and plot() when pandas / matplotlib
#     are installed (optional: skipped without them).
# A sanitizer build (CTN_SANITIZE, CTN_FUZZ) is skipped: its libcatena.a needs the
# sanitizer runtime loaded first, which a Python process does not have.
# ctest-cost: 90
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init python "${1:-}"

BUILD=$(cd "$(dirname "$BIN")" && pwd)
ROOT=$PWD
if grep -Eq '^CTN_(SANITIZE|FUZZ):BOOL=ON' "$BUILD/CMakeCache.txt" 2>/dev/null; then
    echo "skipped: $BUILD is a sanitizer build (the package is tested in the plain build)"
    exit 0
fi

pythons=()
declare -A seen
for py in "$(type -P python3 || true)" /usr/bin/python3; do
    [ -n "$py" ] && [ -x "$py" ] || continue
    real=$(readlink -f "$("$py" -c 'import sys; print(sys.executable)' 2>/dev/null || echo "$py")")
    [ -n "${seen[$real]:-}" ] && continue
    seen[$real]=1
    pythons+=("$py")
done

pytest_py=""
pytest_dir=""
k=0
for py in "${pythons[@]}"; do
    k=$((k + 1))
    dir=$T/site$k
    if ! CATENA_BUILD=$BUILD PIP_NO_INDEX=1 "$py" -m pip install -q --no-build-isolation --no-deps \
            --target "$dir" ./python >"$T/pip$k.log" 2>&1; then
        WHY+=("$py: pip install failed: $(tail -5 "$T/pip$k.log")")
        finish "install ($py)"
        continue
    fi
    finish "install ($py)"
    out=$(cd "$T" && PYTHONPATH=$dir "$py" -c '
import sys, catena
s = catena.read(sys.argv[1]).solve()
print(s.converged, s.displacements.shape, s.forces.shape, catena.__file__)' \
        "$ROOT/examples/paper/s250.8777.cable" 2>&1)
    case $out in
        "True (21, 3) (20,) $dir/catena/__init__.py") ;;
        *) WHY+=("$py: import and solve from $T: $out") ;;
    esac
    finish "import ($py)"
    if [ -z "$pytest_py" ] && PYTHONPATH=$dir "$py" -c 'import pytest, numpy' >/dev/null 2>&1; then
        pytest_py=$py
        pytest_dir=$dir
    fi
done

if [ -z "$pytest_py" ]; then
    WHY+=("no python3 with pytest and numpy (scripts/deps.sh installs python3-pytest, python3-numpy)")
    finish pytest
else
    if ! (cd "$T" && PYTHONPATH=$pytest_dir CATENA_CLI=$BIN CATENA_ROOT=$ROOT \
            "$pytest_py" -m pytest -q -p no:cacheprovider "$ROOT/python/tests" >"$T/pytest.log" 2>&1); then
        WHY+=("pytest ($pytest_py) failed:" "$(tail -40 "$T/pytest.log")")
    fi
    tail -1 "$T/pytest.log"
    finish pytest
fi
cli_summary
