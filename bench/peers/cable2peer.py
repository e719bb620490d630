#!/usr/bin/env python3
# bench/peers/cable2peer.py FORMAT [options] < MODEL.cable > OUT
# One pin-jointed cable model (the plain subset that bench/b1_cable.py and
# bench/hypar_net.py --issue10 write: units kN m, `material NAME E=`, `section NAME
# material= A= [mass=]`, `node ID X Y Z [fix=..] [mass=]`, `element ID N1 N2 section=
# [eps0=E]`, `load ID FX FY FZ`) written for one of the three programs so that the three
# solve the SAME equations, not merely the same picture:
#
#   tcl      OpenSees: corotTruss on uniaxialMaterial InitStrainMaterial(Elastic E, eps0):
#            N = E A (l/L - 1 + eps0), L the node-to-node length at the start (engineering
#            strain measured from the drawn geometry, prestrain added).
#   catena-os  catena's model of exactly that law: strain=engineering, N = E' A (l/l0 - 1)
#            with l0 = L (1 - eps0) (eps0' = eps0/(1 - eps0)) and E' = E (1 - eps0), so that
#            E' A / l0 = E A / L.  Mass per unstressed length m' = m / (1 - eps0) (OpenSees'
#            rho is per drawn length L).
#   inp      CalculiX 2.20: T3D2 trusses (expanded to bricks, nu = 0: uniaxial), NLGEOM:
#            St. Venant-Kirchhoff, the prestrain as a cooling of -eps0/alpha with alpha =
#            1e-5 (as bench/nets.sh). CalculiX splits the stretch: l/L = lam_e (1 - eps0)
#            (a free bar so cooled contracts by exactly eps0 L: measured, 2.000000e-3 of
#            1 m) and the elastic part takes St. Venant-Kirchhoff's law on the reference
#            area: N = E A lam_e (lam_e^2 - 1)/2 (found: it is the law that makes the K = 50
#            and K = 100 nets agree to 1e-5; E (1 - eps0)^3 or E (1 - eps0) leave 2e-3).
#   catena-ccx catena's model of that law: Green-Lagrange, N = E' A lam (lam^2 - 1)/2,
#            lam = l/l0, with l0 = L (1 - eps0) (eps0' = (1/(1 - eps0)^2 - 1)/2) and
#            E' = E (1 - eps0)^2.
#
# Options (tcl, inp):
#   --probe-node ID   the node whose displacement is printed (tcl) / written (inp)
#   --probe-elem ID   the element whose axial force is printed (tcl)
#   --probe-support ID  the support node whose reaction is printed (tcl) / written (inp)
#   --steps N         load steps (tcl: LoadControl 1/N, N steps, full Newton; inp: *STATIC
#                     increment 1/N, fixed) [10 for tcl, 1 for inp]
#   --system NAME     OpenSees linear system (ProfileSPD, BandSPD, SparseSYM, UmfPack,
#                     SparseGEN, ...) [ProfileSPD]
#   --numberer NAME   OpenSees DOF numberer [RCM]
#   --test "SPEC"     OpenSees convergence test [NormDispIncr 1.0e-8 100]
#   --ndm 2           OpenSees: a plane model (ndm 2, ndf 2) when every node is held in z
#   --dynamics "DT T_END" --release "NODE FX FY FZ T1"   (tcl, catena-os) after the static
#                     solve, a Newmark (1/2, 1/4) transient from that equilibrium, its loads
#                     held, with the force (FX, FY, FZ) added at NODE along a ramp from 0 at
#                     t = 0 to 1 at T1 (give minus a static point load to release it: free
#                     vibration); lumped mass (OpenSees' corotTruss default), no damping.
#                     tcl prints "t UX UY UZ N" of the probes every step; catena-os writes
#                     the `function`, `step`, `dynamics` and `record` lines.
#   --motion "NODE DIR TABLE"  (with --dynamics, instead of --release) the fixed node
#                     NODE moved along DIR (x, y or z) from its static position by the
#                     table TABLE ("t u" lines, linear between them; a fairlead driven by
#                     its floater): OpenSees' sp of a Path series of the same points after
#                     `remove sp` of its fix (constraints Transformation: Plain takes no
#                     moving support), catena's `function motion table` (the file's
#                     name, beside the model) and `displace ... fn=motion`.
# Output of the Tcl script on stdout: "peer iterations=I ok=0 u=UX,UY,UZ N=FORCE R=RX,RY,RZ"
# (static) or "t UX UY UZ N" rows and the same last line (dynamics); the .inp's .dat holds
# the probe node's U and the support's RF.
import sys, os, math, argparse

