#!/usr/bin/env bash
# tests/cli/statics.sh CATENA: single-cable and small-system statics against references
# computed independently in python3 (tests/cli/lib/statics_ref.py: Irvine's elastic
# catenary integrated from its differential equations for either strain law, the elastic
# parabola, the two-segment cable under a point load, series chains; nothing of catena's
# own analytic code), the way an independent checker would (tests/cli/lib/statics_check.py):
#   catenary               fine meshes under self-weight (3D inclined spans, gravity along
#                          -y and -z, kN m and N mm, engineering and Green-Lagrange):
#                          node positions, end reactions and mid-span sag at O(h^2);
#   point_load             the closed form of two straight segments, to 1e-11;
#   parabola               hload on an inclined 3D span: shape, arc length, H at O(h^2);
#   prestress_temperature  N0=, s0=, eps0=, dT on taut cables and in steps (closed forms),
#                          a heated catenary element against Irvine;
#   steps                  every step equals a one-step solve of its accumulated loads;
#   springs_reactions      spring forces, reactions' sign, loads on fixed DOFs, displace;
#   arclength              the arc-length end point at lambda against the closed form;
# and in every solved model the equilibrium recomputed from the printed forces and
# positions (converged means balanced). Skipped (passing) without python3.
# ctest-shards: 3
# ctest-cost: 50 (one shard under ASan, about)
# `statics.sh CATENA K/N` runs cases K, K + N, K + 2N, ... of the list below (ctest runs
# cli_statics_1 .. cli_statics_3 side by side); without K/N, all of them.
# Prints "N passed, N failed"; exit 1 on any failure.
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init statics "${1:-}"
cli_shard statics "${2:-}" || exit 1

if [ "$have_python" = 0 ]; then
    echo "statics.sh: no python3: skipped"
    cli_summary
    exit $?
fi

i=0
for c in catenary point_load parabola prestress_temperature steps springs_reactions arclength; do
    i=$((i + 1))
    [ $(((i - 1) % SHARD_N + 1)) = "$SHARD_K" ] || continue
    out=$(python3 tests/cli/lib/statics_check.py "$BIN" "$c" 2>&1) || WHY+=("$out")
    finish "$c"
done

cli_summary
