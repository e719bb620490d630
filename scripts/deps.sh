#!/usr/bin/env bash
# Install the Debian packages catena needs, only those that are missing. libopenblas0-openmp
# becomes the BLAS under CHOLMOD (Debian's alternatives) and runs its threads in the OpenMP
# pool CHOLMOD uses: one threading layer, sized by catena for each factorization.
set -eu
pkgs="gcc binutils make cmake pkg-config libsuitesparse-dev libopenblas0-openmp libarpack2-dev liblapack-dev libcjson-dev gnuplot-nox clang libclang-rt-14-dev python3"
# CTN_DEPS_VTK=1: also VTK's Python reader (76 packages), which tests/cli/vtu.sh then
# uses besides its plain XML reader to read result.vtu back.
[ "${CTN_DEPS_VTK:-0}" = 1 ] && pkgs="$pkgs python3-vtk9"
missing=""
for p in $pkgs; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
echo "deps: installing$missing" >&2
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq $missing >/dev/null