ap = argparse.ArgumentParser()
ap.add_argument("fmt", choices=("tcl", "catena-os", "inp", "catena-ccx"))
ap.add_argument("--probe-node", type=int, default=0)
ap.add_argument("--probe-elem", type=int, default=0)
ap.add_argument("--probe-support", type=int, default=0)
ap.add_argument("--steps", type=int, default=0)
ap.add_argument("--system", default="ProfileSPD")
ap.add_argument("--numberer", default="RCM")
ap.add_argument("--test", default="NormDispIncr 1.0e-8 100")
ap.add_argument("--ndm", type=int, default=3)
ap.add_argument("--dynamics", default="")
ap.add_argument("--release", default="")
ap.add_argument("--motion", default="")
a = ap.parse_args()

mats, secs, nodes, elems, loads = {}, {}, {}, [], []
order = []
def kv(tokens):
    d = {}
    for t in tokens:
        if "=" in t:
            k, v = t.split("=", 1)
            d[k] = v
        elif t in ("tension-only",):
            d[t] = "1"
        else:
            sys.exit("cable2peer: unexpected word '%s'" % t)
    return d
for lineno, line in enumerate(sys.stdin, 1):
    line = line.split("#", 1)[0].strip()
    if not line:
        continue
    w = line.split()
    if w[0] == "units":
        if w[1:] != ["kN", "m"]:
            sys.exit("cable2peer: line %d: only 'units kN m' is taken" % lineno)
    elif w[0] == "material":
        d = kv(w[2:])
        if d.get("strain", "green-lagrange") != "green-lagrange" or "tension-only" in d:
            sys.exit("cable2peer: line %d: a plain (two-way) material only" % lineno)
        mats[w[1]] = float(d["E"])
    elif w[0] == "section":
        d = kv(w[2:])
        secs[w[1]] = (d["material"], float(d["A"]), float(d.get("mass", "0")))
    elif w[0] == "node":
        d = kv(w[5:])
        nodes[int(w[1])] = ([float(x) for x in w[2:5]], d.get("fix", ""), float(d.get("mass", "0")))
        order.append(int(w[1]))
    elif w[0] == "element":
        d = kv(w[4:])
        if set(d) - {"section", "eps0"}:
            sys.exit("cable2peer: line %d: element takes section= and eps0= only" % lineno)
        elems.append((int(w[1]), int(w[2]), int(w[3]), d["section"], float(d.get("eps0", "0"))))
    elif w[0] == "load":
        loads.append((int(w[1]), [float(x) for x in w[2:5]]))
    elif w[0] in ("solve",):
        pass
    else:
        sys.exit("cable2peer: line %d: directive '%s' not taken" % (lineno, w[0]))

eps = sorted(set(e[4] for e in elems))
if len(eps) != 1:
    sys.exit("cable2peer: one eps0 for every element, found %s" % eps[:4])
e0 = eps[0]
out = sys.stdout
W = out.write

