#!/usr/bin/env bash
# bench/nets.sh BUILD_DIR K [catena|ccx|both] - the hypar net of issue 10 (bench/hypar_net.py
# K --issue10: K x K strands on a 100 m square, eps0 = 2e-3, 0.2 kN/m^2) solved by catena
# (`catena solve NET -o DIR`, its defaults) and/or by CalculiX 2.20 (`ccx`, Debian's
# calculix-ccx, installed here if missing) on the identical net. One line per run:
#   tool, K, DOF, wall and CPU seconds, peak RSS (GNU time), load average before, and for
#   catena the summary's phases (setup, assembly, factorization with its count and CPU,
#   solves), ordering, factor size and flops, threads and BLAS.
# Environment: NETS_DIR (default /tmp/catena-nets) keeps the generated models.
#   bash bench/nets.sh build 100 both     # k = 100: catena and CalculiX side by side
#   bash bench/nets.sh build 1000         # k = 1000 (3M DOF), catena only
set -eu
build=${1:?usage: nets.sh BUILD_DIR K [catena|ccx|both]}
k=${2:?usage: nets.sh BUILD_DIR K [catena|ccx|both]}
what=${3:-catena}
here=$(cd "$(dirname "$0")" && pwd)
dir=${NETS_DIR:-/tmp/catena-nets}
mkdir -p "$dir"
net=$dir/net$k.cable
[ -s "$net" ] || python3 "$here/hypar_net.py" "$k" --issue10 > "$net"
dof=$(( 3 * (k - 1) * (k - 1) ))
timed() {   # timed LOG CMD...: run, GNU time's wall/user/sys/maxrss appended to LOG
  /usr/bin/time -f "wall=%e user=%U sys=%S rss_mib=%M" -o "$1.time" "${@:2}" > "$1" 2>&1 || true
  awk '{ for (i = 1; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] } }
       END { printf "wall=%s cpu=%.2f rss_mib=%.0f", v["wall"], v["user"] + v["sys"], v["rss_mib"] / 1024 }' "$1.time"
}
if [ "$what" = catena ] || [ "$what" = both ]; then
  load=$(cut -d ' ' -f 1 /proc/loadavg)
  res=$(timed "$dir/catena$k.log" "$build/catena" solve "$net" -o "$dir/out$k")
  sum=$(awk '
    /^converged|^NOT|after [0-9]+ iterations/ { its = $3; ord = $NF }
    /^time:/ { gsub(/[(),;]/, " "); setup = $3; asm = $6; fac = $9; nfac = $11; cpu = $13; thr = $15; sol = $18; nsol = $20 }
    /^factor:/ { nnz = $2; fl = $4; sub(/^.*; BLAS /, ""); blas = $0; gsub(/ /, "_", blas) }
    END { printf "its=%s ordering=%s setup=%s assembly=%s factor=%s factorizations=%s factor_cpu=%s threads=%s solves=%s nsolves=%s lnz=%s flops=%s blas=%s",
          its, ord, setup, asm, fac, nfac, cpu, thr, sol, nsol, nnz, fl, blas }' "$dir/catena$k.log")
  echo "tool=catena k=$k dof=$dof $res load=$load $sum"
fi
if [ "$what" = ccx ] || [ "$what" = both ]; then
  if ! command -v ccx >/dev/null; then
    SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO=sudo
    $SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq calculix-ccx >/dev/null
  fi
  inp=$dir/net$k
  [ -s "$inp.inp" ] || python3 "$here/hypar_net.py" "$k" --ccx > "$inp.inp"
  load=$(cut -d ' ' -f 1 /proc/loadavg)
  res=$(cd "$dir" && OMP_NUM_THREADS=${OMP_NUM_THREADS:-$(nproc)} timed "$dir/ccx$k.log" ccx -i "net$k")
  its=$(grep -c "iteration [0-9]" "$dir/ccx$k.log" || true)
  echo "tool=ccx k=$k dof=$dof $res load=$load iterations=$its"
fi
