#!/usr/bin/env bash
# bench/peers/dyn.sh N [DT] [T_END] - issue 26: a cable in free vibration, catena against
# OpenSees, the same method and dt. The B1 cable (bench/b1_cable.py N) with a mass of
# 0.1/g t/m (its weight's) and a further 10 kN at the quarter point is solved statically
# (OpenSees: 10 LoadControl steps, full Newton); then the 10 kN is released along a ramp
# of 0.1 s and the cable vibrates freely: Newmark's average acceleration (gamma 1/2, beta
# 1/4), lumped mass, no damping, dt DT (default 0.01 s) to T_END (default 20 s), both
# written by bench/peers/cable2peer.py (OpenSees' corotTruss law and catena's model of
# it). The mid-span displacement and element 1's force are recorded every step and the
# two histories compared: the largest difference over all steps, relative to the largest
# motion about the static state (tolerance 1e-6).
#   bash bench/peers/dyn.sh 1000
set -eu
source "$(dirname "$0")/common.sh"
n=${1:?usage: dyn.sh N [DT] [T_END]}
dt=${2:-0.01}
tend=${3:-20}
d=$PEERS_DIR/dyn_$n
mkdir -p "$d"
mid=$(( n / 2 + 1 ))
q=$(( n / 4 + 1 ))
{ python3 "$root/bench/b1_cable.py" "$n" | sed 's/^section c material=steel A=3.14e-4$/& mass=0.010197162129779282/'
  echo "load $q 0 -10 0"; } > "$d/cable.cable"
grep -q "mass=" "$d/cable.cable" || { echo "dyn.sh: the section line of bench/b1_cable.py changed" >&2; exit 1; }
opts=(--probe-node "$mid" --probe-elem 1 --probe-support 1 --dynamics "$dt $tend" --release "$q 0 10 0 0.1")
c2p catena-os "${opts[@]}" < "$d/cable.cable" > "$d/catena.cable"
c2p tcl --system ProfileSPD --test "NormDispIncr 1.0e-10 100" "${opts[@]}" < "$d/cable.cable" > "$d/os.tcl"
"$CATENA" solve "$d/catena.cable" -o "$d/out" > "$d/out.log" 2>&1 || { echo "catena failed: $d/out.log" >&2; exit 1; }
(cd "$d" && "$OPENSEES" os.tcl > os.tcl.log 2>&1) || { echo "OpenSees failed: $d/os.tcl.log" >&2; exit 1; }
grep "^dynamics" "$d/out.log" || true
python3 - "$d/out/history.csv" "$d/os.tcl.log" "$mid" <<'PY'
import sys, csv
hist, log, mid = sys.argv[1], sys.argv[2], sys.argv[3]
cat = {}
with open(hist) as f:
    for r in csv.DictReader(f):
        cat[round(float(r["t"]), 9)] = (float(r[mid + ".ux"]), float(r[mid + ".uy"]), float(r["1.force"]))
ops = {}
for line in open(log):
    w = line.split()
    if len(w) == 5 and w[0][0] in "0123456789":
        ops[round(float(w[0]), 9)] = (float(w[1]), float(w[2]), float(w[4]))
common = sorted(set(cat) & set(ops))
u0, n0 = cat[common[0]][1], cat[common[0]][2]
amp_u = max(abs(cat[t][1] - u0) for t in common)
amp_n = max(abs(cat[t][2] - n0) for t in common)
du = max(abs(cat[t][1] - ops[t][1]) for t in common) / amp_u
dn = max(abs(cat[t][2] - ops[t][2]) for t in common) / amp_n
ok = max(du, dn) <= 1e-6
print("histories: %d common times (catena %d, OpenSees %d rows); mid-span uy swings %.4f m, element 1 force %.3f kN about "
      "the static state; largest differences %.2e and %.2e of those -> %s (tolerance 1e-06)"
      % (len(common), len(cat), len(ops), amp_u, amp_n, du, dn, "agree" if ok else "DISAGREE"))
PY
echo "time: (cd $d && $CATENA solve catena.cable)  vs  (cd $d && $OPENSEES os.tcl)"
