#!/usr/bin/env bash
# tests/cli/solve.sh CATENA: end-to-end checks of `catena solve` on the paper's examples.
#
#   - examples/paper/*.cable converge: exit 0, empty stderr, the iteration log;
#   - --json: valid JSON with the keys of docs/format.md ("Results"), consistent counts,
#     finite numbers, the residual test met, reactions balancing the self-weight;
#   - -o DIR: result.json (the same document as --json), nodes.csv and elements.csv with
#     their headers and one row per node / element, result.vtu (its contents are
#     tests/cli/vtu.sh's), and nothing else in DIR;
#   - -q prints nothing; help exits 0; usage errors exit 1 with a message on stderr;
#   - every complete model (```cable block) of docs/format.md gives its exit code.
# Run from the repository root (ctest does). Prints "N passed, N failed"; exit 1 on any
# failure.
# ctest-cost: 110 (about the seconds it takes under ASan: ctest -j starts it early)
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init solve "${1:-}"

# check_result_json FILE NNODES NELEMS WEIGHT: the keys and their consistency.
# WEIGHT is the total self-weight the vertical reactions must carry.
check_result_json() {
    if [ "$have_python" = 1 ]; then
        python3 - "$@" <<'EOF'
import json, math, sys
path, nn, ne, weight = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4])
errors = []
def need(cond, what):
    if not cond:
        errors.append(what)
try:
    d = json.load(open(path))
except Exception as e:
    print("not valid JSON: %s" % e)
    sys.exit(1)
def finite_tree(x):
    if isinstance(x, bool) or x is None or isinstance(x, str):
        return True
    if isinstance(x, (int, float)):
        return math.isfinite(x)
    if isinstance(x, list):
        return all(finite_tree(v) for v in x)
    return all(finite_tree(v) for v in x.values())
for k in ("converged", "reason", "iterations", "residual_history", "increment_history",
          "external_force_norm", "units", "nodes", "elements", "reactions", "cables"):
    need(k in d, "missing key '%s'" % k)
if errors:
    print("; ".join(errors))
    sys.exit(1)
need(d["converged"] is True, "converged is not true")
need(d["reason"] == "converged", "reason is %r" % d["reason"])
it = d["iterations"]
need(isinstance(it, int) and 1 <= it <= 50, "iterations = %r" % it)
need(len(d["residual_history"]) == it + 1, "residual_history has %d entries for %d iterations" % (len(d["residual_history"]), it))
need(len(d["increment_history"]) == it, "increment_history has %d entries" % len(d["increment_history"]))
need(d["residual_history"][-1] <= 1e-10 * d["external_force_norm"], "last residual above tol * |f_ext|")
need(d["units"] == {"force": "kN", "length": "m"}, "units = %r" % d["units"])
need(finite_tree(d), "a number is not finite")
need(len(d["nodes"]) == nn, "%d nodes, expected %d" % (len(d["nodes"]), nn))
for n in d["nodes"]:
    for k in ("id", "x", "y", "z", "ux", "uy", "uz"):
        need(k in n, "node without '%s'" % k)
need(len(d["elements"]) == ne, "%d elements, expected %d" % (len(d["elements"]), ne))
for e in d["elements"]:
    for k in ("id", "nodes", "l0", "length", "strain", "force", "stress"):
        need(k in e, "element without '%s'" % k)
    need(isinstance(e.get("nodes"), list) and len(e["nodes"]) == 2, "element nodes is not a pair")
    need(e.get("force", 0) > 0, "element %s not in tension" % e.get("id"))
need(len(d["reactions"]) == 2, "%d reactions, expected 2" % len(d["reactions"]))
for r in d["reactions"]:
    for k in ("node", "fx", "fy", "fz"):
        need(k in r, "reaction without '%s'" % k)
ids = {n["id"] for n in d["nodes"]}
need(len(ids) == nn, "node ids are not unique")
need(all(a in ids for e in d["elements"] for a in e["nodes"]), "an element names an unknown node")
need({r["node"] for r in d["reactions"]} == {1, 2}, "reactions not at the supports 1 and 2")
fy = sum(r["fy"] for r in d["reactions"])
fx = sum(r["fx"] for r in d["reactions"])
need(abs(fy - weight) <= 1e-8 * weight, "vertical reactions %.17g, expected the weight %.17g" % (fy, weight))
need(abs(fx) <= 1e-8 * weight, "horizontal reactions do not balance: %g" % fx)
need(len(d["cables"]) == 1 and d["cables"][0]["first_element"] == 1
     and d["cables"][0]["last_element"] == ne, "cables entry")
if errors:
    print("; ".join(errors))
    sys.exit(1)
