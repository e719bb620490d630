#!/usr/bin/env bash
# tests/cli/mpi.sh CATENA: the MPI build (registered only when PETSc and MPI are found,
# CMakeLists.txt; docs/parallel.md). `mpirun -n N catena solve MODEL --json` against the
# serial CHOLMOD run of the same model (tests/cli/lib/mpi_compare.py: every number of
# the results to 1e-10 relative, the verdicts equal, modes to 1e-8, the keys the same
# plus "ranks" = N and a PETSc "linear_solver", the same exit code):
#   models_2        a representative subset on 2 ranks (a single cable, nets, pulleys,
#                   beams with LDL', slack members, groups, modes, a semi-definite
#                   state, a run that does not converge, buckling); every example and
#                   test model with CTN_MPI_ALL=1 (all pass, 2026-12-03);
#   models_1_3      a beam model and arc-length from a singular start on 1 and 3 ranks;
#   bad_input       a malformed model on 2 ranks: one message, naming file:line, and
#                   every rank exits 2 (mpirun's exit code is the largest);
#   output_dir      -o DIR on 2 ranks: the result set written once, equal to the serial,
#                   and the VTU pieces result_r0.vtu, result_r1.vtu with result.pvtu
#                   (tests/cli/lib/pvtu_check.py: ParaView's XML, the pieces = result.vtu);
#   petsc_options   --petsc -ksp_type cg -pc_type jacobi ... and linear_solver=petsc-cg;
#   batch           `catena batch` of three models on 2 ranks: each result.json the
#                   serial solve's bytes;
#   slepc_modes     modes on SLEPc (Krylov-Schur, shift-invert on MUMPS) on 2 and 3 ranks:
#                   lowest and nearest an interior shift, against the serial ARPACK;
#   vtu_pieces      -o DIR on 3 ranks with mode shapes: three pieces and the .pvtu;
#                   the same DIR on 2 ranks: the third piece removed; then in one
#                   process: no piece and no .pvtu left;
#   killed_rank     rank 1 of 2 killed (kill -9) mid-solve: mpirun's exit code non-zero,
#                   its message naming the rank and the signal, -o DIR left empty;
#   module          PETSc and MPI live in libcatena_mpi.so (src/dist/plugin.h): the
#                   command maps none of their libraries, a `petsc` solver asked for
#                   outside an MPI job is refused naming mpirun, and the module found
#                   beside an installed command (../lib) runs it.
# The nets and single cables among them (s250.8777, net_slack, hypar_snow, slack_held_node,
# paper_E2e22, arclength_singular_start on 1 and 3 ranks) run with the tangent distributed
# by columns (src/problem/dist.c): each rank assembles its own nodes' columns; the
# semi-definite stability check of slack_held_node gathers the tangent to name its node.
# Every check_ranks run sets CATENA_MPI_DEBUG=1 and checks the line it prints (app/mpi.c):
# the tangent "by columns" for those, "whole on every rank" for the beams, pulleys,
# catenary elements, modes and buckling (tangent_of), so a change that silently drops a
# net back to the replicated tangent fails here.
# Two models are compared by their verdicts only (converged, reason, stable), their
# answers being round-off: tests/models/trust/paper_E2e14.cable (E = 2e14: the forces
# are resolved to 1e-6 by any solver, the round-off floor) and the mode shapes of
# tests/models/modes/slack_node.cable (a node held by slack members: zero modes whose
# subspace the other shapes are not unique against).
# ctest-cost: 120
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init mpi "${1:-}"

if [ "$have_python" = 0 ] || ! command -v mpirun >/dev/null 2>&1; then
    echo "mpi.sh: no python3 or mpirun: skipped"
    cli_summary
    exit $?
fi
MPIRUN=(mpirun --allow-run-as-root --oversubscribe)
export OMPI_MCA_btl_vader_single_copy_mechanism=none   # containers without CMA
export OMPI_MCA_mpi_yield_when_idle=1                # ranks waiting in MPI yield the CPU: ctest -j runs other tests beside

