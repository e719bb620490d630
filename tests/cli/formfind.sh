#!/usr/bin/env bash
# tests/cli/formfind.sh CATENA: `catena formfind`.
#
#   - the malformed-input corpus of form finding, tests/errors/formfind/*.cable (headers
#     as in tests/errors: "# expect: CODE: SUBSTRING"; "(args: ...)" on the second line
#     gives extra options), each run as written, with CRLF and with CR line ends: the
#     same code and message, and OUT neither written nor left half-written (an older OUT
#     stays as it was);
#   - the example net: found, written, and `catena solve OUT` stays put (|u| <= 1e-10 m)
#     with the forces q l; the written file is the committed examples/formfind/
#     hypar_net.found.cable to 1e-9 (a regression test);
#   - the ```cable-formfind blocks of docs/format.md: found, and the found model solved;
#   - usage errors (exit 1), an output that cannot be written (exit 4), --help, and the
#     note of `catena solve` on a model with q=.
# ctest-cost: 40 (about the seconds it takes under ASan: ctest -j starts it early)
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init formfind "${1:-}"

# check_case PATH CODE SUBSTRING ARGS MODE
check_case() {
    local path=$1 code=$2 want=$3 args=$4 mode=$5 rc
    printf 'older\n' >"$T/out.cable"
    # shellcheck disable=SC2086
    "$BIN" formfind "$path" -q -o "$T/out.cable" $args >"$T/stdout" 2>"$T/err"
    rc=$?
    [ "$rc" = "$code" ] || WHY+=("$mode: expected exit $code, got $rc; stderr: $(head -c 300 "$T/err")")
    local rest=$want piece
    while [ -n "$rest" ]; do
        piece=${rest%% ... *}
        if [ "$piece" = "$rest" ]; then rest=; else rest=${rest#* ... }; fi
        grep -qF -- "$piece" "$T/err" || WHY+=("$mode: stderr lacks '$piece'; it is: $(head -c 300 "$T/err")")
    done
    head -c 8 "$T/err" | grep -q '^catena: ' || WHY+=("$mode: the message does not start with 'catena: '")
    [ "$(cat "$T/out.cable")" = older ] || WHY+=("$mode: OUT was replaced on exit $rc")
    [ -z "$(find "$T" -maxdepth 1 -name 'out.cable.tmp*')" ] || WHY+=("$mode: a temporary file was left")
    [ -s "$T/stdout" ] && WHY+=("$mode: -q printed on stdout")
}

mkdir -p "$T/crlf" "$T/cr"
for f in tests/errors/formfind/*.cable; do
    name=$(basename "$f" .cable)
    header=$(head -n 1 "$f")
    if ! [[ $header =~ ^#\ expect:\ ([0-9]+):\ ?(.*)$ ]]; then
        WHY+=("corpus: first line is not '# expect: CODE: SUBSTRING': $header")
        finish "$name"
        continue
    fi
    code=${BASH_REMATCH[1]}
    want=${BASH_REMATCH[2]}
    args=$(sed -n '2s/.*(args: \(.*\)).*/\1/p' "$f")
    check_case "$f" "$code" "${want//FILE/$f}" "$args" plain
    c=$T/crlf/$name.cable
    sed 's/$/\r/' "$f" >"$c"
    check_case "$c" "$code" "${want//FILE/$c}" "$args" CRLF
    c=$T/cr/$name.cable
    tr '\n' '\r' <"$f" >"$c"
    check_case "$c" "$code" "${want//FILE/$c}" "$args" CR
    finish "formfind_$name"
done

# ---- the example: found, written, solved where it is --------------------------------
ex=examples/formfind/hypar_net.cable
"$BIN" formfind "$ex" -o "$T/net.cable" >"$T/log" 2>"$T/err" || WHY+=("formfind $ex: exit $?: $(cat "$T/err")")
grep -q "^found in .* iterations, 1 factorization" "$T/log" || WHY+=("no summary line: $(tail -3 "$T/log")")
grep -q "^written: $T/net.cable" "$T/log" || WHY+=("the summary does not say where it wrote")
"$BIN" solve "$T/net.cable" --json >"$T/net.json" 2>"$T/err" || WHY+=("solve OUT: exit $?: $(cat "$T/err")")
[ -s "$T/err" ] && WHY+=("solve OUT printed on stderr: $(head -c 300 "$T/err")")
if [ "$have_python" = 1 ]; then
    python3 - "$T/net.json" "$ex" "$T/net.cable" examples/formfind/hypar_net.found.cable <<'PY' || WHY+=("the found net: see above")
import json, math, re, sys
d = json.load(open(sys.argv[1]))
u = max(abs(n[k]) for n in d["nodes"] for k in ("ux", "uy", "uz"))
ok = d["converged"] and u <= 1e-10
# forces q l: q from the source, l from the found file's coordinates
q = {int(m.group(1)): float(m.group(2)) for m in re.finditer(r"^element (\d+) .*q=(\S+)", open(sys.argv[2]).read(), re.M)}
xyz = {}
for path in (sys.argv[3], sys.argv[4]):
    xyz[path] = {int(m.group(1)): tuple(map(float, m.group(2, 3, 4)))
                 for m in re.finditer(r"^node (\d+) (\S+) (\S+) (\S+)", open(path).read(), re.M)}
pos = xyz[sys.argv[3]]
worst = 0
for e in d["elements"]:
    a, b = (pos[i] for i in e["nodes"])
    worst = max(worst, abs(e["force"] - q[e["id"]] * math.dist(a, b)) / e["force"])
ok = ok and worst <= 1e-10
far = max(math.dist(pos[i], xyz[sys.argv[4]][i]) for i in pos)
ok = ok and far <= 1e-9 and len(pos) == len(xyz[sys.argv[4]])
if not ok: print("max |u| %g m, force mismatch %g, %g m from the committed found model" % (u, worst, far))
sys.exit(0 if ok else 1)
PY
fi
finish example_found_stays_put

# ---- the form-finding examples of docs/format.md (```cable-formfind blocks) -------------
awk -v dir="$T" '
    /^```cable-formfind[[:space:]]*$/ { n++; f = sprintf("%s/docff_%02d.cable", dir, n); inblk = 1; next }
    /^```/ && inblk { inblk = 0; close(f); next }
    inblk { print > f }
    END { print n + 0 > (dir "/docff_count") }' docs/format.md
[ "$(cat "$T/docff_count")" -ge 2 ] || WHY+=("fewer than 2 form-finding examples in docs/format.md")
for f in "$T"/docff_*.cable; do
    [ -e "$f" ] || continue
    "$BIN" formfind "$f" -q -o "$f.found" 2>"$T/err" || WHY+=("$(basename "$f"): formfind exit $?: $(cat "$T/err")")
    "$BIN" solve "$f.found" -q 2>"$T/err" || WHY+=("$(basename "$f"): solve of the found model: exit $?: $(cat "$T/err")")
done
finish docs_format_examples

# ---- the command line ------------------------------------------------------------------
"$BIN" formfind --help >"$T/help" 2>&1 && grep -q "^usage: catena formfind MODEL" "$T/help" && grep -q "force / l" "$T/help" ||
    WHY+=("--help: $(head -3 "$T/help")")
"$BIN" help | grep -q "^  formfind" || WHY+=("catena help does not list formfind")
finish help

"$BIN" formfind >/dev/null 2>&1; [ $? = 1 ] || WHY+=("no model: not exit 1")
"$BIN" formfind "$ex" --tol 0 >/dev/null 2>&1; [ $? = 1 ] || WHY+=("--tol 0: not exit 1")
"$BIN" formfind "$ex" --maxit 1.5 >/dev/null 2>&1; [ $? = 1 ] || WHY+=("--maxit 1.5: not exit 1")
"$BIN" formfind "$ex" --bogus >/dev/null 2>&1; [ $? = 1 ] || WHY+=("--bogus: not exit 1")
"$BIN" formfind "$ex" "$ex" >/dev/null 2>&1; [ $? = 1 ] || WHY+=("two models: not exit 1")
finish usage

"$BIN" formfind "$ex" -q -o "$T/no/such/dir/out.cable" >/dev/null 2>"$T/err"
rc=$?
[ "$rc" = 4 ] || WHY+=("an output in a missing directory: exit $rc, not 4")
grep -qF "$T/no/such/dir/out.cable" "$T/err" || WHY+=("the message does not name the output: $(cat "$T/err")")
"$BIN" formfind "$T/missing.cable" -q >/dev/null 2>"$T/err"
[ $? = 4 ] || WHY+=("a missing model: not exit 4")
finish io_errors

"$BIN" formfind "$ex" -q >"$T/out" 2>"$T/err" || WHY+=("without -o: exit $?")
[ -s "$T/out" ] || [ -s "$T/err" ] && WHY+=("-q without -o printed something")
"$BIN" solve "$ex" -q 2>"$T/err"
grep -q "note: 624 members carry q= or force=, which only \`catena formfind\` uses" "$T/err" ||
    WHY+=("catena solve of a q= model does not say it ignores q=: $(cat "$T/err")")
finish solve_note

cli_summary
