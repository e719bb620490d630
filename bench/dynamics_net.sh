#!/usr/bin/env bash
# bench/dynamics_net.sh BUILD_DIR [K] [STEPS] - the dynamics analysis on the hypar net of
# issue 10 (bench/hypar_net.py K --issue10: K x K strands on a 100 m square, eps0 = 2e-3,
# 0.2 kN/m^2 of snow), given a mass of 1.2 kg/m on the strands: the static step (snow),
# then generalized-alpha (rho_inf 0.9, consistent mass, dt = 0.01 s) through STEPS steps
# (default 1000) of a harmonic gust of 5 kN at 0.5 Hz on the middle node, a row every 10th.
# Two `catena solve` runs: the net without the dynamics (the static step alone), then
# with it; prints one line:
#   K, DOF, static: Newton iterations and one iteration's cost (assembly per iteration +
#   one factorization + one solve, from the static run's phases), dynamics: steps, Newton
#   iterations per step, ms per step, the ratio ms per step / (static iteration x
#   iterations per step) (the issue's target <= 1.5), wall and peak RSS, load average.
# Environment: NETS_DIR (default /tmp/catena-nets) keeps the generated model and log.
set -eu
build=${1:?usage: dynamics_net.sh BUILD_DIR [K] [STEPS]}
k=${2:-100}
steps=${3:-1000}
here=$(cd "$(dirname "$0")" && pwd)
dir=${NETS_DIR:-/tmp/catena-nets}
mkdir -p "$dir"
net=$dir/dynnet$k.cable
mid=$(( (k / 2) * (k + 1) + k / 2 + 1 ))
python3 "$here/hypar_net.py" "$k" --issue10 | awk -v mid="$mid" -v steps="$steps" '
  /^section/ { print $0 " mass=1.2kg/m"; next }
  /^load/ && !stepped { print "step snow"; stepped = 1 }
  { print }
  END {
    print "function gust harmonic amp=1 freq=0.5"
    print "load " mid " 0 0 -5 fn=gust"
    printf "dynamics dt=0.01 t_end=%.10g rho_inf=0.9 output_every=10\n", steps * 0.01
    print "record node=" mid " dof=uz"
  }' > "$net"
grep -v '^dynamics\|^record\|^function\|fn=gust' "$net" > "$dir/statnet$k.cable"
load=$(cut -d ' ' -f 1 /proc/loadavg)
"$build/catena" solve "$dir/statnet$k.cable" > "$dir/statnet$k.log" 2>&1
/usr/bin/time -f "wall=%e rss_kib=%M" -o "$dir/dynnet$k.time" "$build/catena" solve "$net" > "$dir/dynnet$k.log" 2>&1
awk -v k="$k" -v load="$load" -v timef="$dir/dynnet$k.time" '
  FNR == 1 { file++ }
  file == 1 && /^converged after/ { its = $3 }
  file == 1 && /^time: setup/ {
    for (i = 1; i <= NF; i++) {
      if ($i == "assembly") asm = $(i + 1)
      if ($i == "factorization") { fac = $(i + 1); nf = $(i + 3); gsub(/[(;]/, "", nf) }
      if ($i == "solves") { sol = $(i + 1); ns = $(i + 3); gsub(/[()]/, "", ns) }
    }
  }
  file == 1 && /free DOFs/ { for (i = 1; i <= NF; i++) if ($i == "free") dof = $(i - 1) }
  file == 2 && /^dynamics \(/ {
    for (i = 1; i <= NF; i++) {
      if ($i == "steps") dsteps = $(i - 1)
      if ($i == "iterations,") dits = $(i - 1)
      if ($i == "time") dtime = $(i + 1)
    }
  }
  END {
    getline tl < timef
    iter = asm / its + fac / nf + sol / ns
    per = dits / dsteps
    ms = 1000 * dtime / dsteps
    printf "K=%s dof=%s static: %d its, %.2f ms/it (asm %.2f fac %.2f sol %.2f) | dynamics: %d steps, %.2f its/step, %.2f ms/step, ratio %.2f | %s load=%s\n",
      k, dof, its, 1000 * iter, 1000 * asm / its, 1000 * fac / nf, 1000 * sol / ns, dsteps, per, ms, ms / (1000 * iter * per), tl, load
  }' "$dir/statnet$k.log" "$dir/dynnet$k.log"
