# bench/peers/common.sh - sourced by bench/peers/*.sh: where the programs are, and the runs
# that check the answers before anything is timed.
#   CATENA    catena's binary                  (default: BUILD/catena of this tree)
#   OPENSEES  the serial Tcl OpenSees binary   (default: /work/opensees-build/OpenSees;
#             how it was built: bench/peers/README.md)
#   CCX       CalculiX                          (default: ccx, Debian's calculix-ccx)
#   PEERS_DIR where the models and logs go      (default: /tmp/catena-peers)
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
CATENA=${CATENA:-$root/build/catena}
OPENSEES=${OPENSEES:-/work/opensees-build/OpenSees}
CCX=${CCX:-ccx}
PEERS_DIR=${PEERS_DIR:-/tmp/catena-peers}
c2p() { python3 "$here/cable2peer.py" "$@"; }
ans() { python3 "$here/answers.py" "$@"; }

# catena_run MODEL OUTDIR NODE ELEM SUPPORT: solve with -o, print the answer line plus
# "iterations=I factorizations=F" from the summary
catena_run() {
    "$CATENA" solve "$1" -o "$2" > "$2.log" 2>&1 || { echo "catena failed: $2.log" >&2; return 1; }
    local its fac
    its=$(sed -n 's/.*after \([0-9]*\) iterations.*/\1/p' "$2.log" | tail -1)
    fac=$(sed -n 's/.*factorization [0-9.]* s (\([0-9]*\);.*/\1/p' "$2.log" | tail -1)
    echo "$(ans catena "$2" "$3" "$4" "$5") iterations=$its factorizations=$fac"
}

# opensees_run SCRIPT: run it from its directory, print the answer line (with iterations)
# and this one run's wall and CPU seconds (GNU time; a first look, not the timing)
opensees_run() {
    (cd "$(dirname "$1")" && /usr/bin/time -f "%e %U %S" -o "$1.time" "$OPENSEES" "$(basename "$1")" > "$1.log" 2>&1) \
        || { echo "OpenSees failed: $1.log" >&2; return 1; }
    echo "$(ans opensees "$1.log") $(awk '{ printf "once: wall=%s cpu=%.2f", $1, $2 + $3 }' "$1.time")"
}

# ccx_run JOB (JOB.inp in its directory): print the answer line and the increments and
# iterations CalculiX reports
ccx_run() {
    (cd "$(dirname "$1")" && "$CCX" -i "$(basename "$1")" > "$1.log" 2>&1) \
        || { echo "CalculiX failed: $1.log" >&2; return 1; }
    local its inc
    its=$(grep -c "iteration [0-9]" "$1.log" || true)
    inc=$(grep -c "^ increment [0-9]" "$1.log" || true)
    echo "$(ans ccx "$1.dat") increments=$inc iterations=$its"
}

# agree TOL NAME_A LINE_A NAME_B LINE_B (answers.py compare); never stops the script
agree() { ans compare "$@" || true; }
