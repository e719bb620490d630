#!/usr/bin/env bash
# tests/cli/outputs.sh CATENA: what catena may and may not replace when it writes, and an
# exit code that does not depend on the output mode.
#   - `formfind -o` onto the model it reads, onto a device, through a dangling link: exit
#     4, a message naming the path, the file (or device) untouched;
#   - `formfind -o LINK`: written through the link (the link stays a link);
#   - `solve -o DIR` where DIR/result.json is a link to the model: exit 4, model untouched,
#     nothing staged left;
#   - a load of 1e300: exit 3 with the summary, with --json and with -o alike;
#   - SIGINT or SIGTERM at several moments of a solve writing -o DIR over an older set:
#     exit 130 / 143 with the older set whole, or 0 with the new set whole; never a
#     temporary left, never a mix.
# Prints "N passed, N failed"; exit 1 on any failure.
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init outputs "${1:-}"

cp examples/formfind/hypar_net.cable "$T/net.cable"
sum0=$(cksum <"$T/net.cable")

# expect_refusal CASE PATH SUBSTRING: the last run exited 4 and named PATH with SUBSTRING.
expect_refusal() {
    [ "$rc" -eq 4 ] || WHY+=("exit $rc, expected 4")
    grep -qF "$2: $3" "$T/err" || WHY+=("stderr lacks '$2: $3': $(cat "$T/err")")
    [ "$(cksum <"$T/net.cable")" = "$sum0" ] || WHY+=("the model file changed")
    ls "$T" "$T/out" 2>/dev/null | grep -q '\.tmp\.' && WHY+=("a staging file was left")
    finish "$1"
}

"$BIN" formfind "$T/net.cable" -o "$T/net.cable" >/dev/null 2>"$T/err"; rc=$?
expect_refusal formfind_onto_its_model "$T/net.cable" "is the input being read"

ln "$T/net.cable" "$T/hard.cable"
"$BIN" formfind "$T/hard.cable" -o "$T/net.cable" >/dev/null 2>"$T/err"; rc=$?
expect_refusal formfind_onto_a_hard_link_of_its_model "$T/net.cable" "is the input being read"

if mknod "$T/dev" c 1 3 2>/dev/null; then
    "$BIN" formfind "$T/net.cable" -o "$T/dev" >/dev/null 2>"$T/err"; rc=$?
    [ -c "$T/dev" ] || WHY+=("the device was replaced")
    expect_refusal formfind_onto_a_device "$T/dev" "not a regular file"
fi
mkfifo "$T/fifo"
"$BIN" formfind "$T/net.cable" -o "$T/fifo" >/dev/null 2>"$T/err"; rc=$?
[ -p "$T/fifo" ] || WHY+=("the pipe was replaced")
expect_refusal formfind_onto_a_pipe "$T/fifo" "not a regular file"

ln -s "$T/nowhere/x.cable" "$T/dangling.cable"
"$BIN" formfind "$T/net.cable" -o "$T/dangling.cable" >/dev/null 2>"$T/err"; rc=$?
expect_refusal formfind_through_a_dangling_link "$T/dangling.cable" "a symbolic link to a missing file"

echo old >"$T/found.cable"
ln -s found.cable "$T/link.cable"
"$BIN" formfind "$T/net.cable" -o "$T/link.cable" >/dev/null 2>"$T/err"; rc=$?
[ "$rc" -eq 0 ] || WHY+=("exit $rc: $(cat "$T/err")")
[ -L "$T/link.cable" ] || WHY+=("the link was replaced by a file")
grep -q '^# catena formfind' "$T/found.cable" || WHY+=("the link's target does not hold the found model")
finish formfind_through_a_link

mkdir "$T/out"
ln -s ../net.cable "$T/out/result.json"
"$BIN" solve "$T/net.cable" -q -o "$T/out" 2>"$T/err"; rc=$?
[ -L "$T/out/result.json" ] || WHY+=("the link was replaced")
[ -e "$T/out/nodes.csv" ] && WHY+=("part of the set was written")
expect_refusal solve_results_onto_its_model "$T/out/result.json" "is the input being read"
rm -rf "$T/out"