EOF
        return
    fi
    # Without python: the keys at least.
    local k
    for k in converged iterations residual_history nodes elements reactions ux uy uz \
             l0 length strain force stress fx fy fz; do
        grep -q "\"$k\"" "$1" || { echo "missing key '$k'"; return 1; }
    done
    tr -d ' \t\r\n' <"$1" | grep -q '"converged":true' || { echo "converged is not true"; return 1; }
}

# same_json A B: the same JSON document.
same_json() {
    if [ "$have_python" = 1 ]; then
        python3 -c 'import json,sys; sys.exit(json.load(open(sys.argv[1])) != json.load(open(sys.argv[2])))' "$1" "$2" 2>/dev/null
    else
        diff -q <(tr -d ' \t\r\n' <"$1") <(tr -d ' \t\r\n' <"$2") >/dev/null
    fi
}

# ---- the paper's examples -----------------------------------------------------------------
n_examples=0
for f in examples/paper/*.cable; do
    n_examples=$((n_examples + 1))
    name=$(basename "$f" .cable)
    S=$(sed -n 's/.*length=\([0-9.]*\).*/\1/p' "$f")
    W=$(awk -v s="$S" 'BEGIN { printf "%.17g", 0.1 * s }')   # w = 0.1 kN/m

    # Plain run: exit 0, the log, nothing on stderr.
    "$BIN" solve "$f" >"$T/out" 2>"$T/err"
    rc=$?
    [ "$rc" = 0 ] || WHY+=("plain: exit $rc: $(head -c 300 "$T/err")")
    [ -s "$T/err" ] && WHY+=("plain: stderr not empty: $(head -c 300 "$T/err")")
    grep -q '^Newton-Raphson' "$T/out" || WHY+=("plain: no iteration log header")
    grep -qE '^converged after [0-9]+ iterations' "$T/out" || WHY+=("plain: no 'converged after N iterations' line")
    grep -q 'mid-span sag' "$T/out" || WHY+=("plain: no mid-span sag")
    finish "$name: solve"

    # -q: silent.
    "$BIN" solve "$f" -q >"$T/out" 2>"$T/err"
    rc=$?
    [ "$rc" = 0 ] || WHY+=("-q: exit $rc")
    [ -s "$T/out" ] && WHY+=("-q: stdout not empty")
    [ -s "$T/err" ] && WHY+=("-q: stderr not empty")
    finish "$name: solve -q"

    # --json.
    "$BIN" solve "$f" --json >"$T/$name.json" 2>"$T/err"
    rc=$?
    [ "$rc" = 0 ] || WHY+=("--json: exit $rc: $(head -c 300 "$T/err")")
    [ -s "$T/err" ] && WHY+=("--json: stderr not empty")
    msg=$(check_result_json "$T/$name.json" 21 20 "$W" 2>&1) || WHY+=("--json: $msg")
    finish "$name: solve --json"

    # -o DIR (created), then again into the same DIR (overwritten).
    dir=$T/out_$name
    for pass in create overwrite; do
        "$BIN" solve "$f" -q -o "$dir" >"$T/out" 2>"$T/err"
        rc=$?
        [ "$rc" = 0 ] || WHY+=("-o ($pass): exit $rc: $(head -c 300 "$T/err")")
    done
    extra=$(ls -A "$dir" 2>/dev/null | grep -vxE 'result\.json|nodes\.csv|elements\.csv|result\.vtu')
    [ -z "$extra" ] || WHY+=("-o: unexpected files: $extra")
    if [ -s "$dir/result.json" ]; then
        msg=$(check_result_json "$dir/result.json" 21 20 "$W" 2>&1) || WHY+=("result.json: $msg")
        same_json "$dir/result.json" "$T/$name.json" || WHY+=("result.json differs from the --json output")
    else
        WHY+=("-o: no result.json")
    fi
    if [ -s "$dir/nodes.csv" ]; then
        [ "$(head -n 1 "$dir/nodes.csv")" = "id,x,y,z,ux,uy,uz,fix,rx,ry,rz" ] ||
            WHY+=("nodes.csv header: $(head -n 1 "$dir/nodes.csv")")
        [ "$(tail -n +2 "$dir/nodes.csv" | wc -l)" = 21 ] || WHY+=("nodes.csv: not 21 rows")
        awk -F, 'NR > 1 && NF != 11 { bad = 1 } END { exit bad }' "$dir/nodes.csv" ||
            WHY+=("nodes.csv: a row without 11 fields")
        [ "$(awk -F, 'NR > 1 && $8 == "xyz"' "$dir/nodes.csv" | wc -l)" = 2 ] ||
            WHY+=("nodes.csv: not two fix=xyz rows")
    else
        WHY+=("-o: no nodes.csv")
    fi
    if [ -s "$dir/elements.csv" ]; then
        [ "$(head -n 1 "$dir/elements.csv")" = "id,node1,node2,l0,length,strain,force,stress,slack,utilisation,group" ] ||
            WHY+=("elements.csv header: $(head -n 1 "$dir/elements.csv")")
        [ "$(tail -n +2 "$dir/elements.csv" | wc -l)" = 20 ] || WHY+=("elements.csv: not 20 rows")
        awk -F, 'NR > 1 && NF != 11 { bad = 1 } END { exit bad }' "$dir/elements.csv" ||
            WHY+=("elements.csv: a row without 11 fields")
        # l0 = S / n for a generated cable; tension positive.
        awk -F, -v s="$S" 'NR > 1 && (($4 - s / 20) ^ 2 > (1e-12 * s) ^ 2 || $7 <= 0) { bad = 1 } END { exit bad }' \
            "$dir/elements.csv" || WHY+=("elements.csv: l0 != length/n or a non-positive force")
    else
        WHY+=("-o: no elements.csv")
    fi
    grep -qiE 'nan|inf' "$dir"/*.csv 2>/dev/null && WHY+=("a CSV holds nan or inf")
    finish "$name: solve -o DIR"

    # --json and -o together: both outputs.
    dir=$T/both_$name
    "$BIN" solve "$f" --json -o "$dir" >"$T/both.json" 2>"$T/err"
    rc=$?
    [ "$rc" = 0 ] || WHY+=("--json -o: exit $rc")
    same_json "$T/both.json" "$T/$name.json" || WHY+=("--json -o: stdout differs from --json alone")
    [ -s "$dir/result.json" ] && [ -s "$dir/nodes.csv" ] && [ -s "$dir/elements.csv" ] ||
        WHY+=("--json -o: files missing")
    finish "$name: solve --json -o DIR"
done
[ "$n_examples" = 4 ] || { WHY+=("expected 4 paper examples, found $n_examples"); finish examples; }

# ---- the sag of a vertical cable ------------------------------------------------------------
# A cable hanging along gravity (vertical chord), pushed sideways at its middle node: its
# sag is the largest distance of the deformed cable from the chord, not 0, in `sag` and
# `max_sag_from_chord` (docs/format.md, `cables`).
cat >"$T/vertical.cable" <<'CABLE'
units kN m
material steel E=2.0e8 strain=engineering
section rod material=steel A=1e-4 w=0.1
gravity 0 -1 0
node 1 0 0 0 fix=xyz
node 2 0 -10 0 fix=xyz
cable 1 2 section=rod n=10 length=10.2 shape=straight
load 7 1 0 0.5
CABLE
"$BIN" solve "$T/vertical.cable" --json >"$T/vertical.json" 2>"$T/err"
rc=$?
[ "$rc" = 0 ] || WHY+=("exit $rc: $(head -c 300 "$T/err")")
if [ "$have_python" = 1 ] && [ "$rc" = 0 ]; then
    msg=$(python3 - "$T/vertical.json" <<'PY'
import json, math, sys
d = json.load(open(sys.argv[1]))
c = d["cables"][0]
# distance of each deformed node from the chord, the line x = z = 0
dist = max(math.hypot(n["x"] + n["ux"], n["z"] + n["uz"]) for n in d["nodes"])
err = []
if not dist > 0.5: err.append("the cable did not move sideways (%g)" % dist)
for k in ("sag", "max_sag_from_chord"):
    if k not in c or abs(c[k] - dist) > 1e-9 * dist: err.append("%s %r, distance from the chord %r" % (k, c.get(k), dist))
print("; ".join(err)); sys.exit(1 if err else 0)
PY
) || WHY+=("$msg")
fi
"$BIN" solve "$T/vertical.cable" >"$T/out" 2>&1
grep -q "mid-span sag 0 m" "$T/out" && WHY+=("the summary says sag 0")
grep -q "max sag from chord" "$T/out" || WHY+=("the summary lacks the max sag from chord")
finish "sag of a vertical cable"

# ---- the complete models of docs/format.md ------------------------------------------------
# Every ```cable block of the format reference is a whole model; it must give exit 0, or
# the code of a "# exit: N" line in the block.
if [ -f docs/format.md ]; then
    awk -v dir="$T" '
        /^```cable[[:space:]]*$/ { n++; f = sprintf("%s/doc_%02d.cable", dir, n); inblk = 1; next }
        /^```/ && inblk { inblk = 0; close(f); next }
        inblk { print > f }
        END { print n + 0 > (dir "/doc_count") }' docs/format.md
    [ "$(cat "$T/doc_count")" -ge 5 ] || { WHY+=("fewer than 5 complete models in docs/format.md"); finish "docs/format.md examples"; }
    for f in "$T"/doc_*.cable; do
        [ -e "$f" ] || continue
        want=$(sed -n 's/^# exit: \([0-9]\).*/\1/p' "$f" | head -n 1)
        want=${want:-0}
        "$BIN" solve "$f" -q >/dev/null 2>"$T/err"
        rc=$?
        [ "$rc" = "$want" ] || WHY+=("expected exit $want, got $rc: $(head -c 300 "$T/err"); model: $(head -n 3 "$f" | tr '\n' ' ')")
        finish "docs/format.md example $(basename "$f" .cable)"
    done
