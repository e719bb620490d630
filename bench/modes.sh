#!/usr/bin/env bash
# bench/modes.sh BUILD_DIR [K...]: the modal analysis's cost against the static solve
# (issue 12): for each K (default 100 200 400) the K x K hypar net of bench/hypar_net.py
# (mass 0.0012 t/m, `modes count=20`) is solved by `catena solve`; prints, from its
# summary, the static solve (iterations, numeric factorizations, their wall and CPU
# time), the modal analysis (its factorizations, eigen-solver, solves and block solves,
# restarts, largest residual, wall and CPU time) and the ratios modal / mean static
# factorization in wall and in CPU time (the issue's target: < 3), with the process's
# wall, user and system time and peak memory (/usr/bin/time).
#   NET="..."      hypar_net.py's arguments after K (default: tension-only strands, snow
#                  0.5 kN; NET='"" 0' is the prestressed two-way net without snow)
#   SOLVER=block|arpack   the `modes` line's solver= (default: catena's)
# OMP_NUM_THREADS is passed on.
set -eu
build=${1:-build}
shift || true
sizes=${*:-"100 200 400"}
bin=$build/catena
[ -x "$bin" ] || { echo "modes.sh: $bin not found; build first" >&2; exit 1; }
dir=$(mktemp -d "${TMPDIR:-/tmp}/catena-modes.XXXXXX")
trap 'rm -rf "$dir"' EXIT
echo "# $(nproc) cores, load average $(cut -d ' ' -f 1-3 /proc/loadavg), OMP_NUM_THREADS=${OMP_NUM_THREADS:-unset}," \
     "NET=${NET:-default}, SOLVER=${SOLVER:-default}"
printf "%5s %8s %3s %3s %8s %8s %6s %3s %7s %6s %6s %8s %8s %8s %7s %7s %8s %8s %8s %8s %7s\n" K DOFs its fac \
    "fac[s]" "facCPU" solver mf solves blocks rest resid "modal[s]" "mCPU[s]" "sol[s]" "solCPU" ratio \
    "CPUratio" "wall[s]" "user[s]" "RSS[MiB]"
for k in $sizes; do
    eval "MASS=0.0012 MODES=20 python3 \"$(dirname "$0")/hypar_net.py\" $k ${NET:-}" >"$dir/net.cable"
    [ -n "${SOLVER:-}" ] && sed -i "s/^modes count=20$/modes count=20 solver=$SOLVER/" "$dir/net.cable"
    /usr/bin/time -f "%e %U %S %M" -o "$dir/time" "$bin" solve "$dir/net.cable" >"$dir/out" 2>"$dir/err" || true
    awk -v k="$k" -v tf="$dir/time" '
        /^converged after/ { its = $3; dofs = $(NF - 4) }
        /^time: setup/ { for (i = 1; i <= NF; i++) if ($i == "factorization") { tfac = $(i + 1); n = $(i + 3); cfac = $(i + 5) }
                         gsub(/[(;]/, "", n) }
        /^modes \(/ { for (i = 1; i <= NF; i++) { if ($i == "solves,") solves = $(i - 1); if ($i == "factorization(s),") mf = $(i - 1)
                                                  if ($i == "Lanczos") rest = $(i - 1) }
                      resid = $NF }
        /^eigen-solver:/ { solver = $2 == "block" ? "block" : "arpack"; sub(/,$/, "", solver)
                           for (i = 1; i <= NF; i++) if ($i == "block" && $(i + 1) ~ /^solves/) blocks = $(i - 1) }
        /^modal time:/ { total = $3; msol = $(NF - 7); mcpu = $(NF - 4); scpu = $(NF - 1); gsub(/[()]/, "", scpu) }
        END {
            getline t < tf; split(t, a, " ")
            mean = tfac / n; cmean = cfac / n
            printf "%5d %8d %3d %3d %8.3f %8.3f %6s %3d %7d %6d %6d %8.1e %8.3f %8.3f %7.3f %7.3f %8.2f %8.2f %8.1f %8.1f %7.0f\n",
                   k, dofs, its, n, tfac, cfac, solver, mf, solves, blocks, rest, resid, total, mcpu, msol, scpu,
                   total / mean, mcpu / cmean, a[1], a[2], a[4] / 1024
        }' "$dir/out"
done