# how the tangent is held (CATENA_MPI_DEBUG=1's line, app/mpi.c): by columns for the
# nets and single cables on MUMPS (src/problem/dist.c), whole on every rank for beams,
# pulleys, catenary elements, modes and buckling; "" for a model not listed here
tangent_of() {
    case $1 in
    *s250.8777.cable | *net_slack.cable | *hypar_snow.cable | *slack_held_node.cable | *paper_E2e22.cable | \
        *arclength_singular_start.cable) echo "by columns" ;;
    *rollup.cable | *pulleys.cable | *catenary/net.cable | *net4.cable | *bar_springs.cable | *guyed_mast.cable | \
        *footbridge.cable | */n24s.cable) echo "whole on every rank" ;;
    esac
}

# one model on n ranks against the serial run (its JSON in $T/serial.json, exit $2)
check_ranks() {
    local model=$1 want=$2 n=$3 extra=${4:-}
    CATENA_MPI_DEBUG=1 "${MPIRUN[@]}" -n "$n" "$BIN" solve "$model" --json >"$T/par.json" 2>"$T/par.err"
    local got=$?
    [ "$got" = "$want" ] || WHY+=("$model on $n ranks: exit $got, serial $want: $(head -c 300 "$T/par.err")")
    local out tangent ranks="$n ranks"
    out=$(python3 tests/cli/lib/mpi_compare.py "$T/serial.json" "$T/par.json" "$n" $extra 2>&1) ||
        WHY+=("$model on $n ranks: $out")
    tangent=$(tangent_of "$model")
    [ "$n" = 1 ] && ranks="1 rank"
    [ -z "$tangent" ] || grep -qx "catena: mpi: $ranks, the tangent $tangent" "$T/par.err" ||
        WHY+=("$model on $n ranks: not the tangent $tangent: $(grep "^catena: mpi:" "$T/par.err")")
}

serial() {
    "$BIN" solve "$1" --json >"$T/serial.json" 2>/dev/null
}

verdict_flag() {
    case $1 in *paper_E2e14.cable|*slack_node.cable) echo --verdict ;; esac
}

# every model on 2 ranks with CTN_MPI_ALL=1 (about 6 minutes on a busy 2-core machine:
# each mpirun costs seconds), else a representative subset
if [ "${CTN_MPI_ALL:-0}" = 1 ]; then
    models_2=(examples/*/*.cable tests/models/*/*.cable)
else
    models_2=(examples/paper/s250.8777.cable examples/catenary/net.cable examples/catenary/pulleys.cable
        examples/beam/rollup.cable examples/robust/net_slack.cable examples/design/hypar_snow.cable
        tests/models/modes/net4.cable tests/models/trust/slack_held_node.cable
        tests/models/trust/paper_E2e22.cable tests/models/buckling/bar_springs.cable)
fi
for f in "${models_2[@]}"; do
    serial "$f"
    want=$?
    check_ranks "$f" "$want" 2 "$(verdict_flag "$f")"
done
finish models_2

for f in examples/beam/guyed_mast.cable tests/models/trust/arclength_singular_start.cable; do
    serial "$f"
    want=$?
    for n in 1 3; do check_ranks "$f" "$want" "$n" "$(verdict_flag "$f")"; done
done
finish models_1_3

# bad input: reported once with file:line, the same exit code (2) on every rank
bad=tests/errors/area_negative.cable
"$BIN" solve "$bad" --json >/dev/null 2>"$T/ser.err"
want=$?
"${MPIRUN[@]}" -n 2 "$BIN" solve "$bad" --json >"$T/out" 2>"$T/err"
got=$?
[ "$want" = 2 ] && [ "$got" = 2 ] || WHY+=("bad input: exit $got on 2 ranks, $want serial (2 expected)")
n=$(grep -c "^catena: $bad:[0-9]*:" "$T/err")
[ "$n" = 1 ] || WHY+=("bad input: $n messages naming $bad:LINE on 2 ranks (1 expected): $(head -c 300 "$T/err")")
grep -qF "$(head -1 "$T/ser.err")" "$T/err" || WHY+=("bad input: not the serial message")
[ -s "$T/out" ] && WHY+=("bad input: something on stdout")
finish bad_input

