#!/usr/bin/env bash
# tests/cli/study.sh CATENA: end-to-end checks of `catena study` and `catena convergence`.
#
#   - study on the paper's four models (a short sweep): exit 0, the table of the marked
#     lengths (one line each), the error-vs-stress table with the reference column, the
#     slack-branch line; --json: every row converged, 4 marked, the catenary over-predicts
#     the support stress and under-predicts the sag at the two taut lengths;
#   - -o DIR: data files and the four scripts (SVGs when gnuplot is there);
#   - --element catenary: the element and the mesh tables, study_mesh.dat, --json: the
#     element equals the elastic catenary to 1e-10 on every row, the mesh is within 0.3 %;
#   - a model of another span is refused (exit 2), bad options exit 1;
#   - convergence: the observed orders are 2 +- 0.1 (--json), -o writes the figure's
#     script and data, bad --n exits 1.
# Prints "N passed, N failed"; exit 1 on any failure.
# ctest-cost: 45 (about the seconds it takes under ASan: ctest -j starts it early)
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init study "${1:-}"

PAPER=(examples/paper/s200.3340.cable examples/paper/s201.3545.cable examples/paper/s250.8777.cable
       examples/paper/s279.6157.cable)

# ---- the study, plain --------------------------------------------------------------------------
"$BIN" study "${PAPER[@]}" --sweep 12 --claims 50:1,150:6,300:30 >"$T/out" 2>"$T/err"
rc=$?
[ "$rc" = 0 ] || WHY+=("exit $rc: $(head -c 300 "$T/err")")
[ -s "$T/err" ] && WHY+=("stderr not empty: $(head -c 300 "$T/err")")
for L in 200.3340 201.3545 250.8777 279.6157; do
    [ "$(grep -c "^ *$L " "$T/out")" = 1 ] || WHY+=("no single line for the marked length $L")
done
for lev in 50 100 150 200 250 300; do
    grep -q "^ *$lev |" "$T/out" || WHY+=("no line for the level $lev MPa")
done
grep -q "^ *150 |.*| *6$" "$T/out" || WHY+=("no reference 6 % at 150 MPa")
grep -q "^slack branch" "$T/out" || WHY+=("no slack-branch line")
grep -q "16 lengths" "$T/out" || WHY+=("not 16 lengths")
finish "study"

# ---- --json -------------------------------------------------------------------------------------
"$BIN" study "${PAPER[@]}" --sweep 12 --json >"$T/s.json" 2>"$T/err" || WHY+=("--json: exit $?")
if [ "$have_python" = 1 ]; then
    msg=$(python3 - "$T/s.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
err = []
rows = d["rows"]
if len(rows) != 16: err.append("%d rows" % len(rows))
if sum(r["marked"] for r in rows) != 4: err.append("not 4 marked rows")
if not all(r["converged"] for r in rows): err.append("a row did not converge")
if [r["length"] for r in rows] != sorted(r["length"] for r in rows): err.append("rows not sorted")
for r in rows:
    if r["marked"] and r["length"] < 202:
        f, c = r["fea"], r["catenary"]
        if not (c["max_tension"] > 1.03 * f["max_tension"] and c["sag"] < 0.97 * f["sag"]):
            err.append("L0=%g: the catenary does not over-predict stress / under-predict sag" % r["length"])
print("; ".join(err)); sys.exit(1 if err else 0)
PY
) || WHY+=("--json: $msg")
else
    grep -q '"rows"' "$T/s.json" || WHY+=("--json: no rows")
fi
finish "study --json"

# ---- figures ------------------------------------------------------------------------------------
"$BIN" study "${PAPER[@]}" --sweep 12 -q -o "$T/fig" >"$T/out" 2>"$T/err"
rc=$?
[ "$rc" = 0 ] || WHY+=("exit $rc: $(head -c 300 "$T/err")")
for k in study_stress_max study_stress_min study_sag study_error; do
    [ -s "$T/fig/$k.gp" ] || WHY+=("$k.gp missing")
    if [ "$have_gnuplot" = 1 ]; then grep -q "<svg" "$T/fig/$k.svg" 2>/dev/null || WHY+=("$k.svg missing"); fi
done
for k in study_fea.dat study_catenary.dat study_elastic_catenary.dat study_marked_fea.dat study_error.dat; do
    [ -s "$T/fig/$k" ] || WHY+=("$k missing")
