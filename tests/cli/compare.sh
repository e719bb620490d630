#!/usr/bin/env bash
# tests/cli/compare.sh CATENA: end-to-end checks of `catena compare`.
#
#   - the paper's four cables: exit 0, empty stderr, a table with the FEA, the catenary,
#     the elastic catenary and their differences;
#   - --json: the keys fea, catenary, elastic_catenary with sag, max_tension, min_tension,
#     horizontal_force, all finite; the catenary's values against an independent bisection
#     here (python3), the FEA's support tension against `catena solve --json`'s reactions
#     (resultant), and the paper's direction: at high stress the catenary over-predicts the
#     stress and under-predicts the sag (> 3 %), on the slack cables both agree within 1 %;
#   - a weightless chain with point loads and engineering strain: funicular and
#     elastic_funicular keys, the elastic funicular equal to the FEA to 1e-9;
#   - -o DIR: the data files and the two gnuplot scripts (and SVGs when gnuplot is there);
#     with no gnuplot (CATENA_GNUPLOT=/nonexistent): exit 0, data and scripts written and
#     a message saying how to render them;
#   - usage errors exit 1, a missing file 4, a model that is not a single span 2, a model
#     that does not converge 3, each with a message on stderr.
# Prints "N passed, N failed"; exit 1 on any failure.
# ctest-cost: 25 (about the seconds it takes under ASan: ctest -j starts it early)
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init compare "${1:-}"

# check_paper_json COMPARE.json SOLVE.json S: keys, independent catenary, directions.
check_paper_json() {
    if [ "$have_python" = 0 ]; then
        local k
        for k in fea catenary elastic_catenary sag max_tension min_tension horizontal_force; do
            grep -q "\"$k\"" "$1" || { echo "missing key '$k'"; return 1; }
        done
        return 0
    fi
    python3 - "$@" <<'PY'
import json, math, sys
c = json.load(open(sys.argv[1])); s = json.load(open(sys.argv[2])); S = float(sys.argv[3])
err = []
def need(cond, what):
    if not cond: err.append(what)
for k in ("fea", "catenary", "elastic_catenary", "parabola", "elastic_parabola", "elastic_funicular"):
    need(k in c, "missing key %s" % k)
    for q in ("sag", "max_tension", "min_tension", "horizontal_force"):
        need(k in c and isinstance(c[k].get(q), (int, float)) and math.isfinite(c[k][q]) and c[k][q] > 0,
             "%s.%s missing or not positive" % (k, q))
need("funicular" not in c, "funicular given without point loads")
if err: print("; ".join(err)); sys.exit(1)
# the inextensible catenary by bisection: S = 2 c sinh(l / 2c), w = 0.1, l = 200
lo, hi = 1.0, 1e6
for _ in range(200):
    m = math.sqrt(lo * hi)
    if 2 * m * math.sinh(100 / m) > S: lo = m
    else: hi = m
cc = math.sqrt(lo * hi)
cat = c["catenary"]
need(abs(cat["max_tension"] - 0.1 * cc * math.cosh(100 / cc)) <= 1e-9 * cat["max_tension"], "catenary T_max")
need(abs(cat["horizontal_force"] - 0.1 * cc) <= 1e-9 * cat["horizontal_force"], "catenary H")
need(abs(cat["sag"] - cc * (math.cosh(100 / cc) - 1)) <= 1e-8 * cat["sag"], "catenary sag")
# the FEA's support tension is the resultant reaction of `catena solve`
R = max(math.hypot(r["fx"], r["fy"]) for r in s["reactions"])
need(abs(c["fea"]["max_tension"] - R) <= 1e-9 * R, "FEA T_max %r is not the resultant reaction %r" % (c["fea"]["max_tension"], R))
need(abs(c["fea"]["horizontal_force"] - abs(s["reactions"][0]["fx"])) <= 1e-9 * R, "FEA H")
dT = cat["max_tension"] / c["fea"]["max_tension"] - 1
dS = cat["sag"] / c["fea"]["sag"] - 1
need(abs(c["catenary"]["relative_difference"]["max_tension"] - dT) < 1e-12, "relative_difference")
if S < 202:
    need(dT > 0.03 and dS < -0.03, "S=%g: expected stress over, sag under: %.4f %.4f" % (S, dT, dS))
else:
    need(abs(dT) < 0.01 and abs(dS) < 0.01, "S=%g: expected agreement within 1 %%: %.4f %.4f" % (S, dT, dS))
if err: print("; ".join(err)); sys.exit(1)
PY
}