def catena(fmt):
    if fmt == "catena-os":
        Ef, ep, law, mf = 1 - e0, e0 / (1 - e0), " strain=engineering", 1 / (1 - e0)
    else:
        Ef, ep, law, mf = (1 - e0) ** 2, (1 / (1 - e0) ** 2 - 1) / 2, "", 1 / (1 - e0)
    W("units kN m\n")
    for m, E in mats.items():
        W("material %s E=%.17g%s\n" % (m, E * Ef, law))
    for s, (m, A, ms) in secs.items():
        W("section %s material=%s A=%.17g%s\n" % (s, m, A, " mass=%.17g" % (ms * mf) if ms else ""))
    rows = []
    for i in order:
        x, fix, ms = nodes[i]
        rows.append("node %d %.17g %.17g %.17g%s%s\n" % (i, x[0], x[1], x[2], " fix=" + fix if fix else "",
                                                        " mass=%.17g" % ms if ms else ""))
    W("".join(rows))
    W("".join("element %d %d %d section=%s%s\n" % (i, n1, n2, s, " eps0=%.17g" % ep if ep else "")
              for (i, n1, n2, s, _) in elems))
    if a.dynamics and a.motion:
        W("function motion table %s\nstep static\n" % os.path.basename(a.motion.split()[2]))
    elif a.dynamics:
        W("function release ramp t0=0 t1=%s\nstep static\n" % a.release.split()[4])
    W("".join("load %d %.17g %.17g %.17g\n" % (i, f[0], f[1], f[2]) for (i, f) in loads))
    if a.dynamics:
        dt, tend = a.dynamics.split()
        if a.motion:
            mn, md, _ = a.motion.split()
            W("displace %s %s=1 fn=motion\n" % (mn, md))
        else:
            rn, rx, ry, rz, _ = a.release.split()
            W("load %s %s %s %s fn=release\n" % (rn, rx, ry, rz))
        W("dynamics dt=%s t_end=%s method=newmark mass=lumped\n" % (dt, tend))
        W("record node=%d\nrecord element=%d force\n" % (a.probe_node, a.probe_elem))

def tcl():
    ndm = a.ndm
    if ndm == 2 and any("z" not in f for (_, f, _) in nodes.values()):
        sys.exit("cable2peer: --ndm 2 needs every node held in z")
    W("# written by bench/peers/cable2peer.py tcl (a fresh interpreter: no wipe)\nmodel basic -ndm %d -ndf %d\n" % (ndm, ndm))
    rows = []
    for i in order:
        x, fix, ms = nodes[i]
        massarg = (" -mass" + (" %.17g" % ms) * ndm) if ms else ""
        rows.append(("node %d %.17g %.17g" % (i, x[0], x[1])) + (" %.17g" % x[2] if ndm == 3 else "") + massarg + "\n")
        flags = [1 if c in fix else 0 for c in "xyz"[:ndm]]
        if any(flags):
            rows.append("fix %d %s\n" % (i, " ".join(map(str, flags))))
    W("".join(rows))
    mtag = {}
    for k, (m, E) in enumerate(mats.items()):
        mtag[m] = 2 * k + 2
        W("uniaxialMaterial Elastic %d %.17g\n" % (2 * k + 1, E))
        W("uniaxialMaterial InitStrainMaterial %d %d %.17g\n" % (2 * k + 2, 2 * k + 1, e0))
    rows = []
    for (i, n1, n2, s, _) in elems:
        m, A, ms = secs[s]
        rows.append("element corotTruss %d %d %d %.17g %d%s\n" % (i, n1, n2, A, mtag[m],
                                                                  " -rho %.17g" % ms if ms else ""))
    W("".join(rows))
    W("timeSeries Linear 1\npattern Plain 1 1 {\n")
    W("".join("load %d %s\n" % (i, " ".join("%.17g" % v for v in f[:ndm])) for (i, f) in loads))
    W("}\n")
    pn, pe = a.probe_node, a.probe_elem
    probe = ('proc probe {} { return [format "%%.12e %%.12e %%.12e %%.12e" [nodeDisp %d 1] [nodeDisp %d 2] %s '
             '[lindex [eleResponse %d axialForce] 0]] }\n') % (pn, pn, "[nodeDisp %d 3]" % pn if ndm == 3 else "0.0", pe)
    W(probe)
    W("constraints Plain\nnumberer %s\nsystem %s\ntest %s\nalgorithm Newton\n" % (a.numberer, a.system, a.test))
    n = a.steps or 10
    W("integrator LoadControl %.17g\nanalysis Static\n" % (1.0 / n))
    W("set its 0\nset ok 0\nfor {set k 0} {$k < %d} {incr k} {\n  set ok [analyze 1]\n"
      "  if {$ok != 0} break\n  incr its [testIter]\n}\n" % n)
    if a.dynamics:
        dt, tend = (float(x) for x in a.dynamics.split())
        W("loadConst -time 0.0\nwipeAnalysis\n")
        handler = "Plain"
        if a.motion:
            mn, md, tab = a.motion.split()
            k = "xyz".index(md) + 1
            pts = [l.split() for l in open(tab) if l.strip() and not l.startswith("#")]
            W("remove sp %s %d\n" % (mn, k))
            W("timeSeries Path 2 -time {%s} -values {%s}\n" % (" ".join(p[0] for p in pts), " ".join(p[1] for p in pts)))
            W("pattern Plain 2 2 {\n  sp %s %d 1.0\n}\n" % (mn, k))
            handler = "Transformation"
        else:
            rn, rx, ry, rz, t1 = a.release.split()
            W("timeSeries Path 2 -time {0.0 %s 1.0e9} -values {0.0 1.0 1.0}\n" % t1)
            W("pattern Plain 2 2 {\n  load %s %s\n}\n" % (rn, " ".join([rx, ry, rz][:ndm])))
        W("constraints %s\nnumberer %s\nsystem %s\ntest %s\nalgorithm Newton\n" % (handler, a.numberer, a.system, a.test))
        W("integrator Newmark 0.5 0.25\nanalysis Transient\n")
        W("puts \"0 [probe]\"\n")
        W("for {set k 1} {$k <= %d} {incr k} {\n  set ok [analyze 1 %.17g]\n  if {$ok != 0} break\n"
          "  incr its [testIter]\n  puts \"[getTime] [probe]\"\n}\n" % (int(round(tend / dt)), dt))
    ps = a.probe_support
    react = ("reactions\nset r [format \"%%.12e,%%.12e,%%.12e\" [nodeReaction %d 1] [nodeReaction %d 2] %s]\n"
             % (ps, ps, "[nodeReaction %d 3]" % ps if ndm == 3 else "0.0")) if ps else "set r 0,0,0\n"
    W(react)
    W('set p [probe]\nputs "peer iterations=$its ok=$ok u=[join [lrange $p 0 2] ,] N=[lindex $p 3] R=$r"\n')

