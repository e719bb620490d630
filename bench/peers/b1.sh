#!/usr/bin/env bash
# bench/peers/b1.sh N [SYSTEM ...] - issue 29's B1 cable for catena, OpenSees and CalculiX.
# The model: bench/b1_cable.py N (1000 m span, a parabola of 1 m sag, N elements prestressed
# by eps0 = 1e-3, its weight 0.1 kN/m as point loads of 0.1 * 1000 / N kN on the interior
# nodes, held in z), written for each program by bench/peers/cable2peer.py so that the
# three solve the same equations (its header: OpenSees' corotTruss law and catena's model
# of it; CalculiX's St. Venant-Kirchhoff truss and catena's model of that one).
# OpenSees: 10 LoadControl steps of 0.1, full Newton, NormDispIncr 1e-8 m, RCM numbering,
# one script per linear system (default: ProfileSPD BandSPD SparseSYM UmfPack SparseGEN),
# a plane model (ndm 2, B1_NDM=3 for the 3D one with every node held in z: its 1e5 single
# point constraints make OpenSees superlinear: 1.1 s of CPU at n = 1e4, over 93 s at 1e5).
# CalculiX only when CCX_MAX >= N (default 1000: its trusses become 20-node bricks).
# Each program is run once, the mid-span node's displacement, element 1's force and the
# reaction at node 1 compared (tolerance 1e-6 relative, catena vs OpenSees; 1e-3 vs
# CalculiX); then the commands to time are printed (bench/peers/paired.sh times them).
#   bash bench/peers/b1.sh 100000 ProfileSPD SparseSYM
set -eu
source "$(dirname "$0")/common.sh"
n=${1:?usage: b1.sh N [SYSTEM ...]}
shift
systems=${*:-ProfileSPD BandSPD SparseSYM UmfPack SparseGEN}
d=$PEERS_DIR/b1_$n
mkdir -p "$d"
mid=$(( n / 2 + 1 ))
python3 "$root/bench/b1_cable.py" "$n" > "$d/b1.cable"
c2p catena-os < "$d/b1.cable" > "$d/catena_os.cable"
c=$(catena_run "$d/catena_os.cable" "$d/out_os" "$mid" 1 1)
echo "catena (OpenSees' law): $c"
for s in $systems; do
    c2p tcl --ndm "${B1_NDM:-2}" --system "$s" --probe-node "$mid" --probe-elem 1 --probe-support 1 < "$d/b1.cable" > "$d/os_$s.tcl"
    o=$(opensees_run "$d/os_$s.tcl") || continue
    echo "OpenSees $s: $o"
    agree 1e-6 catena "$c" "OpenSees-$s" "$o"
done
if [ "$n" -le "${CCX_MAX:-1000}" ]; then
    c2p catena-ccx < "$d/b1.cable" > "$d/catena_ccx.cable"
    cc=$(catena_run "$d/catena_ccx.cable" "$d/out_ccx" "$mid" 1 1)
    echo "catena (CalculiX' law): $cc"
    c2p inp --probe-node "$mid" --probe-support 1 < "$d/b1.cable" > "$d/b1.inp"
    x=$(ccx_run "$d/b1") && { echo "CalculiX: $x"; agree 1e-3 catena "$cc" CalculiX "$x"; }
fi
echo "time: (cd $d && $CATENA solve catena_os.cable)  vs  (cd $d && $OPENSEES os_SYSTEM.tcl)"
