"""The founding paper's study in ten lines: the 200 m span (E = 200 GPa, A = 3.14 cm^2,
w = 0.1 kN/m, 20 elements, pure Newton) over unstressed lengths from taut to slack: the
largest stress and the mid-span sag of each, from numpy arrays.
    PYTHONPATH=DIR python3 examples/python/paper_sweep.py"""
import numpy as np
import catena

lengths = np.linspace(200.3340, 279.6157, 12)
print(" length [m]   max stress [MPa]   sag [m]")
for S in lengths:
    m = catena.Model(units=("kN", "m"), gravity=(0, -1, 0))
    m.material("steel", E=2.0e8).section("strand", material="steel", A=3.14e-4, w=0.1)
    m.nodes([1, 2], [[0, 0, 0], [200, 0, 0]], fix="xyz").cable(1, 2, section="strand", n=20, length=S)
    sol = m.solve(method="newton", check=True)
    print(f"{S:11.4f} {sol.stresses.max() / 1e3:18.3f} {-sol.coordinates[:, 1].min():9.4f}")
