"""Form finding, then a load analysis: the hyperbolic-paraboloid net of
examples/formfind/hypar_net.cable is found by force density (each member's q=), and the
net found is loaded by a snow load of 0.5 kN at every free node and solved; the found
model is written as .cable (which `catena solve` reads).
    PYTHONPATH=DIR python3 examples/python/formfind_then_load.py [OUTDIR]"""
import os
import sys

import numpy as np
import catena

here = os.path.dirname(os.path.abspath(__file__))
out = sys.argv[1] if len(sys.argv) > 1 else "."
found, report = catena.formfind(os.path.join(here, "..", "formfind", "hypar_net.cable"),
                                path=os.path.join(out, "hypar_found.cable"))
print(f"form finding: {report['reason']} in {report['iterations']} iterations, "
      f"forces {report['force_min']:.2f} .. {report['force_max']:.2f} kN")

prestressed = found.solve(check=True)
free = found.fix == 0
print(f"found net under its prestress: {prestressed.iterations} iterations, "
      f"largest displacement {np.abs(prestressed.displacements).max():.2e} m")

found.loads(found.node_ids[free], [0.0, 0.0, -0.5])
snow = found.solve(check=True)
print(f"snow: largest deflection {-snow.displacements[:, 2].min():.4f} m, "
      f"member forces {snow.forces.min():.2f} .. {snow.forces.max():.2f} kN, slack {int(snow.slack.sum())}")