# -o DIR: written once (rank 0), the same files as the serial run's
m=examples/catenary/net.cable
"$BIN" solve "$m" -q -o "$T/ser" >/dev/null 2>&1
"${MPIRUN[@]}" -n 2 "$BIN" solve "$m" -q -o "$T/par" >/dev/null 2>&1 || WHY+=("output_dir: exit $?")
for f in nodes.csv elements.csv; do
    [ -s "$T/par/$f" ] || WHY+=("output_dir: no $f")
done
python3 tests/cli/lib/mpi_compare.py "$T/ser/result.json" "$T/par/result.json" 2 >"$T/cmp" 2>&1 ||
    WHY+=("output_dir: result.json: $(head -c 300 "$T/cmp")")
[ "$(ls "$T/par" | wc -l)" = "$(($(ls "$T/ser" | wc -l) + 3))" ] || WHY+=("output_dir: $(ls "$T/par") against $(ls "$T/ser") + 3 pieces")
out=$(python3 tests/cli/lib/pvtu_check.py "$T/par" 2 "$T/par/result.vtu" 2>&1) || WHY+=("output_dir: pieces: $out")
finish output_dir

# PETSc options passed through, and the iterative solver by name
m=examples/paper/s250.8777.cable
serial "$m"
"${MPIRUN[@]}" -n 2 "$BIN" solve "$m" --json --petsc -ksp_type cg -pc_type jacobi -ksp_rtol 1e-14 >"$T/par.json" 2>"$T/par.err" ||
    WHY+=("petsc_options: exit $?: $(head -c 300 "$T/par.err")")
grep -q '"linear_solver":	"petsc-cg-jacobi"' "$T/par.json" || WHY+=("petsc_options: $(grep linear_solver "$T/par.json")")
out=$(python3 tests/cli/lib/mpi_compare.py "$T/serial.json" "$T/par.json" 2 2>&1) || WHY+=("petsc_options: $out")
sed 's/^solve /solve linear_solver=petsc-cg /' "$m" >"$T/cg.cable"
grep -q "linear_solver=petsc-cg" "$T/cg.cable" || echo "solve linear_solver=petsc-cg" >>"$T/cg.cable"
"${MPIRUN[@]}" -n 2 "$BIN" solve "$T/cg.cable" --json >"$T/par.json" 2>"$T/par.err" ||
    WHY+=("petsc-cg: exit $?: $(head -c 300 "$T/par.err")")
grep -q '"linear_solver":	"petsc-cg-gamg"' "$T/par.json" || WHY+=("petsc-cg: $(grep linear_solver "$T/par.json")")
out=$(python3 tests/cli/lib/mpi_compare.py "$T/serial.json" "$T/par.json" 2 2>&1) || WHY+=("petsc-cg: $out")
finish petsc_options

# catena batch on 2 ranks: every model's result set, the serial solve's bytes
printf '%s\n' "# three models" examples/paper/s250.8777.cable examples/catenary/net.cable "" \
    examples/springs/elastic_support.cable >"$T/list"
"${MPIRUN[@]}" -n 2 "$BIN" batch "$T/list" -o "$T/batch" >"$T/out" 2>&1 || WHY+=("batch: exit $?: $(head -c 300 "$T/out")")
i=0
for m in s250.8777 net elastic_support; do
    d=$(printf '%s/%05d_%s' "$T/batch" "$i" "$m")
    src=$(sed -n "$((i + 2 + (i == 2)))p" "$T/list")
    "$BIN" solve "$src" -q -o "$T/one_$i" >/dev/null 2>&1
    cmp -s "$d/result.json" "$T/one_$i/result.json" || WHY+=("batch: $d/result.json is not the serial one")
    i=$((i + 1))
