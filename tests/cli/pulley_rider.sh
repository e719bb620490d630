#!/usr/bin/env bash
# tests/cli/pulley_rider.sh CATENA: a slack start under a load without a potential
# (issue 28, item 10). A rider (a free pulley node) on a rope between two anchors holds,
# by a hanger, the middle of a two-element deck loaded by `hload` (deformed projection:
# a follower load, so the globalized Newton measures progress by |r|^2 / 2). Every member
# starts slack. While all are slack neither the merit nor its model moves; such a step
# used to leave the shift where the last rejection put it, and the solve crept for 20
# iterations at a fixed step (40 iterations in all; 54 when the rope stays slack).
#   - converges with the default settings within 30 iterations;
#   - the rope tension, the hanger and deck forces and the two free nodes' heights equal
#     the closed form of the symmetric system (two equations, solved by bisection in
#     python), to 1e-8 relative: rope 2 sqrt(20^2 + (10 - zr)^2) = L (1 + T / EA),
#     hanger zr - zd = 9.5 (1 + Th / EAh), deck sqrt(20^2 + zd^2) = 20.2 (1 + Td / EA),
#     the rider 2 T (10 - zr) / half = Th, the deck's middle Th - 2 Td zd / chord = 20 q.
# Prints "N passed, N failed"; exit 1 on any failure.
# ctest-cost: 2
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init pulley_rider "${1:-}"

model() {   # model ROPE_LENGTH Q
    cat <<M
units kN m
gravity 0 0 -1
material rope E=1.6e8 strain=engineering
section r material=rope A=0.001
section h material=rope A=0.0005
node 1 0 0 10 fix=xyz
node 2 40 0 10 fix=xyz
node 3 20 0 9
node 4 0 0 0 fix=xyz
node 5 20 0 0
node 6 40 0 0 fix=xyz
pulley 9 1 3 2 section=r length=$1
element 10 3 5 section=h l0=9.5
element 11 4 5 section=r l0=20.2
element 12 5 6 section=r l0=20.2
hload q=$2 elements=11-12
M
}

for case in "40.3 20" "40.6 20"; do
    set -- $case
    name=rope_${1}_q$2
    model "$1" "$2" >"$T/$name.cable"
    "$BIN" solve "$T/$name.cable" --json >"$T/$name.json" 2>"$T/$name.err" ||
        { WHY+=("$name: exit $?: $(head -c 300 "$T/$name.err")"); finish "$name"; continue; }
    if [ "$have_python" = 1 ]; then
        msg=$(python3 - "$T/$name.json" "$1" "$2" <<'PY'
import json, math, sys
d = json.load(open(sys.argv[1]))
L, q = float(sys.argv[2]), float(sys.argv[3])
EA, EAh = 1.6e8 * 1e-3, 1.6e8 * 5e-4
out = []
if d["iterations"] > 30: out.append("%d iterations" % d["iterations"])

def bisect(f, a, b):
    fa = f(a)
    for _ in range(200):
        m = 0.5 * (a + b)
        fm = f(m)
        if (fm > 0) == (fa > 0): a, fa = m, fm
        else: b = m
    return 0.5 * (a + b)

def rope(zr):          # the rope's tension with the rider at height zr (0 if slack)
    half = math.hypot(20, 10 - zr)
    return max(0.0, (2 * half / L - 1) * EA)

def deck(zd):          # a deck element's force with the middle at height zd
    return (math.hypot(20, zd) / 20.2 - 1) * EA

def rider(zd):         # the rider's height that balances the hanger, the deck's middle at zd
    def f(zr):
        Th = (((zr - zd) / 9.5) - 1) * EAh
        T = rope(zr)
        return 2 * T * (10 - zr) / math.hypot(20, 10 - zr) - Th
    return bisect(f, zd + 9.5, 10.0 - 1e-9)

def middle(zd):        # the deck's middle: hanger up, deck up (zd < 0), the load down
    zr = rider(zd)
    Th = (((zr - zd) / 9.5) - 1) * EAh
    Td = deck(zd)
    return Th + 2 * Td * (-zd) / math.hypot(20, zd) - 20 * q

# the root with the rope carrying (rider below the anchors): the first change of sign
# from below (another branch, the rider pressed to the anchors' line, is not this one)
grid = [-8 + 0.05 * k for k in range(150)]
lo = next(a for a, b in zip(grid, grid[1:])
          if rider(b) < 9.99 and (middle(a) > 0) != (middle(b) > 0))
zd = bisect(middle, lo, lo + 0.05)
zr = rider(zd)
want = {9: rope(zr), 10: ((zr - zd) / 9.5 - 1) * EAh, 11: deck(zd), 12: deck(zd)}
n = {p["id"]: p for p in d["nodes"]}
e = {x["id"]: x for x in d["elements"]}
for i, f in want.items():
    if abs(e[i]["force"] - f) > 1e-8 * abs(f): out.append("element %d force %.12g, closed form %.12g" % (i, e[i]["force"], f))
for i, z0, z in ((3, 9, zr), (5, 0, zd)):
    if abs(z0 + n[i]["uz"] - z) > 1e-8 * 10: out.append("node %d z %.12g, closed form %.12g" % (i, z0 + n[i]["uz"], z))
    if abs(n[i]["ux"]) > 1e-8 or abs(n[i]["uy"]) > 1e-8: out.append("node %d moved sideways" % i)
print("; ".join(out))
PY
)
        [ -z "$msg" ] || WHY+=("$name: $msg")
    fi
    finish "$name"
done

cli_summary
