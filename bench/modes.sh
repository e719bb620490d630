#!/usr/bin/env bash
# bench/modes.sh BUILD_DIR [K...]: the modal analysis's cost against the static solve
# (issue 12): for each K (default 100 200 400) the K x K hypar net of bench/hypar_net.py
# (tension-only strands, snow 0.5 kN, mass 0.0012 t/m, `modes count=20`) is solved by
# `catena solve`; prints, from its summary, the static solve (iterations, factorizations,
# the mean numeric factorization), the modal analysis (its factorization, solves and
# total) and the ratio modal total / mean factorization, with the process's wall, user
# and system time and peak memory (/usr/bin/time). OMP_NUM_THREADS is passed on.
set -eu
build=${1:-build}
shift || true
sizes=${*:-"100 200 400"}
bin=$build/catena
[ -x "$bin" ] || { echo "modes.sh: $bin not found; build first" >&2; exit 1; }
dir=$(mktemp -d "${TMPDIR:-/tmp}/catena-modes.XXXXXX")
trap 'rm -rf "$dir"' EXIT
echo "# $(nproc) cores, load average $(cut -d ' ' -f 1-3 /proc/loadavg), OMP_NUM_THREADS=${OMP_NUM_THREADS:-unset}"
printf "%5s %8s %4s %5s %10s %10s %9s %9s %7s %9s %6s %8s %8s %8s %8s\n" K DOFs its facts "factor[s]" "mean[s]" \
    "m_fac[s]" "m_sol[s]" solves "modal[s]" ratio "wall[s]" "user[s]" "sys[s]" "RSS[MiB]"
for k in $sizes; do
    MASS=0.0012 MODES=20 python3 "$(dirname "$0")/hypar_net.py" "$k" >"$dir/net.cable"
    /usr/bin/time -f "%e %U %S %M" -o "$dir/time" "$bin" solve "$dir/net.cable" >"$dir/out" 2>"$dir/err" || true
    awk -v k="$k" -v tf="$dir/time" '
        /^converged after/ { its = $3; dofs = $(NF - 4) }
        /^time: setup/ { for (i = 1; i <= NF; i++) { if ($i == "factorization") { tfac = $(i + 1); n = $(i + 3) }
                                                      } gsub(/[()]/, "", n) }
        /^modes \(/ { for (i = 1; i <= NF; i++) if ($i == "solves,") solves = $(i - 1) }
        /^modal time:/ { total = $3; mfac = $(NF - 4); msol = $(NF - 1) }
        END {
            getline t < tf; split(t, a, " ")
            mean = tfac / n
            printf "%5d %8d %4d %5d %10.3f %10.3f %9.3f %9.3f %7d %9.3f %6.2f %8.1f %8.1f %8.1f %8.0f\n", k, dofs, its, n,
                   tfac, mean, mfac, msol, solves, total, total / mean, a[1], a[2], a[3], a[4] / 1024
        }' "$dir/out"
done
