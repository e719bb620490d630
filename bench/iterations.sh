#!/usr/bin/env bash
# bench/iterations.sh CATENA [OLD_CATENA] - the iteration benchmark set (issue 29, item 3):
# Newton iterations, factorizations and wall seconds of each model, by default settings:
#   B1: the OpenSees B1 cable (1000 m span, a 1 m parabola of `element`s prestressed by
#       eps0 = 1e-3, 0.1 kN/m as point loads) at n = 1e3, 1e4, 1e5;
#   the issue-10 hypar nets at K = 50, 100, 400 (bench/hypar_net.py K --issue10);
#   the paper's four cables from the arc (their files: pure Newton) and from straight
#       (shape=straight, method=auto);
#   the hard tension-only nets of issue 28 item 11 (bench/hypar_net.py K: snow 0.5 kN on
#       every node, most strands slack) at K = 100, 200, 300, and K = 100 under 2 kN;
#   every examples/*/*.cable (summed).
# With OLD_CATENA, each model runs with both and the line carries both counts.
# Environment: ITER_DIR (default /tmp/catena-iterations) keeps the generated models;
# ITER_QUICK=1 leaves out K = 400 and the K = 200, 300 hard nets.
set -u
abs() { case $1 in /*) echo "$1" ;; *) echo "$PWD/$1" ;; esac; }
new=$(abs "${1:?usage: iterations.sh CATENA [OLD_CATENA]}")
old=${2:+$(abs "$2")}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
dir=${ITER_DIR:-/tmp/catena-iterations}
mkdir -p "$dir"

b1() { python3 "$here/b1_cable.py" "$1"; }   # b1 N > file

# run BIN MODEL: "iterations factorizations wall-s" of catena's own process ("- -" and
# the reason when it did not converge)
run() {
    (cd "$(dirname "$2")" && /usr/bin/time -f %e -o "$dir/.time" "$1" solve "$2" --json >"$dir/.json" 2>/dev/null)
    python3 - "$dir/.json" "$(tail -1 "$dir/.time")" <<'PY'
import json, sys
try:
    d = json.load(open(sys.argv[1]))
    print(d["iterations"], d.get("factorizations", "-"), sys.argv[2], "" if d["converged"] else d["reason"])
except Exception:
    print("- -", sys.argv[2], "no result")
PY
}

line() {   # line NAME MODEL
    local a b
    a=$(run "$new" "$2")
    if [ -n "$old" ]; then
        b=$(run "$old" "$2")
        printf '%-28s new: %-28s old: %s\n' "$1" "$a" "$b"
    else
        printf '%-28s %s\n' "$1" "$a"
    fi
}

echo "# $(nproc) cores, load $(cut -d ' ' -f 1-3 /proc/loadavg); columns: iterations factorizations wall-s"
for n in 1000 10000 100000; do
    [ -s "$dir/b1_$n.cable" ] || b1 $n >"$dir/b1_$n.cable"
    line "B1 n=$n" "$dir/b1_$n.cable"
done
ks="50 100 400"
[ "${ITER_QUICK:-0}" = 1 ] && ks="50 100"
for k in $ks; do
    [ -s "$dir/net$k.cable" ] || python3 "$here/hypar_net.py" "$k" --issue10 >"$dir/net$k.cable"
    line "net K=$k" "$dir/net$k.cable"
done
for f in "$root"/examples/paper/s*.cable; do
    b=$(basename "$f" .cable)
    line "paper $b arc" "$f"
    sed -e 's/^\(cable .*\) shape=arc/\1 shape=straight/' -e 's/method=newton/method=auto/' "$f" >"$dir/${b}_straight.cable"
    line "paper $b straight" "$dir/${b}_straight.cable"
done
hk="100 200 300"
[ "${ITER_QUICK:-0}" = 1 ] && hk="100"
for k in $hk; do
    [ -s "$dir/hard$k.cable" ] || python3 "$here/hypar_net.py" "$k" >"$dir/hard$k.cable"
    line "hard net K=$k" "$dir/hard$k.cable"
done
[ -s "$dir/hard100_snow2.cable" ] || python3 "$here/hypar_net.py" 100 tension-only 2 >"$dir/hard100_snow2.cable"
line "hard net K=100 snow 2" "$dir/hard100_snow2.cable"
tot_new=0; tot_old=0; nm=0
for f in "$root"/examples/*/*.cable; do
    a=$(run "$new" "$f"); tot_new=$((tot_new + ${a%% *}))
    if [ -n "$old" ]; then b=$(run "$old" "$f"); tot_old=$((tot_old + ${b%% *})); fi
    nm=$((nm + 1))
done 2>/dev/null
if [ -n "$old" ]; then echo "examples ($nm models): iterations new $tot_new, old $tot_old"
else echo "examples ($nm models): iterations $tot_new"; fi
