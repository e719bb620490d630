#!/usr/bin/env bash
# tests/cli/targets_temperature.sh CATENA: targets found with a temperature change in the
# same (first) step (issue 28, item 9). The target's sensitivities must be those of the
# heated or cooled members: they were taken with the length's element at the reference
# temperature, so cooling by 30 K was refused ("the root find does not converge") and
# +30 K took 40 outer iterations, linear convergence.
#   - a mast head held by three catenary guys found together to 20 kN, dT = -30 and +30;
#   - two catenary guys, a cable guy (n=8) and a two-way strut, dT = +30;
# each: exit 0, every target reached, at most 8 outer iterations (Newton on the lengths
# converges quadratically, as it does at dT = 0), and the lengths found, given back as
# length= to a plain solve (no target machinery), give the catenaries' tensions of 20
# to 1e-8 and the head's displacement of the targets' solve.
# Prints "N passed, N failed"; exit 1 on any failure.
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init targets_temperature "${1:-}"

head3() {
    cat <<'M'
units kN m
material steel E=1.6e8 strain=engineering alpha=1.2e-5
material bar E=2e8 alpha=1.2e-5
section guy material=steel A=2e-4 w=0.02
section strut material=bar A=1e-3
gravity 0 0 -9.81
node 1 0 0 30
node 2 40 0 0 fix=xyz
node 3 -20 34.64 0 fix=xyz
node 4 -20 -34.64 0 fix=xyz
node 5 0 0 0 fix=xyz
M
}
{ head3; cat <<'M'
catenary 1 1 2 section=guy tension=20
catenary 2 1 3 section=guy tension=20
catenary 3 1 4 section=guy tension=20
spring 4 1 5 k=1e5
load 1 5 0 0
M
} >"$T/three.cable"
{ head3; cat <<'M'
cable 1 4 section=guy n=8 tension=20
catenary 21 1 2 section=guy tension=20
catenary 22 1 3 section=guy tension=20
element 40 1 5 section=strut
load 1 5 0 0
temperature all dT=30
M
} >"$T/mixed.cable"
sed 's/^load 1 5 0 0$/&\ntemperature all dT=-30/' "$T/three.cable" >"$T/cold.cable"
sed 's/^load 1 5 0 0$/&\ntemperature all dT=30/' "$T/three.cable" >"$T/hot.cable"

# check NAME: solve with targets, then with the lengths found given back as length=
check() {
    local f="$T/$1.cable"
    "$BIN" solve "$f" >"$T/$1.out" 2>"$T/$1.err"
    local rc=$?
    "$BIN" solve "$f" --json >"$T/$1.target.json" 2>/dev/null
    [ $rc -eq 0 ] || { WHY+=("$1: exit $rc: $(head -c 300 "$T/$1.err")"); return; }
    local n_reached n_targets worst
    n_targets=$(grep -c 'tension=20' "$f")
    n_reached=$(grep -c 'tension=20 reached' "$T/$1.out")
    [ "$n_reached" = "$n_targets" ] || WHY+=("$1: $n_reached of $n_targets targets reached")
    worst=$(sed -n 's/.*(\([0-9]*\) outer iterations).*/\1/p' "$T/$1.out" | sort -n | tail -1)
    [ -n "$worst" ] && [ "$worst" -le 8 ] || WHY+=("$1: ${worst:-?} outer iterations (Newton on the lengths takes 5 at dT=0)")
    # the lengths back into the model, in the order of the target lines (the summary
    # lists cables first, then catenaries: the models put their cables first)
    cp "$f" "$T/$1.fixed.cable"
    local L
    for L in $(sed -n 's/.*length found \([0-9.e+-]*\) m.*/\1/p' "$T/$1.out"); do
        awk -v L="$L" '/tension=20/ { n++; if (n == 1) sub(/tension=20/, "length=" L ($1 == "cable" ? " shape=straight" : "")) } { print }' \
            "$T/$1.fixed.cable" >"$T/x" && mv "$T/x" "$T/$1.fixed.cable"
    done
    "$BIN" solve "$T/$1.fixed.cable" --json >"$T/$1.json" 2>"$T/$1.err2" ||
        { WHY+=("$1: the plain solve with the lengths found: exit $?: $(head -c 300 "$T/$1.err2")"); return; }
    [ "$have_python" = 1 ] || return
    local msg
    msg=$(python3 - "$T/$1.json" "$T/$1.target.json" <<'PY'
import json, sys
d, t = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
out = []
for e in d["elements"]:
    if e.get("type") == "catenary" and abs(max(e["tension"]) - 20) > 2e-7:
        out.append("catenary %d: tension %.12g" % (e["id"], max(e["tension"])))
# the state with the lengths given is the state the targets found (the cable guy's
# tension is its end's pull plus half its end element's weight: read through the head)
head = lambda j: [n for n in j["nodes"] if n["id"] == 1][0]
for k in ("ux", "uy", "uz"):
    if abs(head(d)[k] - head(t)[k]) > 1e-8: out.append("head %s %.12g with the lengths, %.12g with the targets" % (k, head(d)[k], head(t)[k]))
print("; ".join(out))
PY
)
    [ -z "$msg" ] || WHY+=("$1: $msg")
}

for m in cold hot mixed; do
    check $m
    finish "targets_with_temperature_$m"
done

cli_summary