done
grep -q "^batch: 3 models over 2 ranks" "$T/out" || WHY+=("batch: $(head -c 200 "$T/out")")
finish batch

# modes on SLEPc (Krylov-Schur, shift-invert on MUMPS): the footbridge's (beams and
# catenary stays) and 8 nearest an interior shift of 3 Hz of a hypar net K = 24 with mass
# on 2 ranks, the 12 lowest of that net on 3; the same modes as the serial ARPACK run to 1e-8 (frequencies
# and shapes), and the JSON's modal solver "slepc"
MASS=0.0012 MODES=12 python3 bench/hypar_net.py 24 "" >"$T/n24.cable"
sed 's/^modes count=12$/modes count=8 shift=3/' "$T/n24.cable" >"$T/n24s.cable"
grep -q "^modes count=8 shift=3$" "$T/n24s.cable" || WHY+=("slepc_modes: no shifted model")
for m in examples/structures/footbridge.cable "$T/n24s.cable"; do
    serial "$m"
    check_ranks "$m" 0 2
    grep -q '"solver":	"slepc"' "$T/par.json" || WHY+=("slepc_modes: $m: modal solver $(grep '"solver"' "$T/par.json")")
done
# the 12 lowest on 3 ranks, in the same run as vtu_pieces (-o with --json)
serial "$T/n24.cable"
"${MPIRUN[@]}" -n 3 "$BIN" solve "$T/n24.cable" --json -o "$T/pieces" >"$T/par.json" 2>"$T/par.err" ||
    WHY+=("slepc_modes: n24 on 3 ranks: exit $?: $(head -c 300 "$T/par.err")")
out=$(python3 tests/cli/lib/mpi_compare.py "$T/serial.json" "$T/par.json" 3 2>&1) || WHY+=("slepc_modes: n24 on 3 ranks: $out")
grep -q '"solver":	"slepc"' "$T/par.json" || WHY+=("slepc_modes: n24: modal solver $(grep '"solver"' "$T/par.json")")
finish slepc_modes

# VTU pieces on 3 ranks (the run above): the hypar net with its 12 mode shapes (numbered
# point arrays), result.pvtu and result_r0..2.vtu against the run's own result.vtu
out=$(python3 tests/cli/lib/pvtu_check.py "$T/pieces" 3 "$T/pieces/result.vtu" 2>&1) || WHY+=("vtu_pieces: $out")
grep -q 'Name="mode_12"' "$T/pieces/result.pvtu" || WHY+=("vtu_pieces: no mode_12 in result.pvtu")
# the same directory again on 2 ranks: result_r2.vtu of the 3-rank run is gone, the
# .pvtu lists 2 pieces; then in one process: no piece and no .pvtu left
"${MPIRUN[@]}" -n 2 "$BIN" solve examples/paper/s250.8777.cable -q -o "$T/pieces" >/dev/null 2>&1 || WHY+=("vtu_pieces: 2 ranks: exit $?")
[ -e "$T/pieces/result_r2.vtu" ] && WHY+=("vtu_pieces: result_r2.vtu of 3 ranks left beside a 2-rank set")
out=$(python3 tests/cli/lib/pvtu_check.py "$T/pieces" 2 "$T/pieces/result.vtu" 2>&1) || WHY+=("vtu_pieces: 2 after 3: $out")
"$BIN" solve examples/paper/s250.8777.cable -q -o "$T/pieces" >/dev/null 2>&1 || WHY+=("vtu_pieces: serial: exit $?")
left=$(cd "$T/pieces" && ls result_r*.vtu result.pvtu 2>/dev/null)
[ -z "$left" ] || WHY+=("vtu_pieces: a serial set left $left")
finish vtu_pieces

