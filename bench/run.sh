#!/usr/bin/env bash
# bench/run.sh BUILD_DIR - the single-cable benchmark (bench_cable) at n = 1e3, 1e4, 1e5,
# 1e6 elements: prints each run's key=value line, then a table and the targets.
# `make bench` calls it as `bash bench/run.sh build`. Environment:
#   BENCH_SIZES="1000 10000"                    other sizes
#   BENCH_ARGS="--method newton --ordering amd"  extra bench_cable options
#   BENCH_OUT=file                              also keep the raw lines in file
# Exit status 1 if bench_cable is missing or failed for some size.
set -eu
build=${1:-build}
bin=$build/bench_cable
if [ ! -x "$bin" ]; then
  echo "run.sh: $bin not found; build first (cmake --build $build)" >&2
  exit 1
fi
sizes=${BENCH_SIZES:-"1000 10000 100000 1000000"}
extra=${BENCH_ARGS:-}
raw=$(mktemp)
trap 'rm -f "$raw"' EXIT

cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -n 1)
echo "# $(nproc) cores, ${cpu:-unknown CPU}; load average $(cut -d ' ' -f 1-3 /proc/loadavg)"
echo "# $bin N --repeat R $extra"
status=0
for n in $sizes; do
  repeat=3
  [ "$n" -ge 1000000 ] && repeat=1             # one 1e6 solve takes several seconds
  # shellcheck disable=SC2086                  # $extra holds several options
  if ! line=$("$bin" "$n" --repeat "$repeat" $extra); then
    echo "run.sh: bench_cable $n failed" >&2
    status=1
    continue
  fi
  echo "$line" | tee -a "$raw"
done
if [ -n "${BENCH_OUT:-}" ]; then cp "$raw" "$BENCH_OUT"; fi
echo "# load average after: $(cut -d ' ' -f 1-3 /proc/loadavg)"

awk '
function v(k) { return val[k] }
{
  delete val
  for (i = 1; i <= NF; i++) { split($i, kv, "="); val[kv[1]] = kv[2] }
  r++
  n[r] = v("n"); conv[r] = v("reason"); at_floor[r] = v("at_floor"); relres[r] = v("rel_res")
  tsolve[r] = v("t_solve"); rss[r] = v("rss_mib"); ratio[r] = v("ratio")
  steady[r] = v("ratio_steady"); nsit[r] = v("ns_elem_it"); nstot[r] = 1e9 * v("t_solve") / v("n")
  line[r] = sprintf("%8d %5d %-10s %8.3f %8.3f %9.3f %8.3f %8.3f %8.3f %8.3f %9.3f %6.2f %6.2f" \
                    " %8.0f %8.0f %8.0f %s",
    v("n"), v("its"), conv[r] (at_floor[r] == 1 ? "*" : ""), tsolve[r], v("t_setup"),
    1e3 * v("t_iter"), 1e3 * v("asm_it"), 1e3 * v("fac_it"), 1e3 * v("sol_it"),
    1e3 * v("other_it"), 1e3 * v("floor"), ratio[r], steady[r], nsit[r], nstot[r], rss[r],
    v("ordering"))
  ord[r] = sprintf("%8d %-8s %11.3f %11.3f %7.2f %11.3f %11.3f %12d %12d", v("n"),
    v("ordering"), 1e3 * v("floor_nat"), 1e3 * v("floor_amd"), v("floor_amd") / v("floor_nat"),
    1e3 * v("t_an_nat"), 1e3 * v("t_an_amd"), v("lnz_nat"), v("lnz_amd"))
}
END {
  print ""
  printf "%8s %5s %-10s %8s %8s %9s %8s %8s %8s %8s %9s %6s %6s %8s %8s %8s %s\n", "n", "its",
    "reason", "solve[s]", "setup[s]", "iter[ms]", "asm", "factor", "solve", "other",
    "floor[ms]", "ratio", "steady", "ns/el/it", "ns/el", "RSS[MiB]", "ordering"
  for (i = 1; i <= r; i++) print line[i]
  print "  (converged*: the residual test was waived at its round-off floor;"
  print "   ratio = iter / floor; steady = per iteration over iterations 2..last / floor)"
  print ""
  print "floor (numeric factorization + solve, median) per ordering:"
  printf "%8s %-8s %11s %11s %7s %11s %11s %12s %12s\n", "n", "used", "natural[ms]",
    "amd[ms]", "amd/nat", "analyze_nat", "analyze_amd", "lnz_nat", "lnz_amd"
  for (i = 1; i <= r; i++) print ord[i]
  print ""
  print "targets:"
  for (i = 1; i <= r; i++) {
    printf "  n=%-8d converged: %-3s (|r|/|f_ext| %s%s)", n[i],
      conv[i] == "converged" ? "yes" : "NO", relres[i], at_floor[i] == 1 ? ", at floor" : ""
    printf "  per-iteration/floor %.2f <= 1.2: %-7s (steady %.2f)\n", ratio[i],
      ratio[i] <= 1.2 ? "met" : "NOT met", steady[i]
    if (n[i] == 1000000)
      printf "  n=1e6: solve %.2f s < 3 s: %s; peak RSS %.0f MiB < 1.5 GB (1430 MiB): %s\n",
        tsolve[i], tsolve[i] < 3 ? "met" : "NOT met", rss[i], rss[i] < 1430.5 ? "met" : "NOT met"
  }
  if (r > 1)
    printf "  linearity, n=%d vs n=%d: time per element per iteration x%.2f, whole solve" \
           " per element x%.2f\n", n[r], n[1], nsit[r] / nsit[1], nstot[r] / nstot[1]
}' "$raw"
exit "$status"
