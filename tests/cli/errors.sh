#!/usr/bin/env bash
# tests/cli/errors.sh CATENA: the malformed-input corpus.
#
# Every tests/errors/*.cable starts with a header line
#     # expect: CODE: SUBSTRING
# CODE is the exit code of `catena solve FILE` (0 converged, 2 bad model, 3 not converged,
# 4 I/O); SUBSTRING must occur in its stderr. The word FILE in SUBSTRING stands for the
# path given to catena, so "FILE:7: unknown directive" demands the `file:line:` prefix
# with line 7. " ... " splits SUBSTRING into pieces that must each occur (in any order),
# for messages whose exact wording is open: "FILE:7: ... 100000". An empty SUBSTRING
# (CODE 0) demands an empty stderr.
#
# Each case is run four ways and must give the same exit code every time:
#   plain       exit code, message (bounded in length, starting "catena: ");
#   --json      exit 0/3: stdout is valid JSON with "converged" true/false;
#               exit 2/4: stdout empty;
#   -q -o DIR   no temporary or partial file left in DIR; exit 2/4: DIR holds nothing;
#               exit 0: result.json (valid, "converged": true), nodes.csv, elements.csv,
#               result.vtu (and result.pvd with result_K.vtu for several steps);
#               exit 3: those files (result.json with "converged": false) or none;
#   CRLF        the same file with DOS line endings: same code, same message and line;
#   CR          the same file with old Mac line endings (a lone CR): likewise.
# Hostile inputs that cannot be committed (empty, binary, huge lines, directories,
# missing files) are generated into a temporary directory below.
# The plain build runs each as a process; a sanitizer build runs them all in one process
# (tests/corpus_runner.c, the command's own code once per run, a leak check after each:
# crun in lib/common.sh), where a process start and exit-time leak check cost ~0.1 s.
#
# ctest-shards: 4
# ctest-cost: 40 (about the seconds of one shard: ctest -j starts them first)
# Shards: `errors.sh CATENA K/N` runs the cases whose name hashes to K of N (ctest runs
# cli_errors_1 .. cli_errors_N side by side, see CMakeLists.txt); without K/N, every case.
# The JSON documents of a run are checked together by one python3 at the end; each case
# is then counted and reported (FAIL NAME, MODE: what failed) in the order it ran.
#
# Run from the repository root (ctest does). Prints "N passed, N failed"; exit 1 on any
# failure.
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init errors "${1:-}"
[ -d tests/errors ] || { echo "errors.sh: no tests/errors directory" >&2; exit 1; }
cli_shard errors "${2:-}" || exit 1

