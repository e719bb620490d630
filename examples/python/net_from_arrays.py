"""A prestressed flat cable net built from numpy arrays and solved: a grid of nodes, the
border anchored, members along both directions prestressed to 30 kN, 1.5 kN down at each
interior node; the largest deflection and member forces, the reactions' balance, the
net written as .cable (which `catena solve` reads) and as ParaView .vtu.
    PYTHONPATH=DIR python3 examples/python/net_from_arrays.py [OUTDIR]"""
import os
import sys

import numpy as np
import catena

nx, ny, a = 21, 15, 2.0
ii, jj = np.meshgrid(np.arange(nx), np.arange(ny), indexing="ij")
ids = (ii * ny + jj + 1).ravel()
X = np.stack([ii.ravel() * a, jj.ravel() * a, np.zeros(ids.size)], axis=1)
border = ((ii == 0) | (ii == nx - 1) | (jj == 0) | (jj == ny - 1)).ravel()
grid = ids.reshape(nx, ny)
ends = np.concatenate([np.stack([grid[:-1, 1:-1].ravel(), grid[1:, 1:-1].ravel()], axis=1),
                       np.stack([grid[1:-1, :-1].ravel(), grid[1:-1, 1:].ravel()], axis=1)])

m = catena.Model(units=("kN", "m"), name="net.cable")
m.material("strand", E=1.6e8, strain="engineering", tension_only=True)
m.section("rope", material="strand", A=1.5e-4, mbl=250, safety=2.5)
m.nodes(ids, X, fix=np.where(border, "xyz", ""))
m.elements(np.arange(1, len(ends) + 1), ends, section="rope", N0=30.0)
m.loads(ids[~border], [0.0, 0.0, -1.5])
sol = m.solve(check=True)

print(f"{len(ids)} nodes, {len(ends)} members: {sol.iterations} iterations")
print(f"largest deflection {-sol.displacements[:, 2].min():.4f} m")
print(f"member forces {sol.forces.min():.3f} .. {sol.forces.max():.3f} kN, utilisation <= {sol.utilisation.max():.3f}")
print(f"reactions sum {sol.reactions.sum(axis=0)} (the loads: {-1.5 * (~border).sum():.1f} along z)")
out = sys.argv[1] if len(sys.argv) > 1 else "."
m.write(os.path.join(out, "net.cable"))
sol.to_vtu(os.path.join(out, "net.vtu"))