else
    WHY+=("docs/format.md is missing")
    finish "docs/format.md examples"
fi

# ---- usage --------------------------------------------------------------------------------
EX=examples/paper/s200.3340.cable
# usage_case NAME ARGS...: exit 1, a message on stderr, nothing on stdout.
usage_case() {
    local name=$1
    shift
    "$BIN" "$@" >"$T/out" 2>"$T/err"
    local rc=$?
    [ "$rc" = 1 ] || WHY+=("expected exit 1, got $rc")
    [ -s "$T/err" ] || WHY+=("no message on stderr")
    [ -s "$T/out" ] && WHY+=("stdout not empty: $(head -c 200 "$T/out")")
    finish "usage: $name"
}
usage_case "no command"
usage_case "unknown command" frobnicate
usage_case "solve without a model" solve
usage_case "solve --json without a model" solve --json
usage_case "two models" solve "$EX" "$EX"
usage_case "unknown option" solve --bogus "$EX"
usage_case "-o without a directory" solve "$EX" -o

for h in help --help -h; do
    "$BIN" "$h" >"$T/out" 2>"$T/err"
    rc=$?
    [ "$rc" = 0 ] || WHY+=("exit $rc")
    grep -q 'exit codes' "$T/out" || WHY+=("no usage text on stdout")
    finish "catena $h"
