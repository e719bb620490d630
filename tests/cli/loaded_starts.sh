#!/usr/bin/env bash
# tests/cli/loaded_starts.sh CATENA: a chain of `element`s whose nodes carry point loads
# of one direction, uniform per length, starts on the elastic catenary of that load
# (issue 29, item 2), as a generated `cable` under its weight does. The OpenSees B1
# cable: a 1000 m span of n elements prestressed by eps0 = 1e-3 on a parabola of 1 m sag,
# its weight 0.1 kN/m as point loads, plane (nodes held in z). Before: 11 iterations at
# n = 1000 (13 at 1e4, 15 at 1e5), the first steps swinging the chain down 38 m.
#   - n = 1000 converges in at most 5 iterations (method=auto, the default);
#   - its answer equals load-stepped pure Newton's from the parabola (method=newton
#     steps=10, OpenSees' procedure, no pre-shaping) to 1e-9 of the sag;
#   - an arch is not turned over: the same chain bulging upwards (sag -1 m) under the
#     same loads is not pre-shaped (the start line says so), and converges to the state
#     load-stepped Newton reaches.
#   - a span swung 76 degrees by a wind across it (tests/test_wind.c's: 130 m of cable
#     on a 100 m span, w = 0.5, wind 2 kN/m) starts in the plane of its weight and the
#     drag: the default method converges within 30 iterations (it stalled at the default
#     maxit from the catenary of the weight alone) to the answer of load-stepped Newton
#     (method=newton steps=20) to 1e-9 m.
# Prints "N passed, N failed"; exit 1 on any failure.
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init loaded_starts "${1:-}"
[ "$have_python" = 1 ] || { echo "loaded_starts: python3 missing: skipped"; cli_summary; exit $?; }

b1() { python3 bench/b1_cable.py "$@"; }   # b1 N SAG EXTRA_LINE (cli_init is at the root)

compare() {   # compare A.json B.json WHAT: mid-span node equal to 1e-9 of the sag
    python3 - "$1" "$2" "$3" <<'PY'
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
mid = lambda d: [x for x in d["nodes"] if x["id"] == 501][0]
sag = abs(mid(b)["uy"])
if not abs(mid(a)["uy"] - mid(b)["uy"]) <= 1e-9 * max(sag, 1):
    print("%s: mid-span uy %.15g, load-stepped Newton %.15g" % (sys.argv[3], mid(a)["uy"], mid(b)["uy"]))
PY
}

b1 1000 1 "" >"$T/b1.cable"
b1 1000 1 "solve method=newton steps=10" >"$T/b1_steps.cable"
"$BIN" solve "$T/b1.cable" --json >"$T/b1.json" 2>"$T/err" || WHY+=("b1: exit $?: $(head -c 300 "$T/err")")
"$BIN" solve "$T/b1_steps.cable" --json >"$T/b1_steps.json" 2>"$T/err" || WHY+=("b1 steps: exit $?: $(head -c 300 "$T/err")")
if [ ${#WHY[@]} -eq 0 ]; then
    it=$(python3 -c "import json; print(json.load(open('$T/b1.json'))['iterations'])")
    [ "$it" -le 5 ] || WHY+=("b1 n=1000: $it iterations (11 from the parabola)")
    msg=$(compare "$T/b1.json" "$T/b1_steps.json" b1)
    [ -z "$msg" ] || WHY+=("$msg")
fi
finish chain_of_point_loads_starts_on_its_catenary

b1 1000 -1 "" >"$T/arch.cable"
b1 1000 -1 "solve method=newton steps=10" >"$T/arch_steps.cable"
"$BIN" solve "$T/arch.cable" --json >"$T/arch.json" 2>"$T/arch.err" || WHY+=("arch: exit $?: $(head -c 300 "$T/arch.err")")
"$BIN" solve "$T/arch_steps.cable" --json >"$T/arch_steps.json" 2>"$T/err" || WHY+=("arch steps: exit $?: $(head -c 300 "$T/err")")
"$BIN" solve "$T/arch.cable" 2>&1 | grep -q "pre-shaped" && WHY+=("arch: pre-shaped")
if [ ${#WHY[@]} -eq 0 ]; then
    msg=$(compare "$T/arch.json" "$T/arch_steps.json" arch)
    [ -z "$msg" ] || WHY+=("$msg")
fi
finish an_arch_is_not_turned_over

swing() {   # swing SOLVE_LINE
    printf 'units kN m\nmaterial steel E=2.0e8 strain=engineering\nsection s material=steel A=1e-3 w=0.5\n'
    printf 'gravity 0 0 -1\nnode 1 0 0 0 fix=xyz\nnode 2 100 0 0 fix=xyz\ncable 1 2 section=s n=40 length=130\n'
    printf 'wind all dir=0,1,0 pressure=2kPa cd=1 d=1m\n%s\n' "$1"
}
swing "solve tol=1e-12" >"$T/swing.cable"
swing "solve tol=1e-12 method=newton steps=20" >"$T/swing_steps.cable"
"$BIN" solve "$T/swing.cable" --json >"$T/swing.json" 2>"$T/err" || WHY+=("swing: exit $?: $(head -c 300 "$T/err")")
"$BIN" solve "$T/swing_steps.cable" --json >"$T/swing_steps.json" 2>"$T/err" || WHY+=("swing steps: exit $?")
if [ ${#WHY[@]} -eq 0 ]; then
    msg=$(python3 - "$T/swing.json" "$T/swing_steps.json" <<'PY'
import json, math, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
out = []
if a["iterations"] > 30: out.append("%d iterations" % a["iterations"])
err = max(abs(x[k] - y[k]) for x, y in zip(a["nodes"], b["nodes"]) for k in ("ux", "uy", "uz"))
if not err <= 1e-9: out.append("differs from load-stepped Newton by %.3g m" % err)
mid = [x for x in a["nodes"] if x["id"] == 22][0]           # an interior node near mid-span
ang = math.degrees(math.atan2(mid["y"] + mid["uy"], -(mid["z"] + mid["uz"])))
if not 70 < ang < 80: out.append("swing %.1f degrees" % ang)
print("; ".join(out))
PY
)
    [ -z "$msg" ] || WHY+=("swing: $msg")
fi
finish a_wind_swing_starts_in_its_plane

cli_summary
