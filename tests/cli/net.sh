#!/usr/bin/env bash
# tests/cli/net.sh CATENA: the `net` generator (docs/format.md "net"):
#   - a 6 x 6 hypar net (tension-only strands prestressed to N0 = 10 kN, 0.5 kN on every
#     interior node through the set roof.inner) against the same net written out by
#     bench/hypar_net.py 6 (its own ids, coordinates z = 10 (x^2 - y^2) / 50^2, element
#     order and l0 from a bisection on the Green-Lagrange strain): the same node ids,
#     element ids and connectivity, coordinates, displacements and forces to 1e-10
#     (relative, + 1e-10);
#   - a flat 3 x 2 net after an explicit node 20, given origin=, fix=xyz (the corners, which
#     no member reaches, held in x, y, z whatever fix= says), eps0= and its member set loaded by lineload,
#     written before its section and material: the model
#     written out by hand (nodes 21..32, members 1..7 by the rule of net_gen.h, the
#     loads on the sets by ids), bit for bit in the JSON;
#   - `catena formfind` of a net with q=: written back as node, element and set lines;
#     the found file stays put with the forces q l, and equals (JSON bit for bit, with a
#     load on the set roof.inner in a later step) the same net written by hand and found;
#   - a flat prestressed net under snow starts towards its force-density shape: fewer
#     iterations, and the answer of load-stepped pure Newton.
# ctest-cost: 3
# Prints "N passed, N failed"; exit 1 on any failure.
set -u

. "$(dirname "$0")/lib/common.sh"
cli_init net "${1:-}"
PY=/usr/bin/python3
[ -x "$PY" ] || PY=python3

# 1. hypar against bench/hypar_net.py
"$PY" bench/hypar_net.py 6 >"$T/py.cable"
cat >"$T/net.cable" <<'M'
units kN m
material strand E=1.6e8 tension-only
section s material=strand A=1.5e-4
net roof hypar nx=6 ny=6 lx=100 ly=100 h=10 section=s N0=10
load set=roof.inner fz=-0.5
M
"$BIN" solve "$T/net.cable" --json >"$T/n.json" 2>"$T/err"; rc=$?
[ $rc -eq 0 ] || WHY+=("net: exit $rc: $(head -c 200 "$T/err")")
"$BIN" solve "$T/py.cable" --json >"$T/p.json" 2>"$T/err"; rc=$?
[ $rc -eq 0 ] || WHY+=("python's net: exit $rc: $(head -c 200 "$T/err")")
"$PY" - "$T/n.json" "$T/p.json" <<'PY' || WHY+=("the generated hypar differs from bench/hypar_net.py's")
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
worst = 0.0
def cmp(x, y, path):
    global worst
    if isinstance(x, dict):
        assert set(x) == set(y), (path, set(x) ^ set(y))
        for k in x: cmp(x[k], y[k], path + "/" + k)
    elif isinstance(x, list):
        assert len(x) == len(y), path
        for u, v in zip(x, y): cmp(u, v, path)
    elif isinstance(x, (int, float)) and not isinstance(x, bool):
        assert not isinstance(x, int) or not path.endswith(("/id", "/nodes")) or x == y, (path, x, y)
        worst = max(worst, abs(x - y) / (1e-10 + abs(y)) if abs(x - y) > 1e-10 else 0)
    else:
        assert x == y, (path, x, y)
for key in ("nodes", "elements", "reactions"):
    cmp(a[key], b[key], key)
assert len(a["nodes"]) == 49 and len(a["elements"]) == 60, (len(a["nodes"]), len(a["elements"]))
assert worst <= 1e-10, worst
print("hypar: worst relative difference %.3g" % worst)
PY
finish hypar_vs_python

# 2. flat net against the model written by hand
cat >"$T/flat.cable" <<'M'
node 20 0 0 5 fix=xyz
lineload roof qz=-0.01
load set=roof.inner fz=-0.2
net roof flat nx=3 ny=2 lx=9 ly=4 origin=10,20,5 fix=xyz section=s eps0=1e-3
section s material=m A=1e-4
material m E=2e8
units kN m
M
cat >"$T/hand.cable" <<'M'
units kN m
material m E=2e8
section s material=m A=1e-4
node 20 0 0 5 fix=xyz
node 21 5.5 18 5 fix=xyz
node 22 5.5 20 5 fix=xyz
node 23 5.5 22 5 fix=xyz
node 24 8.5 18 5 fix=xyz
node 25 8.5 20 5
node 26 8.5 22 5 fix=xyz
node 27 11.5 18 5 fix=xyz
node 28 11.5 20 5
node 29 11.5 22 5 fix=xyz
node 30 14.5 18 5 fix=xyz
node 31 14.5 20 5 fix=xyz
node 32 14.5 22 5 fix=xyz
element 1 22 25 section=s eps0=1e-3
element 2 24 25 section=s eps0=1e-3
element 3 25 28 section=s eps0=1e-3
element 4 25 26 section=s eps0=1e-3
element 5 27 28 section=s eps0=1e-3
element 6 28 31 section=s eps0=1e-3
element 7 28 29 section=s eps0=1e-3
lineload all qz=-0.01
load 25 0 0 -0.2
load 28 0 0 -0.2
M
"$BIN" solve "$T/flat.cable" --json >"$T/f.json" 2>"$T/err"; rc=$?
[ $rc -eq 0 ] || WHY+=("flat net: exit $rc: $(head -c 300 "$T/err")")
"$BIN" solve "$T/hand.cable" --json >"$T/h.json" 2>"$T/err"; rc=$?
[ $rc -eq 0 ] || WHY+=("hand-written net: exit $rc: $(head -c 300 "$T/err")")
cmp -s "$T/f.json" "$T/h.json" || WHY+=("the flat net's JSON differs from the hand-written model's")
finish flat_vs_hand