done

# ---- output that cannot be written: exit 4 and a message, never a silent success ------
# io_case NAME PATTERN: the last run (stderr in $T/err, exit code in $rc) exited 4 with a
# message matching PATTERN.
io_case() {
    [ "$rc" = 4 ] || WHY+=("expected exit 4, got $rc")
    grep -qE "^catena: .*$2" "$T/err" || WHY+=("no message matching '$2' on stderr: $(head -c 300 "$T/err")")
    finish "write error: $1"
}
if [ -w /dev/full ]; then
    "$BIN" solve "$EX" --json >/dev/full 2>"$T/err"; rc=$?
    io_case "--json > /dev/full" 'stdout: write error: No space left on device'
    "$BIN" solve "$EX" >/dev/full 2>"$T/err"; rc=$?
    io_case "summary > /dev/full" 'stdout: write error: No space left on device'
    "$BIN" compare "$EX" --json >/dev/full 2>"$T/err"; rc=$?
    io_case "compare --json > /dev/full" 'stdout: write error: No space left on device'
    "$BIN" help >/dev/full 2>"$T/err"; rc=$?
    io_case "help > /dev/full" 'stdout: write error: No space left on device'
fi
# -o into a directory that cannot be made (its parent is a file; works as root too).
: >"$T/plainfile"
"$BIN" solve "$EX" -q -o "$T/plainfile/out" >"$T/out" 2>"$T/err"; rc=$?
io_case "-o below a regular file" 'plainfile/out: cannot create directory: Not a directory'
# -o into a read-only directory (not as root: root writes there anyway).
if [ "$(id -u)" != 0 ]; then
    mkdir -p "$T/readonly" && chmod 555 "$T/readonly"
    "$BIN" solve "$EX" -q -o "$T/readonly" >"$T/out" 2>"$T/err"; rc=$?
    io_case "-o into a read-only directory" 'readonly/result.json: cannot create: Permission denied'
    [ -z "$(ls -A "$T/readonly")" ] || { WHY+=("files left: $(ls -A "$T/readonly")"); finish "read-only directory left empty"; }
    chmod 755 "$T/readonly"
fi
# -o when the disk fills up mid-way (file size limit of 4 KiB, SIGXFSZ ignored): exit 4,
# the older set untouched, no temporary left.
dir=$T/fsize
"$BIN" solve examples/robust/net_slack.cable -q -o "$dir" >/dev/null 2>&1
cp "$dir/result.json" "$T/fsize_before.json" 2>/dev/null
(ulimit -f 4; trap '' XFSZ; exec "$BIN" solve "$EX" -q -o "$dir") >"$T/out" 2>"$T/err"; rc=$?
io_case "-o with the file size limit hit" 'result.json: write failed: File too large'
extra=$(ls -A "$dir" | grep -vxE 'result\.json|nodes\.csv|elements\.csv|result\.vtu')
[ -z "$extra" ] || WHY+=("files left: $extra")
cmp -s "$dir/result.json" "$T/fsize_before.json" || WHY+=("the older result.json was replaced")
finish "-o with the file size limit hit: the older set kept"

cli_summary
