#!/usr/bin/env bash
# bench/peers/paired.sh RUNS DIR 'COMMAND_A' 'COMMAND_B' - whole-process wall and CPU
# seconds of two commands run in turn (A B A B ..., one warm-up of each first, not
# counted), each from DIR, by GNU time; prints every pair and the medians, and the median
# of the pair-by-pair ratios B/A (how many times faster A is). Pairing keeps the ratio
# meaningful when the machine's load drifts; the load average is printed before and after.
#   bash bench/peers/paired.sh 5 /tmp/catena-peers/b1_100000 \
#        "$PWD/build/catena solve catena_os.cable" "/work/opensees-build/OpenSees os_ProfileSPD.tcl"
set -eu
runs=${1:?usage: paired.sh RUNS DIR COMMAND_A COMMAND_B}
dir=$2 a=$3 b=$4
cd "$dir"
t=$(mktemp)
trap 'rm -f "$t"' EXIT
one() {  # one COMMAND: "wall cpu" of one run, its output thrown away
    /usr/bin/time -f "%e %U %S" -o "$t" sh -c "exec $1 >/dev/null 2>&1" || true
    awk '{ printf "%s %.2f\n", $1, $2 + $3 }' "$t"
}
echo "load average before: $(cut -d ' ' -f 1-3 /proc/loadavg)"
one "$a" >/dev/null; one "$b" >/dev/null
: > "$t.pairs"
for i in $(seq "$runs"); do
    ra=$(one "$a"); rb=$(one "$b")
    echo "pair $i: A wall/cpu $ra   B wall/cpu $rb"
    echo "$ra $rb" >> "$t.pairs"
done
echo "load average after: $(cut -d ' ' -f 1-3 /proc/loadavg)"
python3 - "$t.pairs" <<'PY'
import sys, statistics as st
rows = [list(map(float, l.split())) for l in open(sys.argv[1])]
med = lambda k: st.median(r[k] for r in rows)
print("median A wall %.3f s cpu %.2f s; B wall %.3f s cpu %.2f s; B/A wall %.1fx (pairs %.1f-%.1f), cpu %.1fx"
      % (med(0), med(1), med(2), med(3), st.median(r[2] / r[0] for r in rows),
         min(r[2] / r[0] for r in rows), max(r[2] / r[0] for r in rows),
         st.median(r[3] / max(r[1], 1e-3) for r in rows)))
PY
rm -f "$t.pairs"
