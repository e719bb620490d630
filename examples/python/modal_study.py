"""A modal study of the paper's cable: the first natural frequencies of the 200 m span
about its equilibrium under self-weight, for the four lengths of the paper, beside the
taut string's f1 = 1 / (2 L) sqrt(H / m) (H the horizontal tension).
    PYTHONPATH=DIR python3 examples/python/modal_study.py"""
import numpy as np
import catena

print(" length [m]   H [kN]   f1..f4 [Hz]                              string f1 [Hz]")
for S in (200.3340, 201.3545, 250.8777, 279.6157):
    m = catena.Model(units=("kN", "m"), gravity=(0, -1, 0))
    m.material("steel", E=2.0e8).section("strand", material="steel", A=3.14e-4, w=0.1)
    m.nodes([1, 2], [[0, 0, 0], [200, 0, 0]], fix="xyz").cable(1, 2, section="strand", n=40, length=S)
    sol = m.solve(modes=4, check=True)
    H = abs(sol.reactions[0, 0])
    mass = 0.1 / 9.80665                                  # t/m: w / g
    f = sol.modes.frequencies
    print(f"{S:11.4f} {H:8.3f}   {np.array2string(f, precision=4):40s} {np.sqrt(H / mass) / 400:.4f}")
