#!/usr/bin/env bash
# bench/peers/net.sh K [SYSTEM ...] - issue 29's hypar net (bench/hypar_net.py K --issue10:
# K x K two-way strands on a 100 m square, z = 10 (x^2 - y^2)/50^2, eps0 = 2e-3, 0.2 kN/m^2
# as point loads on the free nodes, boundary pinned) for catena, OpenSees and CalculiX,
# each written by bench/peers/cable2peer.py (the same equations; see its header).
# OpenSees: 10 LoadControl steps, full Newton, NormDispIncr 1e-8 m, RCM numbering, one
# script per linear system (default SparseSYM ProfileSPD UmfPack). CalculiX (T3D2, NLGEOM,
# one *STATIC step, the prestrain as a cooling; bench/nets.sh's writer with nu = 0) when
# CCX_MAX >= K (default 100). Probes: the centre node's displacement, element 1's force,
# the reaction at the middle of the edge x = -50. Tolerance 1e-6 (OpenSees), 1e-3 (CalculiX:
# its default residual test is 0.5 % of the average force).
#   bash bench/peers/net.sh 100
set -eu
source "$(dirname "$0")/common.sh"
k=${1:?usage: net.sh K [SYSTEM ...]}
shift
systems=${*:-SparseSYM ProfileSPD UmfPack}
d=$PEERS_DIR/net_$k
mkdir -p "$d"
centre=$(( (k / 2) * (k + 1) + k / 2 + 1 ))
edge=$(( k / 2 + 1 ))
python3 "$root/bench/hypar_net.py" "$k" --issue10 > "$d/net.cable"
c2p catena-os < "$d/net.cable" > "$d/catena_os.cable"
c=$(catena_run "$d/catena_os.cable" "$d/out_os" "$centre" 1 "$edge")
echo "catena (OpenSees' law): $c"
for s in $systems; do
    c2p tcl --system "$s" --probe-node "$centre" --probe-elem 1 --probe-support "$edge" < "$d/net.cable" > "$d/os_$s.tcl"
    o=$(opensees_run "$d/os_$s.tcl") || continue
    echo "OpenSees $s: $o"
    agree 1e-6 catena "$c" "OpenSees-$s" "$o"
done
if [ "$k" -le "${CCX_MAX:-100}" ]; then
    c2p catena-ccx < "$d/net.cable" > "$d/catena_ccx.cable"
    cc=$(catena_run "$d/catena_ccx.cable" "$d/out_ccx" "$centre" 1 "$edge")
    echo "catena (CalculiX' law): $cc"
    c2p inp --probe-node "$centre" --probe-support "$edge" < "$d/net.cable" > "$d/net.inp"
    x=$(ccx_run "$d/net") && { echo "CalculiX: $x"; agree 1e-3 catena "$cc" CalculiX "$x"; }
fi
echo "time: (cd $d && $CATENA solve catena_os.cable)  vs  (cd $d && $OPENSEES os_SYSTEM.tcl)  vs  (cd $d && $CCX -i net)"