# a rank killed mid-solve: the hypar net K = 120 (43k DOFs, seconds on 2 ranks), rank 1
# killed (SIGKILL) once rank 0 has printed the Newton table's head; mpirun ends the job
# with a non-zero code naming the rank and the signal; -o DIR holds nothing (no result
# set, no staged temporary: rank 0 writes only after the solve)
python3 bench/hypar_net.py 120 --issue10 >"$T/net120.cable"
"${MPIRUN[@]}" -n 2 "$BIN" solve "$T/net120.cable" -o "$T/killed" >"$T/k.out" 2>"$T/k.err" &
mp=$!
victim=
for _ in $(seq 600); do                       # up to 60 s for the solve to start
    grep -q "^Newton" "$T/k.out" 2>/dev/null && break
    kill -0 "$mp" 2>/dev/null || break
    sleep 0.1
done
for p in $(pgrep -P "$mp" 2>/dev/null); do
    tr '\0' '\n' <"/proc/$p/environ" 2>/dev/null | grep -qx OMPI_COMM_WORLD_RANK=1 && victim=$p
done
if [ -n "$victim" ] && grep -q "^Newton" "$T/k.out"; then
    kill -9 "$victim"
    wait "$mp"
    code=$?
    [ "$code" != 0 ] || WHY+=("killed_rank: mpirun exited 0")
    grep -q "rank 1 .*exited on signal 9" "$T/k.err" || WHY+=("killed_rank: no message naming rank 1 and signal 9: $(head -c 300 "$T/k.err")")
    grep -q "^converged" "$T/k.out" && WHY+=("killed_rank: the solve finished before the kill (too small a model)")
    [ -z "$(ls -A "$T/killed" 2>/dev/null)" ] || WHY+=("killed_rank: -o DIR holds $(ls -A "$T/killed" | head -5 | tr '\n' ' ')")
else
    kill "$mp" 2>/dev/null
    wait "$mp"
    WHY+=("killed_rank: the solve did not start (rank 1: '${victim}'): $(head -c 300 "$T/k.err")")
fi
finish killed_rank

# the MPI module: loaded only for a job
libs=$(ldd "$BIN" 2>/dev/null)
case $libs in *libpetsc* | *libmpi*) WHY+=("module: the command links PETSc or MPI: $(grep -E 'petsc|mpi' <<<"$libs" | head -3)") ;; esac
[ -f "$(dirname "$BIN")/libcatena_mpi.so" ] || WHY+=("module: no libcatena_mpi.so beside $BIN")
grep -v "^solve" examples/paper/s250.8777.cable >"$T/ps.cable"
echo "solve linear_solver=petsc" >>"$T/ps.cable"
"$BIN" solve "$T/ps.cable" >"$T/out" 2>"$T/err"
code=$?
[ "$code" = 4 ] && grep -q "linear solver 'petsc' runs in an MPI job: under mpirun, or with --petsc" "$T/err" ||
    WHY+=("module: linear_solver=petsc outside a job: exit $code: $(head -c 300 "$T/err")")
"$BIN" solve "$T/ps.cable" --json --petsc >"$T/par.json" 2>"$T/err" || WHY+=("module: --petsc: exit $?: $(head -c 300 "$T/err")")
grep -q '"ranks":	1' "$T/par.json" || WHY+=("module: --petsc: no ranks 1 in the JSON")
# an installed command finds the module in ../lib (the installation's library directory)
BUILD=$(dirname "$BIN")
if cmake --install "$BUILD" --prefix "$T/prefix" >"$T/install.log" 2>&1; then
    inst=$(find "$T/prefix" -name libcatena_mpi.so | head -1)
    [ -n "$inst" ] || WHY+=("module: libcatena_mpi.so not installed")
    "$T/prefix/bin/catena" solve examples/paper/s250.8777.cable --json --petsc >"$T/par.json" 2>"$T/err" ||
        WHY+=("module: installed command with --petsc: exit $?: $(head -c 300 "$T/err")")
    grep -q '"ranks":	1' "$T/par.json" || WHY+=("module: the installed command did not run PETSc")
else
    WHY+=("module: cmake --install failed: $(tail -3 "$T/install.log")")
fi
finish module

cli_summary
