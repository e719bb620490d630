#!/usr/bin/env bash
# bench/peers/beam.sh N [K] [SYSTEM] - issue 23: the large-deflection cantilever of
# bench/peers/cantilever.py (L = 10 m, 0.1 x 0.1 m steel, N elements, tip load
# P = K EI / L^2, default K = 2) for catena (`beam`, corotational), OpenSees
# (elasticBeamColumn, Corotational transformation, 10 LoadControl steps, full Newton,
# SYSTEM default BandGeneral) and CalculiX (B31, NLGEOM) when CCX_MAX >= N (default 100),
# each against the inextensible elastica (shooting) and catena against each peer:
# tip displacement and clamp reaction (catena vs OpenSees to 1e-5: two different
# corotational elements, each within 2.4e-5 of the elastica at N = 100, differ by their
# discretization errors). catena is run with its defaults and, as OpenSees,
# with `solve steps=10 method=newton linear_solver=cholmod-ldl` (docs/format.md: "Large
# rotations: load in several steps").
#   bash bench/peers/beam.sh 100
set -eu
source "$(dirname "$0")/common.sh"
n=${1:?usage: beam.sh N [K] [SYSTEM]}
k=${2:-2}
system=${3:-BandGeneral}
d=$PEERS_DIR/beam_$n
mkdir -p "$d"
cant() { python3 "$here/cantilever.py" "$@"; }
e=$(cant elastica "$n" "$k")
echo "elastica (inextensible): $e"
cant catena "$n" "$k" > "$d/catena.cable"
{ cat "$d/catena.cable"; echo "solve steps=10 method=newton linear_solver=cholmod-ldl"; } > "$d/catena_steps.cable"
for m in catena catena_steps; do
    # the tip is node 2, the clamp node 1; beam results carry no axial `force` column check
    c=$(catena_run "$d/$m.cable" "$d/out_$m" 2 1 1) || { echo "$m: not converged (see $d/out_$m.log)"; continue; }
    echo "$m: $c"
    agree 1e-4 "$m" "$(echo "$c" | sed 's/ N=[^ ]*/ N=0/')" elastica "$e"
done
cant tcl "$n" "$k" "$system" > "$d/os.tcl"
o=$(opensees_run "$d/os.tcl") && {
    echo "OpenSees $system: $o"
    agree 1e-4 OpenSees "$o" elastica "$e"
    [ -n "${c:-}" ] && agree 1e-5 catena "$(echo "$c" | sed 's/ N=[^ ]*/ N=0/')" OpenSees "$o"
}
if [ "$n" -le "${CCX_MAX:-100}" ]; then
    cant inp "$n" "$k" > "$d/beam.inp"
    x=$(ccx_run "$d/beam") && { echo "CalculiX: $x"; agree 5e-3 CalculiX "$x" elastica "$e"; }
fi
echo "time: (cd $d && $CATENA solve catena.cable)  vs  (cd $d && $OPENSEES os.tcl)  vs  (cd $d && $CCX -i beam)"