# ---- the paper's cables ------------------------------------------------------------------
for f in examples/paper/s*.cable; do
    name=$(basename "$f" .cable)
    S=$(sed -n 's/.*length=\([0-9.]*\).*/\1/p' "$f")
    "$BIN" compare "$f" >"$T/out" 2>"$T/err"
    rc=$?
    [ "$rc" = 0 ] || WHY+=("plain: exit $rc: $(head -c 300 "$T/err")")
    [ -s "$T/err" ] && WHY+=("plain: stderr not empty: $(head -c 300 "$T/err")")
    for row in "^FEA " "^catenary " "^elastic catenary " "difference \[%\]"; do
        grep -q "$row" "$T/out" || WHY+=("plain: no line matching '$row'")
    done
    "$BIN" compare "$f" --json >"$T/c.json" 2>"$T/err" || WHY+=("--json: exit $?")
    "$BIN" solve "$f" --json >"$T/s.json" 2>/dev/null || WHY+=("solve --json failed")
    msg=$(check_paper_json "$T/c.json" "$T/s.json" "$S") || WHY+=("--json: $msg")
    finish "compare $name"
done

# ---- figures --------------------------------------------------------------------------------
f=examples/paper/s201.3545.cable
"$BIN" compare "$f" -o "$T/fig" -q >"$T/out" 2>"$T/err"
rc=$?
[ "$rc" = 0 ] || WHY+=("-o: exit $rc: $(head -c 300 "$T/err")")
for k in compare_shape.gp compare_stress.gp compare_shape_fea.dat compare_shape_catenary.dat \
         compare_shape_elastic_catenary.dat compare_stress_fea.dat compare_stress_catenary.dat; do
    [ -s "$T/fig/$k" ] || WHY+=("-o: $k missing")
done
if [ "$have_gnuplot" = 1 ]; then
    for k in compare_shape.svg compare_stress.svg; do
        grep -q "<svg" "$T/fig/$k" 2>/dev/null || WHY+=("-o: $k missing or not SVG")
    done
