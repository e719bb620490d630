#!/usr/bin/env bash
# bench/peers/mooring.sh N [DT] [T_END] - issue 26: a mooring line driven at its fairlead,
# catena against OpenSees, the same equations, method and dt. The line of
# bench/peers/mooring_line.py N (a 302 m chain from an anchor 100 m down to a fairlead
# 280 m away, EA 7.5e5 kN, 0.115 t/m, 0.98 kN/m submerged, prestrained 5e-4, N corotTruss
# elements in the plane) is solved statically (OpenSees: 10 LoadControl steps, full
# Newton), then its fairlead surges: u = 3 min(t / 12, 1) sin(2 pi t / 12) m (a 12 s wave
# period, the amplitude ramped over the first period), given to both as the same table
# of points every DT (linear between them); Newmark's average acceleration (gamma 1/2,
# beta 1/4), lumped mass, no damping, dt DT (default 0.02 s) to T_END (default 60 s),
# both models written by bench/peers/cable2peer.py (OpenSees' corotTruss law and
# catena's model of it). The fairlead tension (the top element's force) and the mid node's
# displacement are recorded every step and compared: the largest difference over all
# steps, relative to the largest swing about the static state (tolerance 1e-6). Then the
# two are timed in pairs (bench/peers/paired.sh, RUNS runs, default 3).
#   bash bench/peers/mooring.sh 50
set -eu
source "$(dirname "$0")/common.sh"
n=${1:?usage: mooring.sh N [DT] [T_END] [RUNS]}
dt=${2:-0.02}
tend=${3:-60}
runs=${4:-3}
d=$PEERS_DIR/mooring_$n
mkdir -p "$d"
mid=$(( n / 2 + 1 ))
python3 "$root/bench/peers/mooring_line.py" "$n" > "$d/line.cable"
python3 - "$d/motion.txt" "$dt" "$tend" <<'PY'
import sys, math
path, dt, tend = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
with open(path, "w") as f:
    for k in range(int(round(tend / dt)) + 1):
        t = k * dt
        f.write("%.9g %.17g\n" % (t, 3.0 * min(t / 12.0, 1.0) * math.sin(2 * math.pi * t / 12.0)))
PY
opts=(--probe-node "$mid" --probe-elem "$n" --probe-support 1 --dynamics "$dt $tend" --motion "$(( n + 1 )) x $d/motion.txt")
c2p catena-os "${opts[@]}" < "$d/line.cable" > "$d/catena.cable"
c2p tcl --ndm 2 --system ProfileSPD --test "NormDispIncr 1.0e-10 100" "${opts[@]}" < "$d/line.cable" > "$d/os.tcl"
"$CATENA" solve "$d/catena.cable" -o "$d/out" > "$d/out.log" 2>&1 || { echo "catena failed: $d/out.log" >&2; exit 1; }
(cd "$d" && "$OPENSEES" os.tcl > os.tcl.log 2>&1) || { echo "OpenSees failed: $d/os.tcl.log" >&2; exit 1; }
grep "^dynamics" "$d/out.log" || true
python3 - "$d/out/history.csv" "$d/os.tcl.log" "$mid" "$n" <<'PY'
import sys, csv
hist, log, mid, n = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]
cat = {}
with open(hist) as f:
    for r in csv.DictReader(f):
        cat[round(float(r["t"]), 9)] = (float(r[mid + ".ux"]), float(r[mid + ".uy"]), float(r[n + ".force"]))
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
tmax = max(common, key=lambda t: cat[t][2])
tmin = min(common, key=lambda t: cat[t][2])
ok = max(du, dn) <= 1e-6 and len(common) == len(cat)
print("histories: %d common times (catena %d, OpenSees %d rows); fairlead tension %.3f kN static, %.3f at t = %g s to "
      "%.3f at t = %g s (OpenSees %.3f, %.3f); mid node uy swings %.4f m; largest differences %.2e (uy) and %.2e (tension) "
      "of the swings -> %s (tolerance 1e-06)"
      % (len(common), len(cat), len(ops), n0, cat[tmax][2], tmax, cat[tmin][2], tmin, ops[tmax][2], ops[tmin][2], amp_u,
         du, dn, "agree" if ok else "DISAGREE"))
PY
echo "paired timing (A catena, B OpenSees):"
bash "$here/paired.sh" "$runs" "$d" "$CATENA solve catena.cable -q" "$OPENSEES os.tcl"