# mine NAME: the case NAME belongs to this shard (a hash of its name, modulo N).
mine() {
    local s=$1 h=5381 i c
    [ "$SHARD_N" = 1 ] && return 0
    for ((i = 0; i < ${#s}; i++)); do
        printf -v c '%d' "'${s:i:1}"
        h=$(((h * 33 + c) % 1000003))
    done
    [ $((h % SHARD_N + 1)) = "$SHARD_K" ]
}

# Cases are counted at the end, after the JSON checks: case_done NAME keeps the case's
# WHY in $T/why/INDEX; json_check records a document for the one python3 run.
CASES=()
mkdir -p "$T/why" "$T/json" "$T/outdir"
: >"$T/json_checks"
case_done() {
    case_stderr
    [ ${#WHY[@]} -eq 0 ] || printf '%s\0' "${WHY[@]}" >"$T/why/${#CASES[@]}"
    CASES+=("$1")
    WHY=()
}

# json_converged FILE WANT: FILE is valid JSON with "converged": WANT (true|false).
json_converged() {
    if [ "$have_python" = 1 ]; then
        python3 -m json.tool "$1" >/dev/null 2>&1 || return 1
        python3 - "$1" "$2" <<'EOF' 2>/dev/null
import json, sys
d = json.load(open(sys.argv[1]))
sys.exit(0 if d.get("converged") is (sys.argv[2] == "true") and isinstance(d.get("reason"), str) else 1)
EOF
        return
    fi
    # Minimal check: an object from first to last byte, with the converged key.
    local first last
    first=$(tr -d ' \t\r\n' <"$1" | head -c 1)
    last=$(tr -d ' \t\r\n' <"$1" | tail -c 1)
    [ "$first" = "{" ] && [ "$last" = "}" ] &&
        tr -d ' \t\r\n' <"$1" | grep -q "\"converged\":$2"
}

# json_check FILE WANT MESSAGE: FILE must be valid JSON with "converged": WANT, else the
# current case fails with MESSAGE; with python3, checked at the end (check_all_json).
json_check() {
    if [ "$have_python" = 1 ]; then
        printf '%s\t%s\t%s\t%s\n' "${#CASES[@]}" "$1" "$2" "$3" >>"$T/json_checks"
    else
        json_converged "$1" "$2" || WHY+=("$3")
    fi
}

# check_all_json: one python3 for every recorded document; a failure joins its case's WHY.
check_all_json() {
    [ -s "$T/json_checks" ] || return 0
    local out i msg
    out=$(python3 - "$T/json_checks" 2>&1 <<'EOF'
import json, sys
for line in open(sys.argv[1], encoding="utf-8"):
    index, path, want, msg = line.rstrip("\n").split("\t", 3)
    try:
        d = json.load(open(path))
        ok = d.get("converged") is (want == "true") and isinstance(d.get("reason"), str)
    except Exception:
        ok = False
    if not ok:
        print(index + "\t" + msg)
EOF
    ) || { WHY+=("the JSON checker failed: $out"); case_done json_checker; return; }
    while IFS=$'\t' read -r i msg; do
        [ -n "$i" ] && printf '%s\0' "$msg" >>"$T/why/$i"
    done <<<"$out"
}

# describe RC: "exit RC" plus a hint for signals.
describe() {
    if [ "$1" -ge 128 ]; then echo "exit $1 (killed by signal $(($1 - 128)): a crash)"; else echo "exit $1"; fi
}

# sanitizer_report ERRFILE MODE: a sanitizer finding is always a failure. The stderr
# files of a case (one per mode) are searched together when it is done (case_stderr).
ERRS=()
LONG=()
sanitizer_report() {
    ERRS+=("$1" "$2")
}

# case_stderr: the sanitizer search of sanitizer_report, and each message of check_plain
# bounded to 2048 bytes, for all modes of the case in one grep and one find.
case_stderr() {
    local files=() i f len
    for ((i = 0; i < ${#ERRS[@]}; i += 2)); do files+=("${ERRS[i]}"); done
    if [ ${#files[@]} -gt 0 ]; then
        local hits
        hits=$(grep -lE 'AddressSanitizer|LeakSanitizer|runtime error:|UndefinedBehaviorSanitizer' "${files[@]}")
        for ((i = 0; i < ${#ERRS[@]}; i += 2)); do
            f=${ERRS[i]}
            [[ $'\n'$hits$'\n' == *$'\n'"$f"$'\n'* ]] &&
                WHY+=("${ERRS[i + 1]}: sanitizer report: $(grep -m1 -E 'Sanitizer|runtime error' "$f")")
        done
    fi
    if [ ${#LONG[@]} -gt 0 ]; then
        while IFS= read -r f; do
            [ -n "$f" ] || continue
            len=$(wc -c <"$f")
            WHY+=("${f##*/err.}: message of $len bytes (hostile input echoed unbounded?)")
        done <<<"$(find "${LONG[@]}" -maxdepth 0 -size +2048c)"
    fi
    ERRS=()
    LONG=()
}

# check_plain PATH CODE SUBSTRING MODE
check_plain() {
    local path=$1 code=$2 want=$3 mode=$4 rc err=$T/err.$4
    crun "$T/out" "$err" solve "$path"
    rc=$RC
    sanitizer_report "$err" "$mode"
    if [ "$rc" != "$code" ]; then
        WHY+=("$mode: expected exit $code, got $(describe "$rc"); stderr: $(head -c 300 "$err")")
        return
    fi
    if [ -z "$want" ]; then
        [ -s "$err" ] && WHY+=("$mode: expected an empty stderr, got: $(head -c 300 "$err")")
    else
        local rest=$want piece
        while [ -n "$rest" ]; do
            piece=${rest%% ... *}
            if [ "$piece" = "$rest" ]; then rest=; else rest=${rest#* ... }; fi
            grep -qF -- "$piece" "$err" ||
                WHY+=("$mode: stderr lacks '$piece'; it is: $(head -c 300 "$err")")
        done
        local start=
        [ "$code" = 0 ] || { LC_ALL=C IFS= read -r -d '' -n 8 start <"$err"; [ "$start" = "catena: " ]; } ||
            WHY+=("$mode: the message does not start with 'catena: '")
    fi
    LONG+=("$err")                                  # at most 2048 bytes (case_stderr)
}

# check_json PATH CODE
check_json() {
    local path=$1 code=$2 rc
    local out=$T/json/${#CASES[@]}.json
    crun "$out" "$T/err.json" solve "$path" --json
    rc=$RC
    sanitizer_report "$T/err.json" "--json"
    [ "$rc" = "$code" ] ||
        WHY+=("--json: expected exit $code, got $(describe "$rc"); stderr: $(head -c 300 "$T/err.json")")
    case $code in
        0) json_check "$out" true "--json: stdout is not valid JSON with \"converged\": true" ;;
        3) json_check "$out" false "--json: stdout is not valid JSON with \"converged\": false ($(wc -c <"$out") bytes)" ;;
        *) [ -s "$out" ] && WHY+=("--json: stdout not empty on exit $code: $(head -c 200 "$out")") ;;
    esac
}

# check_outdir PATH CODE NAME
check_outdir() {
    local path=$1 code=$2 dir=$T/outdir/$3 rc
    crun /dev/null "$T/err.o" solve "$path" -q -o "$dir"
    rc=$RC
    sanitizer_report "$T/err.o" "-o"
    [ "$rc" = "$code" ] ||
        WHY+=("-o: expected exit $code, got $(describe "$rc"); stderr: $(head -c 300 "$T/err.o")")
    if [ -d "$dir" ]; then
        local stray
        stray=$(find "$dir" -mindepth 1 ! -name result.json ! -name nodes.csv ! -name elements.csv \
                     ! -name modes.csv ! -name result.vtu ! -name result.pvd ! -name 'result_[0-9]*.vtu' | head -3)
        [ -z "$stray" ] && stray=$(find "$dir" -mindepth 1 -name '*tmp*' | head -3)
        [ -n "$stray" ] && WHY+=("-o: stray (temporary or partial) files: $stray")
    fi
    case $code in
        0|3)
            local want=true f n=0
            [ "$code" = 3 ] && want=false
            for f in result.json nodes.csv elements.csv result.vtu; do
                [ -s "$dir/$f" ] && n=$((n + 1))
            done
            if [ "$code" = 0 ] || [ "$n" != 0 ]; then     # exit 3 may write all or nothing
                [ "$n" = 4 ] || WHY+=("-o: expected result.json, nodes.csv, elements.csv, result.vtu; found: $(ls -A "$dir" 2>/dev/null | tr '\n' ' ')")
            fi
            [ -s "$dir/result.json" ] &&
                json_check "$dir/result.json" "$want" "-o: result.json is not valid JSON with \"converged\": $want"
            [ -s "$dir/nodes.csv" ] && { head -n 1 "$dir/nodes.csv" | grep -q '^id,x,y,z,ux,uy,uz,fix,rx,ry,rz' ||
                WHY+=("-o: nodes.csv header"); }
            [ -s "$dir/elements.csv" ] && { head -n 1 "$dir/elements.csv" | grep -q '^id,node1,node2,l0,length,strain,force,stress' ||
                WHY+=("-o: elements.csv header"); }
            ;;
        *)
            if [ -d "$dir" ] && [ -n "$(ls -A "$dir")" ]; then
                WHY+=("-o: files written on exit $code: $(ls -A "$dir" | tr '\n' ' ')")
            fi
            ;;
    esac
}


# run_case NAME PATH CODE SUBSTRING [all]: plain (+ --json and -o with "all"), if the
# case is this shard's.
run_case() {
    local name=$1 path=$2 code=$3 want=${4//FILE/$2}
    mine "$name" || return 0
    check_plain "$path" "$code" "$want" plain
    if [ "${5:-}" = all ]; then
        check_json "$path" "$code"
        check_outdir "$path" "$code" "$name"
    fi
    case_done "$name"
}

# ---- the committed corpus -------------------------------------------------------------
# Every file in every mode, and its CRLF and CR-only copies. A sanitizer build runs them
# in one process (tests/corpus_runner.c through crun, lib/common.sh): a sanitized process
# start and leak check cost ~0.1 s, and the corpus is ~1500 runs.
cli_runner_start
mkdir -p "$T/crlf" "$T/cr"
ncorpus=0
for f in tests/errors/*.cable; do
    name=${f##*/}
    name=${name%.cable}
    ncorpus=$((ncorpus + 1))
    mine "$name" || continue
    header=
    IFS= read -r header <"$f"
    header=${header//$'\r'/}
    if ! [[ $header =~ ^#\ expect:\ ([0-9]+):\ ?(.*)$ ]]; then
        WHY+=("corpus: first line is not '# expect: CODE: SUBSTRING': $header")
        case_done "$name"
        continue
    fi
    code=${BASH_REMATCH[1]}
    want=${BASH_REMATCH[2]}
    # The corpus itself: a FILE:N: expectation must point at a directive line.
    if [[ $want =~ FILE:([0-9]+): ]]; then
        n=${BASH_REMATCH[1]}
        line=()
        mapfile -t -s $((n - 1)) -n 1 line <"$f"
        line=${line[0]:-}
        line=${line//$'\r'/}
        line=${line%%#*}
        line=${line//[[:space:]]/}
        [ -n "$line" ] || WHY+=("corpus: line $n of $f is blank or a comment")
    fi
    check_plain "$f" "$code" "${want//FILE/$f}" plain
    check_json "$f" "$code"
    check_outdir "$f" "$code" "$name"
    # The same model with CRLF line endings.
    c=$T/crlf/$name.cable
    sed 's/\r*$/\r/' "$f" >"$c"
    check_plain "$c" "$code" "${want//FILE/$c}" CRLF
    # ... and with CR-only line endings.
    c=$T/cr/$name.cable
    sed 's/\r*$//' "$f" | tr '\n' '\r' >"$c"
    check_plain "$c" "$code" "${want//FILE/$c}" CR
    case_done "$name"
done
if mine corpus_size && [ "$ncorpus" -lt 45 ]; then
    WHY+=("only $ncorpus corpus files (at least 45 expected)")
    case_done corpus_size
fi

# The committed CRLF case must really have CRLF endings (an editor or git may strip them).
if mine ok_crlf_has_cr; then
    if ! grep -q $'\r$' tests/errors/ok_crlf.cable; then
        WHY+=("tests/errors/ok_crlf.cable lost its CRLF line endings")
    fi
    case_done ok_crlf_has_cr
fi

# ---- generated hostile inputs ---------------------------------------------------------
# (every shard writes them, a few MB; each runs in its own shard)
G=$T/gen
mkdir -p "$G"
PAPER='units kN m
material steel E=2.0e8
section strand material=steel A=3.14e-4 w=0.1
gravity 0 -1 0
node 1 0 0 0 fix=xyz
node 2 200 0 0 fix=xyz
cable 1 2 section=strand n=20 length=200.3340'

# Repeat character $1 $2 times.
rep() { head -c "$2" /dev/zero | tr '\0' "$1"; }

: >"$G/empty.cable"
run_case gen_empty_file "$G/empty.cable" 2 "FILE: the model has no elements" all

run_case gen_dev_null /dev/null 2 "FILE: the model has no elements"

printf '\000\001\002\003garbage\377\376\n' >"$G/nul_line1.cable"
run_case gen_binary_nul_line1 "$G/nul_line1.cable" 2 "FILE:1: binary data (a NUL byte)" all

printf 'units kN m\nmaterial steel E=2.0e8\n\nnode 1 0\0000 0\n' >"$G/nul_line4.cable"
run_case gen_binary_nul_line4 "$G/nul_line4.cable" 2 "FILE:4: binary data (a NUL byte)" all

printf '\177ELF\002\001\001\003 \377\376\375\n\211PNG\r\n\032\n' >"$G/elf.cable"
run_case gen_binary_no_nul "$G/elf.cable" 2 "FILE:1: unknown directive '\\x7fELF" all

# 4 KiB of deterministic pseudo-random bytes (a linear congruential generator).
seed=12345
esc=''
for ((i = 0; i < 4096; i++)); do
    seed=$(((seed * 1103515245 + 12345) % 2147483648))
    printf -v byte '\\%03o' $(((seed >> 16) & 255))
    esc+=$byte
done
printf "$esc" >"$G/random.cable"
run_case gen_binary_random "$G/random.cable" 2 "FILE:" all

{ printf '\357\273\277'; printf '%s\n' "$PAPER"; } >"$G/bom.cable"
run_case gen_utf8_bom "$G/bom.cable" 0 "" all
{ printf 'units kN m\n\357\273\277gravity 0 -1 0\n'; } >"$G/bom_later.cable"
run_case gen_utf8_bom_not_first "$G/bom_later.cable" 2 "FILE:2: unknown directive" all

{ echo "units kN m"; printf '# '; rep a 1048576; printf '\nbogus 1\n'; } >"$G/long_comment.cable"
run_case gen_long_comment_then_error "$G/long_comment.cable" 2 "FILE:3: unknown directive 'bogus'" all

{ echo "units kN m"; rep a 1048576; echo; } >"$G/long_directive.cable"
run_case gen_long_directive "$G/long_directive.cable" 2 "FILE:2: unknown directive 'aaaaaaaaaa" all

{ printf 'node 1 0 0 '; rep 1 100000; echo; } >"$G/long_number.cable"
run_case gen_long_number "$G/long_number.cable" 2 "FILE:1: non-finite number for a coordinate" all

{ printf 'material '; rep m 100000; echo " E=1"; } >"$G/long_name.cable"
run_case gen_long_name "$G/long_name.cable" 2 "FILE:1: material name longer than 63 characters" all

{ printf 'node 1 0 0 0 '; rep k 1048576; echo "=1"; } >"$G/long_key.cable"
run_case gen_long_key "$G/long_key.cable" 2 "FILE:1: unknown key 'kkkkkkkkkk" all

{ printf '%s\n' "$PAPER" | sed 's/section=strand/section='"$(rep s 100000)"'/'; } >"$G/long_value.cable"
run_case gen_long_section_reference "$G/long_value.cable" 2 "FILE:7: cable: undefined section 'sssssssss" all

{ rep '\n' 1000000; echo "bogus"; } >"$G/many_lines.cable"
run_case gen_million_blank_lines "$G/many_lines.cable" 2 "FILE:1000001: unknown directive 'bogus'" all

{ printf '%s\n' "$PAPER"; printf '# '; rep c 1048576; echo; } >"$G/ok_long_comment.cable"
run_case gen_ok_long_trailing_comment "$G/ok_long_comment.cable" 0 "" all

printf '%s' "$PAPER" >"$G/ok_no_final_newline.cable"
run_case gen_ok_no_final_newline "$G/ok_no_final_newline.cable" 0 "" all

{ printf '%s\n' "$PAPER"; printf 'frobnicate\n'; } | sed 's/$/\r/' >"$G/crlf_error.cable"
run_case gen_crlf_error_line "$G/crlf_error.cable" 2 "FILE:8: unknown directive 'frobnicate'" all

{ printf '%s\n' "$PAPER"; printf 'frobnicate\n'; } | tr '\n' '\r' >"$G/cr_error.cable"
run_case gen_cr_error_line "$G/cr_error.cable" 2 "FILE:8: unknown directive 'frobnicate'" all

# An error on line 5 of a CR-only file, after a blank line and a comment line.
printf 'units kN m\r\r# a comment\rmaterial steel E=2.0e8\rbogus 5\r' >"$G/cr_line5.cable"
run_case gen_cr_error_line5 "$G/cr_line5.cable" 2 "FILE:5: unknown directive 'bogus'" all

# CR, LF and CRLF line ends mixed in one file: each ends one line.
printf 'units kN m\rmaterial steel E=2.0e8\r\nsection s material=steel A=1\n\r\rbogus 6\n' >"$G/mixed_ends.cable"
run_case gen_mixed_line_ends "$G/mixed_ends.cable" 2 "FILE:6: unknown directive 'bogus'" all

# A CR-only copy of a model solves to the same answer (same JSON, byte for byte).
printf '%s\n' "$PAPER" >"$G/lf.cable"
printf '%s\n' "$PAPER" | tr '\n' '\r' >"$G/cr.cable"
if mine gen_cr_only_same_answer; then
    "$BIN" solve "$G/lf.cable" --json >"$T/lf.json" 2>"$T/err" || WHY+=("LF copy: exit $?: $(head -c 300 "$T/err")")
    "$BIN" solve "$G/cr.cable" --json >"$T/cr.json" 2>"$T/err" || WHY+=("CR copy: exit $?: $(head -c 300 "$T/err")")
    cmp -s "$T/lf.json" "$T/cr.json" || WHY+=("the CR-only copy gives another answer than the LF file")
    grep -q '"converged":[[:space:]]*true' "$T/cr.json" || WHY+=("the CR-only copy did not converge")
    case_done gen_cr_only_same_answer
fi

mkdir -p "$G/a_directory.cable"
run_case gen_directory_as_model "$G/a_directory.cable" 4 "FILE: " all

run_case gen_missing_file "$G/no_such_file.cable" 4 "FILE: cannot open" all

# ---- output that cannot be written: exit 4 and nothing half-written -------------------
printf '%s\n' "$PAPER" >"$G/paper.cable"
if mine gen_output_blocked; then
    dir=$T/blocked
    mkdir -p "$dir/elements.csv"                   # a directory where a file must go
    "$BIN" solve "$G/paper.cable" -q -o "$dir" >/dev/null 2>"$T/err"
    rc=$?
    [ "$rc" = 4 ] || WHY+=("expected exit 4 when elements.csv cannot be written, got $(describe "$rc")")
    grep -qF "elements.csv" "$T/err" || WHY+=("the message does not name elements.csv: $(cat "$T/err")")
    stray=$(find "$dir" -mindepth 1 -name '*tmp*')
    [ -z "$stray" ] || WHY+=("temporary files left behind: $stray")
    [ -e "$dir/result.json" ] && WHY+=("result.json written although elements.csv failed")
    case_done gen_output_blocked
fi

if mine gen_output_under_file; then
    touch "$T/plainfile"
    "$BIN" solve "$G/paper.cable" -q -o "$T/plainfile/sub" >/dev/null 2>"$T/err"
    rc=$?
    [ "$rc" = 4 ] || WHY+=("expected exit 4 for an output directory under a regular file, got $(describe "$rc")")
    grep -qF "$T/plainfile/sub" "$T/err" || WHY+=("the message does not name the directory: $(cat "$T/err")")
    case_done gen_output_under_file
fi

# ---- the runner's own end (a leak found at its exit), the JSON documents, then every
# case in the order it ran ----------------------------------------------------------------
cli_runner_stop || { rc=$?; WHY+=("the in-process runner (tests/corpus_runner.c) exited with $(describe "$rc")"); case_done corpus_runner; }
check_all_json
for i in "${!CASES[@]}"; do
    WHY=()
    [ -f "$T/why/$i" ] && mapfile -d '' WHY <"$T/why/$i"
    finish "${CASES[i]}"
done
cli_summary