# A load of 1e300: the same exit code and message whatever the output.
awk 'NR > 2' tests/errors/load_overflow.cable >"$T/huge.cable"
"$BIN" solve "$T/huge.cable" >/dev/null 2>"$T/e1"; r1=$?
"$BIN" solve "$T/huge.cable" --json >"$T/j" 2>"$T/e2"; r2=$?
"$BIN" solve "$T/huge.cable" -q -o "$T/o" 2>"$T/e3"; r3=$?
[ "$r1$r2$r3" = 333 ] || WHY+=("exit codes summary $r1, --json $r2, -o $r3; expected 3 each")
for e in e1 e2 e3; do
    grep -qF "$T/huge.cable: not converged" "$T/$e" || WHY+=("$e does not name the model: $(cat "$T/$e")")
done
grep -q '"converged":[[:space:]]*false' "$T/j" || WHY+=("--json does not say converged false")
grep -q '"external_force_norm":[[:space:]]*1e+300' "$T/j" || WHY+=("|f_ext| is not 1e300")
finish huge_load_same_exit_code_every_output

# Signals: a 50 000-element cable solved and written over the set of a lighter one.
cable() {   # cable W: the cable with self-weight W
    printf 'units kN m\nmaterial steel E=2.0e8\nsection strand material=steel A=3.14e-4 w=%s\n' "$1"
    printf 'gravity 0 -1 0\nnode 1 0 0 0 fix=xyz\nnode 2 200 0 0 fix=xyz\n'
    printf 'cable 1 2 section=strand n=50000 length=201.3545\n'
}
cable 0.1 >"$T/light.cable"
cable 0.2 >"$T/heavy.cable"
"$BIN" solve "$T/heavy.cable" -q -o "$T/new" 2>/dev/null || WHY+=("the heavy cable does not solve")
"$BIN" solve "$T/light.cable" -q -o "$T/set" 2>/dev/null || WHY+=("the light cable does not solve")
sums() { (cd "$1" && cksum result.json nodes.csv elements.csv result.vtu 2>&1 | awk '{ print $1, $2 }'); }
old_sums=$(sums "$T/set")
new_sums=$(sums "$T/new")
[ "$old_sums" != "$new_sums" ] || WHY+=("the two sets are alike")
finish signal_setup
seen=""
for sig in INT TERM; do
    for delay in 0.05 0.15 0.3 0.6 1.0; do
        # (a background job starts with SIGINT ignored, which catena keeps: reset it)
        env --default-signal=INT "$BIN" solve "$T/heavy.cable" -q -o "$T/set" 2>"$T/err" &
        pid=$!
        # the delay counts from catena's handlers being set (SigCgt of /proc/PID/status
        # holds SIGINT's bit): a loaded machine may take longer than any fixed delay to
        # get there, and before it a signal kills silently
        for _ in $(seq 200); do
            cgt=$(awk '/^SigCgt:/ { print $2 }' "/proc/$pid/status" 2>/dev/null) || break
            [ -n "$cgt" ] && [ $((0x$cgt & 2)) -ne 0 ] && break
            sleep 0.02
        done
        sleep "$delay"
        kill -s "$sig" "$pid" 2>/dev/null
        wait "$pid"; rc=$?
        want=130; [ "$sig" = TERM ] && want=143
        now=$(sums "$T/set")
        case $rc in
        0) [ "$now" = "$new_sums" ] || WHY+=("SIG$sig at $delay s: exit 0 without the new set") ;;
        "$want") [ "$now" = "$old_sums" ] || WHY+=("SIG$sig at $delay s: exit $rc, the older set changed")
                 grep -q "interrupted" "$T/err" || WHY+=("SIG$sig at $delay s: no message: $(cat "$T/err")") ;;
        *) WHY+=("SIG$sig at $delay s: exit $rc: $(cat "$T/err")") ;;
        esac
        seen="$seen $rc"
        ls "$T/set" | grep -q '\.tmp\.' && WHY+=("SIG$sig at $delay s: a temporary was left")
        [ "$rc" = 0 ] && "$BIN" solve "$T/light.cable" -q -o "$T/set" 2>/dev/null   # the older set again
    done
done
case $seen in *130*) ;; *) WHY+=("no run was interrupted by SIGINT (exit codes:$seen)") ;; esac
echo "signals: exit codes$seen"
finish signals_leave_one_whole_set

cli_summary