def inp():
    W("** written by bench/peers/cable2peer.py inp\n*NODE, NSET=NALL\n")
    W("".join("%d, %.17g, %.17g, %.17g\n" % ((i,) + tuple(nodes[i][0])) for i in order))
    bysec = {}
    for el in elems:
        bysec.setdefault(el[3], []).append(el)
    for s, els in bysec.items():
        W("*ELEMENT, TYPE=T3D2, ELSET=E%s\n" % s)
        W("".join("%d, %d, %d\n" % (i, n1, n2) for (i, n1, n2, _, _) in els))
    for d, c in ((1, "x"), (2, "y"), (3, "z")):
        held = [i for i in order if c in nodes[i][1]]
        if held:
            W("*NSET, NSET=FIX%s\n" % c + "".join("%d,\n" % i for i in held))
    for m, E in mats.items():
        W("*MATERIAL, NAME=%s\n*ELASTIC\n%.17g, 0.\n*EXPANSION\n1e-5\n" % (m.upper(), E))
    for s, (m, A, _) in secs.items():
        W("*SOLID SECTION, ELSET=E%s, MATERIAL=%s\n%.17g\n" % (s, m.upper(), A))
    W("*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 0.\n*BOUNDARY\n")
    for d, c in ((1, "x"), (2, "y"), (3, "z")):
        if any(c in nodes[i][1] for i in order):
            W("FIX%s, %d, %d\n" % (c, d, d))
    W("*NSET, NSET=PROBE\n%d\n*NSET, NSET=PROBER\n%d\n" % (a.probe_node, a.probe_support))
    n = a.steps or 1
    W("*STEP, NLGEOM, INC=1000\n*STATIC%s\n%.17g, 1.0\n" % (", DIRECT" if n > 1 else "", 1.0 / n))
    W("*TEMPERATURE\nNALL, %.17g\n*CLOAD\n" % (-e0 / 1e-5))
    W("".join("%d, %d, %.17g\n" % (i, d + 1, f[d]) for (i, f) in loads for d in range(3) if f[d] != 0.0))
    W("*NODE PRINT, NSET=PROBE\nU\n*NODE PRINT, NSET=PROBER\nRF\n*END STEP\n")

if a.fmt == "tcl":
    tcl()
elif a.fmt == "inp":
    inp()
else:
    catena(a.fmt)
