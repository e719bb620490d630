#!/usr/bin/env bash
# Install the Debian packages catena needs, only those that are missing. libopenblas0-openmp
# is the BLAS under CHOLMOD, linked by its own path (CMakeLists.txt), and runs its threads
# in the OpenMP pool CHOLMOD uses: one threading layer, sized by catena for each
# factorization. The machine's BLAS alternatives are left as they were.
set -eu
# python3-dev, -pip, -setuptools, -numpy, -pytest: the Python package (python/, docs/python.md)
# built offline from the tree and its tests (ctest cli_python).
pkgs="gcc binutils make cmake pkg-config libsuitesparse-dev libopenblas0-openmp libarpack2-dev liblapack-dev libcjson-dev gnuplot-nox clang libclang-rt-14-dev python3
      python3-dev python3-pip python3-setuptools python3-numpy python3-pytest"
# petsc-dev, slepc-dev, libopenmpi-dev, openmpi-bin: the MPI build (docs/parallel.md):
# PETSc 3.18 with MUMPS, OpenMPI 4.1, found by CMake (optional there: without them
# catena builds as the serial program; CTN_DEPS_MPI=0 leaves them out).
[ "${CTN_DEPS_MPI:-1}" = 1 ] && pkgs="$pkgs petsc-dev slepc-dev libopenmpi-dev openmpi-bin"
# calculix-ccx: CalculiX 2.20, the peer of the benchmarks (bench/nets.sh, bench/peers/);
# no build or test uses it.
pkgs="$pkgs calculix-ccx"
# CTN_DEPS_VTK=1: also VTK's Python reader (76 packages), which tests/cli/vtu.sh then
# uses besides its plain XML reader to read result.vtu back.
[ "${CTN_DEPS_VTK:-0}" = 1 ] && pkgs="$pkgs python3-vtk9"
missing=""
for p in $pkgs; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
# Debian's python3 refuses `pip install` outside a virtual environment (PEP 668: the
# EXTERNALLY-MANAGED marker); catena's package installs from the tree with `python3 -m
# pip install --no-build-isolation --no-deps ./python` (docs/python.md), so pip is told
# once, in /etc/pip.conf, to allow it on this development machine.
allow_pip() {
  ls /usr/lib/python3*/EXTERNALLY-MANAGED >/dev/null 2>&1 || return 0
  grep -qs '^break-system-packages' /etc/pip.conf && return 0
  echo "deps: /etc/pip.conf: break-system-packages = true (PEP 668; docs/python.md)" >&2
  if grep -qs '^\[global\]' /etc/pip.conf; then
    $SUDO sed -i '/^\[global\]/a break-system-packages = true' /etc/pip.conf
  else
    printf '[global]\nbreak-system-packages = true\n' | $SUDO tee -a /etc/pip.conf >/dev/null
  fi
}
if [ -z "$missing" ]; then allow_pip; exit 0; fi
echo "deps: installing$missing" >&2
# Installing libopenblas0-openmp would switch Debian's libblas.so.3 and liblapack.so.3
# alternatives for every program on the machine; catena links OpenBLAS by its own path
# (CMakeLists.txt), so what the alternatives pointed to before is put back.
arch=$(dpkg-architecture -qDEB_HOST_MULTIARCH 2>/dev/null || gcc -print-multiarch 2>/dev/null || echo x86_64-linux-gnu)
alts="libblas.so.3-$arch liblapack.so.3-$arch"
declare -A before
for a in $alts; do
  before[$a]=$(update-alternatives --query "$a" 2>/dev/null | awk '/^Value:/ { print $2 }')
done
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq $missing >/dev/null
for a in $alts; do
  now=$(update-alternatives --query "$a" 2>/dev/null | awk '/^Value:/ { print $2 }')
  if [ -n "${before[$a]}" ] && [ "$now" != "${before[$a]}" ]; then
    echo "deps: $a back to ${before[$a]} (catena links OpenBLAS itself)" >&2
    $SUDO update-alternatives --set "$a" "${before[$a]}" >/dev/null
  fi
done
allow_pip
