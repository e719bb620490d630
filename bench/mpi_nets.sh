#!/usr/bin/env bash
# bench/mpi_nets.sh BUILD_DIR K [serial|1|2 ...] - the hypar net of issue 10
# (bench/hypar_net.py K --issue10, 3 (K-1)^2 DOFs) solved by the serial program (CHOLMOD)
# and under mpirun on N ranks (MUMPS through PETSc, docs/parallel.md), each process timed
# by GNU time (/usr/bin/time -v, one file per rank). One line per run:
#   run, K, DOF, wall (mpirun's whole job), the peak RSS of each rank (MiB), load
#   average before, the summary's iterations, factorizations and factorization time,
#   and for MUMPS its own figures (ICNTL(4) = 2 statistics of the last factorization):
#   INFOG(16)/(17) the estimated memory per rank (largest) and in total (MB), INFOG(18)/(19)
#   the memory it used (largest rank, total; MB), INFOG(29) the factor's entries, RINFOG(1)
#   its flops (CHOLMOD's factor entries and flops for the serial run).
# Environment: NETS_DIR (default /tmp/catena-nets) keeps the models and the logs.
#   bash bench/mpi_nets.sh build 400 serial 1 2
#   bash bench/mpi_nets.sh build 1000 serial 1 2     # 3M DOF: about 20 GB in all; once
set -eu
build=${1:?usage: mpi_nets.sh BUILD_DIR K [serial|1|2 ...]}
k=${2:?usage: mpi_nets.sh BUILD_DIR K [serial|1|2 ...]}
shift 2
runs=${*:-serial 1 2}
here=$(cd "$(dirname "$0")" && pwd)
dir=${NETS_DIR:-/tmp/catena-nets}
mkdir -p "$dir"
net=$dir/net$k.cable
[ -s "$net" ] || python3 "$here/hypar_net.py" "$k" --issue10 >"$net"
dof=$((3 * (k - 1) * (k - 1)))
export OMPI_MCA_btl_vader_single_copy_mechanism=none OMP_NUM_THREADS=1
rss() {   # the peak RSS of each rank's GNU time file, MiB
    for f in "$@"; do awk '/Maximum resident set size/ { printf "%.0f ", $NF / 1024 }' "$f"; done
}
for run in $runs; do
    log=$dir/mpi$k.$run
    rm -f "$log".time.*
    load=$(cut -d ' ' -f 1 /proc/loadavg)
    t0=$(date +%s.%N)
    if [ "$run" = serial ]; then
        /usr/bin/time -v -o "$log.time.0" "$build/catena" solve "$net" >"$log.out" 2>&1 || true
    else
        mpirun --allow-run-as-root --oversubscribe -n "$run" sh -c \
            'exec /usr/bin/time -v -o "$0.time.$OMPI_COMM_WORLD_RANK" "$@"' "$log" \
            "$build/catena" solve "$net" --petsc -mat_mumps_icntl_4 2 >"$log.out" 2>&1 || true
    fi
    t1=$(date +%s.%N)
    wall=$(echo "$t1 - $t0" | bc)
    sum=$(awk '
        /^converged|^NOT/ { its = $3 }
        /^time:/ { gsub(/[(),;]/, " "); fac = $9; nfac = $11 }
        /INFOG\(16\)/ { g16 = $NF } /INFOG\(17\)/ { g17 = $NF }
        /INFOG\(18\)/ { g18 = $NF } /INFOG\(19\)/ { g19 = $NF }
        /INFOG\(29\)/ { g29 = $NF } /RINFOG\(1\)/ { fl = $NF }
        /^factor:/ { lnz = $2; fl = $4 }
        END { printf "its=%s factorizations=%s factor_s=%s", its, nfac, fac
              if (g16 == "") { g16 = g17; g18 = g19 }   # one rank: MUMPS prints the totals only
              if (g17 != "") printf " infog16_mb=%s infog17_mb=%s infog18_mb=%s infog19_mb=%s infog29=%s", g16, g17, g18, g19, g29
              else printf " lnz=%s", lnz
              printf " flops=%s", fl }' "$log.out")
    echo "run=$run k=$k dof=$dof wall=$(printf %.1f "$wall") rss_mib_per_rank=\"$(rss "$log".time.* | sed 's/ $//')\" load=$load $sum"
done
