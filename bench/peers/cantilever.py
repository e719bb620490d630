#!/usr/bin/env python3
# bench/peers/cantilever.py FORMAT N [K] [SYSTEM] - issue 23's large-deflection cantilever:
# L = 10 m along x, clamped at x = 0, a square solid section 0.1 x 0.1 m (E = 2.1e8 kPa,
# nu = 0.3), N equal elements, a tip load P in -z of K = P L^2 / EI (default 2: the tip
# turns by 0.78 rad), dead (fixed direction); Euler-Bernoulli bending.
#   catena    `beam ... n=N` (corotational), default solver
#   tcl       OpenSees: elasticBeamColumn on a Corotational geomTransf, 10 LoadControl steps,
#             full Newton, NormDispIncr 1e-10 m, RCM, system SYSTEM (default BandGeneral);
#             prints "peer iterations=I ok=0 u=UX,UY,UZ N=0 R=RX,RY,RZ" (tip, clamp reaction)
#   inp       CalculiX: B31 beams (expanded to bricks), *BEAM SECTION RECT, NLGEOM, *STATIC
#   elastica  the inextensible elastica's tip displacement (shooting on theta'(0), RK4 with
#             4000 steps) as "u=UX,0,UZ" - the independent truth
# Node 1 is the clamp; the tip is node N + 1 (tcl, inp) or node 2 (catena: `beam n=`
# numbers the inner nodes after it).
import sys, math
fmt, n = sys.argv[1], int(sys.argv[2])
k = float(sys.argv[3]) if len(sys.argv) > 3 else 2.0
system = sys.argv[4] if len(sys.argv) > 4 else "BandGeneral"
L, b, E, nu = 10.0, 0.1, 2.1e8, 0.3
A, I = b * b, b ** 4 / 12
J = 0.1406 * b ** 4                       # a square's torsion constant (Roark)
G = E / (2 * (1 + nu))
P = k * E * I / L ** 2
W = sys.stdout.write

def elastica():
    q = P / (E * I)                        # theta'' = -q cos(theta), theta(0) = 0, theta'(L) = 0
    def shoot(k0, out=False):
        m = 4000
        h = L / m
        th, w, x, z = 0.0, k0, 0.0, 0.0
        f = lambda th, w: (w, -q * math.cos(th))
        for _ in range(m):
            a1 = f(th, w); a2 = f(th + h / 2 * a1[0], w + h / 2 * a1[1])
            a3 = f(th + h / 2 * a2[0], w + h / 2 * a2[1]); a4 = f(th + h * a3[0], w + h * a3[1])
            c = [math.cos(th), math.cos(th + h / 2 * a1[0]), math.cos(th + h / 2 * a2[0]), math.cos(th + h * a3[0])]
            s = [math.sin(th), math.sin(th + h / 2 * a1[0]), math.sin(th + h / 2 * a2[0]), math.sin(th + h * a3[0])]
            x += h / 6 * (c[0] + 2 * c[1] + 2 * c[2] + c[3])
            z += h / 6 * (s[0] + 2 * s[1] + 2 * s[2] + s[3])
            th += h / 6 * (a1[0] + 2 * a2[0] + 2 * a3[0] + a4[0])
            w += h / 6 * (a1[1] + 2 * a2[1] + 2 * a3[1] + a4[1])
        return (x, z, th) if out else w
    lo, hi = 0.0, q * L                    # theta'(L) < 0 at lo, >= 0 at hi
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if shoot(mid) > 0: hi = mid
        else: lo = mid
    x, z, th = shoot(0.5 * (lo + hi), True)
    print("u=%.12e,0,%.12e N=0 R=0,0,%.12e theta=%.12e" % (x - L, -z, P, th))

if fmt == "elastica":
    elastica()
elif fmt == "catena":
    W("units kN m\nmaterial steel E=%.17g nu=%g\n" % (E, nu))
    W("section sq material=steel A=%.17g Iy=%.17g Iz=%.17g J=%.17g\n" % (A, I, I, J))
    W("node 1 0 0 0 fix=xyzrxryrz\nnode 2 %.17g 0 0\n" % L)
    W("beam 1 1 2 section=sq orient=0,0,1 n=%d\n" % n)
    W("load 2 0 0 %.17g\n" % -P)
elif fmt == "tcl":
    W("model basic -ndm 3 -ndf 6\n")
    W("".join("node %d %.17g 0 0\n" % (i + 1, L * i / n) for i in range(n + 1)))
    W("fix 1 1 1 1 1 1 1\ngeomTransf Corotational 1 0 0 1\n")   # local z = global z (vecxz)
    W("".join("element elasticBeamColumn %d %d %d %.17g %.17g %.17g %.17g %.17g %.17g 1\n"
              % (i + 1, i + 1, i + 2, A, E, G, J, I, I) for i in range(n)))
    W("timeSeries Linear 1\npattern Plain 1 1 {\n  load %d 0 0 %.17g 0 0 0\n}\n" % (n + 1, -P))
    W("constraints Plain\nnumberer RCM\nsystem %s\ntest NormDispIncr 1.0e-10 100\nalgorithm Newton\n" % system)
    W("integrator LoadControl 0.1\nanalysis Static\nset its 0\nset ok 0\n")
    W("for {set k 0} {$k < 10} {incr k} {\n  set ok [analyze 1]\n  if {$ok != 0} break\n  incr its [testIter]\n}\n")
    W("reactions\nset t %d\n" % (n + 1))
    W('puts [format "peer iterations=%d ok=%d u=%.12e,%.12e,%.12e N=0 R=%.12e,%.12e,%.12e" $its $ok '
      '[nodeDisp $t 1] [nodeDisp $t 2] [nodeDisp $t 3] [nodeReaction 1 1] [nodeReaction 1 2] [nodeReaction 1 3]]\n')
elif fmt == "inp":
    W("*NODE, NSET=NALL\n")
    W("".join("%d, %.17g, 0, 0\n" % (i + 1, L * i / n) for i in range(n + 1)))
    W("*ELEMENT, TYPE=B31, ELSET=EALL\n")
    W("".join("%d, %d, %d\n" % (i + 1, i + 1, i + 2) for i in range(n)))
    W("*MATERIAL, NAME=STEEL\n*ELASTIC\n%.17g, %g\n" % (E, nu))
    W("*BEAM SECTION, ELSET=EALL, MATERIAL=STEEL, SECTION=RECT\n%g, %g\n0, 1, 0\n" % (b, b))
    W("*NSET, NSET=TIP\n%d\n*NSET, NSET=CLAMP\n1\n*BOUNDARY\nCLAMP, 1, 6\n" % (n + 1))
    W("*STEP, NLGEOM, INC=1000\n*STATIC\n0.1, 1.0\n*CLOAD\n%d, 3, %.17g\n" % (n + 1, -P))
    W("*NODE PRINT, NSET=TIP\nU\n*NODE PRINT, NSET=CLAMP\nRF\n*END STEP\n")
else:
    sys.exit("cantilever.py: FORMAT is catena, tcl, inp or elastica")
