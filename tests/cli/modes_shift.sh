#!/usr/bin/env bash
# tests/cli/modes_shift.sh CATENA: modes nearest a shift are reported only when they are
# eigenpairs (issue 28, item 12). On the 4 x 4 net of tests/models/modes (highest
# frequency about 36 Hz):
#   - shift=10 and shift=1e4: exit 0, residuals at round-off, the 5 modes of the file's own
#     27 nearest the shift in omega^2 (shift-invert's distance);
#   - shift=1e6: the modes fail the residual test: exit 3, the message says so and
#     names the model's frequency scale, nothing on stdout (--json) and no files (-o);
#   - shift=1e8, 1e20, 1e152: refused before any work as unresolvable: exit 3, the same;
#   - nothing but catena's own message on stdout or stderr (no LAPACK complaint).
# Prints "N passed, N failed"; exit 1 on any failure.
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init modes_shift "${1:-}"
net=tests/models/modes/net4.cable
shifted() { sed "s/^modes .*/modes count=5 mass=lumped shift=$1/" "$net" >"$T/s$1.cable"; echo "$T/s$1.cable"; }

"$BIN" solve "$net" --json >"$T/all.json" 2>/dev/null || WHY+=("the net does not solve")
for sh in 10 1e4; do
    "$BIN" solve "$(shifted $sh)" --json >"$T/j" 2>"$T/err"; rc=$?
    [ $rc -eq 0 ] || WHY+=("shift=$sh: exit $rc: $(cat "$T/err")")
    if [ $have_python = 1 ]; then
        msg=$(python3 - "$T/j" "$T/all.json" "$sh" <<'PY'
import json, sys
d, a, sh = json.load(open(sys.argv[1])), json.load(open(sys.argv[2])), float(sys.argv[3])
if not d["modal"]["max_residual"] <= 1e-9: print("residual %g" % d["modal"]["max_residual"])
f = sorted(m["frequency"] for m in d["modes"])
ref = sorted(m["frequency"] for m in a["modes"])
want = sorted(sorted(ref, key=lambda x: abs(x * x - sh * sh))[:5])   # nearest in omega^2
if any(abs(x - y) > 1e-8 * y for x, y in zip(f, want)): print("modes %s, the nearest of all 27 %s" % (f, want))
PY
)
        [ -z "$msg" ] || WHY+=("shift=$sh: $msg")
    fi
    finish "shift_${sh}_resolved"
done

for sh in 1e6 1e8 1e20 1e152; do
    m=$(shifted $sh)
    "$BIN" solve "$m" --json >"$T/j" 2>"$T/err"; rc=$?
    [ $rc -eq 3 ] || WHY+=("shift=$sh: exit $rc, expected 3: $(cat "$T/err")")
    [ -s "$T/j" ] && WHY+=("shift=$sh: stdout holds $(head -c 100 "$T/j")")
    case $sh in
    1e6) grep -q "modes fail the residual test" "$T/err" || WHY+=("shift=$sh: $(cat "$T/err")") ;;
    *) grep -q "no mode can be resolved" "$T/err" || WHY+=("shift=$sh: $(cat "$T/err")") ;;
    esac
    grep -q "far above the model's highest frequency" "$T/err" || WHY+=("shift=$sh: no frequency scale named")
    [ "$(wc -l <"$T/err")" -eq 1 ] || WHY+=("shift=$sh: more than catena's one line: $(cat "$T/err")")
    "$BIN" solve "$m" -q -o "$T/o$sh" 2>/dev/null; rc=$?
    [ $rc -eq 3 ] || WHY+=("shift=$sh -o: exit $rc")
    [ -n "$(ls -A "$T/o$sh" 2>/dev/null)" ] && WHY+=("shift=$sh -o: files written: $(ls "$T/o$sh")")
    finish "shift_${sh}_refused"
done

cli_summary
