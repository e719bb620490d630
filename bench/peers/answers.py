#!/usr/bin/env python3
# bench/peers/answers.py: one line "u=UX,UY,UZ N=FORCE R=RX,RY,RZ" per program, and the check
# that two such lines agree.
#   answers.py catena DIR NODE ELEM SUPPORT   from catena's -o DIR (nodes.csv, elements.csv)
#   answers.py opensees LOG                   the "peer ..." line the Tcl script printed
#   answers.py ccx JOB.dat                    the last increment's U of the probe set and
#                                             RF of the support set (N left out: n/a)
#   answers.py compare TOL NAME_A LINE_A NAME_B LINE_B
#       relative differences |a - b| / |b| of the displacement vector (2-norm), of N and of
#       the reaction vector; prints them and "agree" or "DISAGREE" (exit 1) against TOL.
import sys, csv, math, re

def fmt(u, n, r):
    f = lambda v: ",".join("%.12e" % x for x in v)
    return "u=%s N=%s R=%s" % (f(u), "%.12e" % n if n is not None else "nan", f(r))

def parse(line):
    d = dict(t.split("=", 1) for t in line.split() if "=" in t)
    vec = lambda s: [float(x) for x in s.split(",")]
    n = float(d["N"]) if d.get("N", "nan") != "nan" else None
    return vec(d["u"]), n, vec(d["R"])

def catena(dirname, node, elem, support):
    u = r = None
    with open(dirname + "/nodes.csv") as f:
        for row in csv.DictReader(f):
            if int(row["id"]) == node:
                u = [float(row[k]) for k in ("ux", "uy", "uz")]
            if int(row["id"]) == support:
                r = [float(row[k]) for k in ("rx", "ry", "rz")]
    n = None
    with open(dirname + "/elements.csv") as f:
        for row in csv.DictReader(f):
            if int(row["id"]) == elem:
                n = float(row["force"])
                break
    if u is None or r is None or n is None:
        sys.exit("answers.py: node %d, element %d or support %d not in %s" % (node, elem, support, dirname))
    print(fmt(u, n, r))

def opensees(log):
    last = [l for l in open(log) if l.startswith("peer ")]
    if not last:
        sys.exit("answers.py: no 'peer' line in %s" % log)
    d = dict(t.split("=", 1) for t in last[-1].split() if "=" in t)
    if d["ok"] != "0":
        sys.exit("answers.py: OpenSees did not converge (ok=%s) in %s" % (d["ok"], log))
    print("%s iterations=%s" % (fmt(*parse(last[-1])), d["iterations"]))

def ccx(dat):
    text = open(dat).read()
    blocks = re.split(r"\n\s*(displacements|forces) \(\w+,\w+,\w+\) for set (\w+) and time\s+(\S+)", text)
    u = r = None
    for i in range(1, len(blocks) - 3, 4):
        kind, rows = blocks[i], blocks[i + 3]
        first = rows.strip().splitlines()[0].split()
        vals = [float(x) for x in first[1:4]]
        if kind == "displacements":
            u = vals
        else:
            r = vals
    if u is None or r is None:
        sys.exit("answers.py: no U or RF in %s" % dat)
    print(fmt(u, None, r))

def rel(a, b):
    na = math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))
    nb = math.sqrt(sum(y * y for y in b))
    return na / nb if nb > 0 else na

def compare(tol, na, la, nb, lb):
    ua, fa, ra = parse(la)
    ub, fb, rb = parse(lb)
    du, dr = rel(ua, ub), rel(ra, rb)
    dn = abs(fa - fb) / abs(fb) if fa is not None and fb is not None and fb != 0 else None
    worst = max(du, dr, dn or 0.0)
    ok = worst <= tol
    print("%s vs %s: displacement %.2e, force %s, reaction %.2e (relative) -> %s (tolerance %.0e)"
          % (na, nb, du, "%.2e" % dn if dn is not None else "n/a", dr, "agree" if ok else "DISAGREE", tol))
    sys.exit(0 if ok else 1)

cmd = sys.argv[1]
if cmd == "catena":
    catena(sys.argv[2], int(sys.argv[3]), int(sys.argv[4]), int(sys.argv[5]))
elif cmd == "opensees":
    opensees(sys.argv[2])
elif cmd == "ccx":
    ccx(sys.argv[2])
elif cmd == "compare":
    compare(float(sys.argv[2]), *sys.argv[3:7])
else:
    sys.exit("answers.py: catena|opensees|ccx|compare")