done
grep -qi "nan\|inf" "$T/fig"/*.dat && WHY+=("a data file holds nan or inf")
[ -s "$T/out" ] && WHY+=("-q printed something")
finish "study -o"

# ---- one catenary element per length (--element catenary) ------------------------------------------
"$BIN" study "${PAPER[@]}" --sweep 12 --element catenary -o "$T/cat" >"$T/out" 2>"$T/err"
rc=$?
[ "$rc" = 0 ] || WHY+=("--element catenary: exit $rc: $(head -c 300 "$T/err")")
grep -q "^The catenary element (one per length) against the inextensible catenary" "$T/out" || WHY+=("no element table")
grep -q "^The catenary element against the elastic catenary and the FE mesh (20 cable elements" "$T/out" ||
    WHY+=("no element-against-mesh table")
for L in 200.3340 201.3545 250.8777 279.6157; do
    [ "$(grep -c "^ *$L |" "$T/out")" = 1 ] || WHY+=("no line for $L in the element-against-mesh table")
done
[ -s "$T/cat/study_mesh.dat" ] || WHY+=("study_mesh.dat missing")
[ -s "$T/cat/study_element.gp" ] && [ -s "$T/cat/study_element.dat" ] || WHY+=("study_element figure missing")
grep -q "FE mesh, 20 cable elements" "$T/cat/study_sag.gp" || WHY+=("the sag figure lacks the mesh")
"$BIN" study "${PAPER[@]}" --sweep 12 --element catenary --json >"$T/c.json" 2>"$T/err" || WHY+=("--element --json: exit $?")
if [ "$have_python" = 1 ]; then
    msg=$(python3 - "$T/c.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
err = []
if d.get("element") != "catenary": err.append("element %r" % d.get("element"))
for r in d["rows"]:
    f, e, m = r["fea"], r["elastic_catenary"], r.get("mesh")
    for k in ("sag", "max_tension", "horizontal_force"):
        if abs(e[k] - f[k]) > 1e-10 * abs(f[k]): err.append("L0=%g: %s element %r elastic %r" % (r["length"], k, f[k], e[k]))
    if not m or abs(m["max_tension"] - f["max_tension"]) > 3e-3 * f["max_tension"]: err.append("L0=%g: mesh" % r["length"])
print("; ".join(err[:5])); sys.exit(1 if err else 0)
PY
) || WHY+=("--element --json: $msg")
fi
finish "study --element catenary"

# ---- errors ---------------------------------------------------------------------------------------
expect() {   # expect CODE TEXT ARGS...
    local code=$1 text=$2
    shift 2
    "$BIN" "$@" >"$T/out" 2>"$T/err"
    local rc=$?
    [ "$rc" = "$code" ] || WHY+=("'$*': exit $rc, expected $code")
    grep -q -- "$text" "$T/err" || WHY+=("'$*': stderr lacks '$text': $(head -c 200 "$T/err")")
}
sed 's/^node 2 200 0 0/node 2 150 0 0/' examples/paper/s250.8777.cable >"$T/other.cable"
expect 2 "not the span of" study examples/paper/s200.3340.cable "$T/other.cable" --sweep 2
expect 1 "usage: catena study" study
expect 1 "invalid option '--sweep'" study examples/paper/s200.3340.cable --sweep x
expect 1 "invalid option '--claims'" study examples/paper/s200.3340.cable --claims 1,2,3
expect 1 "sweep must run" study examples/paper/s200.3340.cable --from 150 --to 300
expect 1 "invalid option '--element'" study examples/paper/s200.3340.cable --element chain
finish "study errors"

# ---- convergence ------------------------------------------------------------------------------------
"$BIN" convergence examples/paper/s250.8777.cable --n 10,20,40,80 --json >"$T/c.json" 2>"$T/err"
rc=$?
[ "$rc" = 0 ] || WHY+=("exit $rc: $(head -c 300 "$T/err")")
if [ "$have_python" = 1 ]; then
    msg=$(python3 - "$T/c.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
err = []
for k in ("order_sag", "order_max_tension", "order_horizontal_force"):
    if abs(d.get(k, 0) - 2) > 0.1: err.append("%s = %r" % (k, d.get(k)))
if [r["elements"] for r in d["rows"]] != [10, 20, 40, 80]: err.append("rows")
print("; ".join(err)); sys.exit(1 if err else 0)
PY
) || WHY+=("$msg")
fi
"$BIN" convergence examples/paper/s250.8777.cable --n 10,20 -q -o "$T/conv" >"$T/out" 2>"$T/err" || WHY+=("-o: exit $?")
[ -s "$T/conv/convergence.gp" ] && [ -s "$T/conv/convergence.dat" ] || WHY+=("-o: files missing")
"$BIN" convergence examples/paper/s250.8777.cable >"$T/out" 2>"$T/err" || WHY+=("plain: exit $?")
grep -q "observed order.*sag 2\.0" "$T/out" || WHY+=("plain: no order 2.0 line")
expect 1 "--n takes" convergence examples/paper/s250.8777.cable --n 1,5
expect 1 "usage: catena convergence" convergence
finish "convergence"

cli_summary