# 3. form finding a generated net: written back as its nodes, members and sets; the found
#    file solved stays put under the prestress step with the forces q l, and a later step
#    loading the set roof.inner gives the JSON, bit for bit, of the same net written by
#    hand (node and element lines by the rule of net_gen.h, loads by node ids) found and
#    solved the same way.
cat >"$T/ff.cable" <<'M'
units kN m
material m E=2e8
section s material=m A=1e-4
net roof hypar nx=4 ny=4 lx=10 ly=10 h=1 section=s q=10 group=g
step prestress
step snow
load set=roof.inner fz=-0.5
M
"$PY" - >"$T/ffhand.cable" <<'PY'
print("units kN m\nmaterial m E=2e8\nsection s material=m A=1e-4")
nx = ny = 4; lx = ly = 10.0; h = 1.0; a, b = lx / 2, ly / 2
edge = lambda i, j: i in (0, nx) or j in (0, ny)
for i in range(nx + 1):
    for j in range(ny + 1):
        dx, dy = -a + i * (lx / nx), -b + j * (ly / ny)
        print("node %d %r %r %r%s" % (1 + i * (ny + 1) + j, dx, dy, h * (dx * dx / (a * a) - dy * dy / (b * b)),
                                      " fix=xyz" if edge(i, j) else ""))
e = 1
for i in range(nx + 1):
    for j in range(ny + 1):
        n = 1 + i * (ny + 1) + j
        if i < nx and j not in (0, ny): print("element %d %d %d section=s q=10 group=g" % (e, n, n + ny + 1)); e += 1
        if j < ny and i not in (0, nx): print("element %d %d %d section=s q=10 group=g" % (e, n, n + 1)); e += 1
print("step prestress\nstep snow")
for i in range(1, nx):
    for j in range(1, ny): print("load %d 0 0 -0.5" % (1 + i * (ny + 1) + j))
PY
for f in ff ffhand; do
    "$BIN" formfind "$T/$f.cable" -q -o "$T/$f.found.cable" 2>"$T/err" || WHY+=("formfind $f: exit $?: $(head -c 300 "$T/err")")
    "$BIN" solve "$T/$f.found.cable" --json >"$T/$f.json" 2>"$T/err" || WHY+=("solve $f found: exit $?: $(head -c 300 "$T/err")")
done
grep -q "^set roof.inner nodes ids=7-9,12-14,17-19$" "$T/ff.found.cable" || WHY+=("the found net lacks its set roof.inner")
grep -q "^net " "$T/ff.found.cable" && WHY+=("the found file still has a net line")
cmp -s "$T/ff.json" "$T/ffhand.json" || WHY+=("the found net's JSON differs from the hand-written net's")
"$PY" - "$T/ff.json" "$T/ff.found.cable" <<'PY' || WHY+=("the found net does not stay put with q l")
import json, math, re, sys
d = json.load(open(sys.argv[1]))
xyz = {int(m.group(1)): tuple(map(float, m.group(2, 3, 4)))
       for m in re.finditer(r"^node (\d+) (\S+) (\S+) (\S+)", open(sys.argv[2]).read(), re.M)}
st = d["steps"][0]
u = max(abs(n[k]) for n in st["nodes"] for k in ("ux", "uy", "uz"))
f = max(abs(e["force"] / (10 * math.dist(*(xyz[i] for i in e["nodes"]))) - 1) for e in st["elements"])
print("found net: |u| %.2g m under the prestress, forces / (q l) - 1 %.2g" % (u, f))
assert d["converged"] and len(xyz) == 25 and u <= 1e-10 and f <= 1e-10
PY
finish formfind_net_written

# 4. a flat prestressed net under snow starts towards its force-density shape (issue 29
#    item 2; src/start/fdensity.c): 13 iterations before, at most 8 now (6 measured), and
#    the answer of load-stepped pure Newton (no start heuristics) to 1e-9 m.
cat >"$T/fd.cable" <<'M'
units kN m
material strand E=1.6e8
section s material=strand A=1.5e-4
net roof flat nx=8 ny=8 lx=80 ly=80 section=s N0=10
load set=roof.inner fz=-2
M
{ cat "$T/fd.cable"; echo "solve method=newton steps=10"; } >"$T/fd_steps.cable"
"$BIN" solve "$T/fd.cable" --json >"$T/fd.json" 2>"$T/err" || WHY+=("flat net: exit $?: $(head -c 300 "$T/err")")
"$BIN" solve "$T/fd_steps.cable" --json >"$T/fd_steps.json" 2>"$T/err" || WHY+=("flat net, newton steps=10: exit $?: $(head -c 300 "$T/err")")
"$BIN" solve "$T/fd.cable" 2>/dev/null | grep -q "^start: the net's free nodes moved towards" || WHY+=("flat net: no start line in the summary")
"$PY" - "$T/fd.json" "$T/fd_steps.json" <<'PY' || WHY+=("flat net: the force-density start")
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
du = max(abs(x[k] - y[k]) for x, y in zip(a["nodes"], b["nodes"]) for k in ("ux", "uy", "uz"))
sag = max(abs(x["uz"]) for x in b["nodes"])
print("flat net: %d iterations (13 before), |u - u_newton| %.2g m of a sag %.3f m" % (a["iterations"], du, sag))
assert a["converged"] and b["converged"] and a.get("force_density_start") is True and "force_density_start" not in b
assert a["iterations"] <= 8 and du <= 1e-9 and sag > 1, (a["iterations"], du, sag)
PY
finish flat_net_starts_by_force_density

cli_summary