fi
grep -qi "nan\|inf" "$T/fig"/*.dat && WHY+=("-o: a data file holds nan or inf")
[ "$(grep -v '^#' "$T/fig/compare_shape_fea.dat" | wc -l)" = 21 ] || WHY+=("-o: FEA shape is not 21 nodes")
ls "$T/fig" | grep -q tmp && WHY+=("-o: a temporary file was left")
[ -s "$T/out" ] && WHY+=("-q: printed something")
finish "compare -o"

CATENA_GNUPLOT=/nonexistent/gnuplot "$BIN" compare "$f" -o "$T/nognu" >"$T/out" 2>"$T/err"
rc=$?
[ "$rc" = 0 ] || WHY+=("exit $rc")
[ -s "$T/nognu/compare_shape.gp" ] && [ -s "$T/nognu/compare_stress_fea.dat" ] || WHY+=("scripts or data missing")
ls "$T/nognu" | grep -q svg && WHY+=("an SVG without gnuplot")
grep -q "gnuplot not found" "$T/err" && grep -q "gnuplot compare_shape.gp" "$T/err" || WHY+=("no message: $(cat "$T/err")")
grep -q "^FEA " "$T/out" || WHY+=("no table")
finish "compare -o without gnuplot"

# ---- point loads: the elastic funicular is the FEA ------------------------------------------
cat >"$T/chain.cable" <<'CABLE'
units kN m
material steel E=2.0e8 strain=engineering
section rod material=steel A=1e-4
node 1 0 0 0 fix=xyz
node 2 4 -2 0 fix=z
node 3 7 -2.5 0 fix=z
node 4 12 1 0 fix=xyz
element 1 1 2 section=rod l0=4.4
element 2 2 3 section=rod l0=3.1
element 3 3 4 section=rod l0=6.2
load 2 1 -10 0
load 3 0 -25 0
CABLE
"$BIN" compare "$T/chain.cable" --json >"$T/chain.json" 2>"$T/err"
rc=$?
[ "$rc" = 0 ] || WHY+=("exit $rc: $(head -c 300 "$T/err")")
if [ "$have_python" = 1 ] && [ "$rc" = 0 ]; then
    msg=$(python3 - "$T/chain.json" <<'PY'
import json, sys
c = json.load(open(sys.argv[1]))
err = []
for k in ("fea", "funicular", "elastic_funicular"):
    if k not in c: err.append("missing %s" % k)
for k in ("catenary", "parabola"):
    if k in c: err.append("%s given for point loads" % k)
if not err:
    for q, v in c["elastic_funicular"]["relative_difference"].items():
        if abs(v) > 1e-9: err.append("elastic funicular %s differs by %g" % (q, v))
print("; ".join(err)); sys.exit(1 if err else 0)
PY
) || WHY+=("$msg")
fi
finish "compare point loads"

# ---- one sag: solve and compare report the same number, odd and even n --------------------
for n in 19 20 21; do
    sed "s/n=20 /n=$n /" examples/paper/s250.8777.cable >"$T/n$n.cable"
    "$BIN" solve "$T/n$n.cable" --json >"$T/n$n.solve.json" 2>"$T/err" || WHY+=("n=$n: solve exit $?")
    "$BIN" compare "$T/n$n.cable" --json >"$T/n$n.compare.json" 2>"$T/err" || WHY+=("n=$n: compare exit $?")
done
if [ "$have_python" = 1 ]; then
    msg=$(python3 - "$T" <<'PY'
import json, sys
T = sys.argv[1]; err = []; sag = {}
for n in (19, 20, 21):
    s = json.load(open("%s/n%d.solve.json" % (T, n)))["cables"][0]["sag"]
    c = json.load(open("%s/n%d.compare.json" % (T, n)))
    if s != c["fea"]["sag"]: err.append("n=%d: solve %r, compare %r" % (n, s, c["fea"]["sag"]))
    sag[n] = s
    ref = c["elastic_catenary"]["sag"]
# the sag approaches the catenary monotonically (odd n does not dip below its neighbours)
if not (sag[19] > sag[20] > sag[21]): err.append("not monotone in n: %r" % sag)
print("; ".join(err)); sys.exit(1 if err else 0)
PY
) || WHY+=("$msg")
fi
finish "one sag: solve = compare"

# ---- errors -----------------------------------------------------------------------------------
expect() {   # expect CODE TEXT ARGS...: exit code and a stderr substring
    local code=$1 text=$2
    shift 2
    "$BIN" "$@" >"$T/out" 2>"$T/err"
    local rc=$?
    [ "$rc" = "$code" ] || WHY+=("'$*': exit $rc, expected $code")
    grep -q -- "$text" "$T/err" || WHY+=("'$*': stderr lacks '$text': $(head -c 200 "$T/err")")
}
expect 1 "usage: catena compare" compare
expect 1 "unknown or incomplete option" compare examples/paper/s200.3340.cable --bogus
expect 1 "more than one model" compare a.cable b.cable
expect 4 "catena: " compare "$T/does-not-exist.cable"
sed 's/^cable 1 2/node 3 0 50 0 fix=xyz\nnode 4 200 50 0 fix=xyz\ncable 3 4 section=strand n=4 length=201\ncable 1 2/' \
    examples/paper/s250.8777.cable >"$T/two.cable"
expect 2 "not a single span" compare "$T/two.cable"
sed 's/maxit=50/maxit=1/' examples/paper/s250.8777.cable >"$T/maxit.cable"
expect 3 "did not converge" compare "$T/maxit.cable"
finish "compare errors"

# ---- every message about the model starts with its file name ---------------------------------
# expect_named CODE FILE TEXT CMD...: exit CODE, stderr "catena: FILE:" ... TEXT (one line).
expect_named() {
    local code=$1 file=$2 text=$3
    shift 3
    "$BIN" "$@" >"$T/out" 2>"$T/err"
    local rc=$?
    [ "$rc" = "$code" ] || WHY+=("'$*': exit $rc, expected $code: $(head -c 300 "$T/err")")
    head -c $((${#file} + 9)) "$T/err" | grep -qxF "catena: $file:" ||
        WHY+=("'$*': the message does not start with 'catena: $file:': $(head -c 300 "$T/err")")
    grep -qF -- "$text" "$T/err" || WHY+=("'$*': stderr lacks '$text': $(head -c 300 "$T/err")")
    [ "$(wc -l <"$T/err")" = 1 ] || WHY+=("'$*': not one line: $(head -c 300 "$T/err")")
}
HEAD='units kN m
material steel E=2.0e8 strain=engineering
section rod material=steel A=1e-4'
printf '%s\n' "$HEAD" 'node 1 0 0 0 fix=xyz' 'node 2 10 0 0 fix=xyz' 'node 3 5 -1 0' \
    'element 1 1 3 section=rod' 'element 2 3 2 section=rod' >"$T/noload.cable"
expect_named 2 "$T/noload.cable" "neither gravity nor loads" compare "$T/noload.cable"
printf '%s\n' "$HEAD" 'node 1 0 0 0 fix=xyz' 'node 2 0 -10 0 fix=xyz' 'node 3 1 -5 0' \
    'element 1 1 3 section=rod' 'element 2 3 2 section=rod' 'load 3 0 -1 0' >"$T/vertical.cable"
expect_named 2 "$T/vertical.cable" "chord is vertical" compare "$T/vertical.cable"
printf '%s\n' "$HEAD" 'gravity 0 -1 0' 'node 1 0 0 0 fix=xyz' 'node 2 10 0 0 fix=xyz' 'node 3 5 -1 0' \
    'element 1 1 3 section=rod' 'element 2 3 2 section=rod' 'load 3 0 -1 0.5' >"$T/outofplane.cable"
expect_named 2 "$T/outofplane.cable" "leave the vertical plane" compare "$T/outofplane.cable"
printf '%s\n' "$HEAD" 'section heavy material=steel A=1e-4 w=0.1' 'gravity 0 -1 0' 'node 1 0 0 0 fix=xyz' 'node 2 10 0 0 fix=xyz' 'node 3 5 -1 0' \
    'element 1 1 3 section=rod' 'element 2 3 2 section=heavy' >"$T/differ.cable"
expect_named 2 "$T/differ.cable" "elements differ" compare "$T/differ.cable"
printf '%s\n' "$HEAD" 'node 1 0 0 0 fix=xyz' 'node 2 10 0 0 fix=xyz' 'node 3 5 -1 0' 'node 4 5 -3 0 fix=xyz' \
    'element 1 1 3 section=rod' 'element 2 3 2 section=rod' 'element 3 3 4 section=rod' 'load 3 0 -1 0' >"$T/joins.cable"
expect_named 2 "$T/joins.cable" "not a single span" compare "$T/joins.cable"
expect_named 2 "$T/two.cable" "not a single span" compare "$T/two.cable"
# a bad model: the model checks' own file:line
printf '%s\n' "$HEAD" 'node 1 0 0 0 fix=xyz' 'node 2 10 0 0 fix=xyz' 'node 3 5 -1 0' \
    'element 1 1 3 section=rod' 'element 2 3 2 section=rod' 'load 3 0 -1 0' \
    'node 4 0 5 0' 'node 5 5 5 0' 'element 9 4 5 section=rod' >"$T/part.cable"
expect_named 2 "$T/part.cable:12" "no support reaches" compare "$T/part.cable"
expect_named 2 "$T/part.cable:12" "no support reaches" study "$T/part.cable" --sweep 2
expect_named 2 "$T/part.cable:12" "no support reaches" convergence "$T/part.cable" --n 4
# study and convergence: spans they cannot take
expect_named 2 "$T/chain.cable" "not point loads" study "$T/chain.cable" --sweep 2
expect_named 2 "$T/chain.cable" "self-weight only" convergence "$T/chain.cable" --n 4
expect_named 2 "$T/two.cable" "not a single span" study examples/paper/s250.8777.cable "$T/two.cable" --sweep 2
expect_named 2 "$T/noload.cable" "neither gravity nor loads" convergence "$T/noload.cable" --n 4
expect_named 3 "$T/maxit.cable" "did not converge" compare "$T/maxit.cable"
finish "compare errors name the model file"

cli_summary
