"""catena: geometrically non-linear static analysis of 3D cable structures, from Python.

    import catena
    m = catena.read("examples/paper/s250.8777.cable")   # or catena.Model() built from arrays
    sol = m.solve()                                     # the GIL released; Ctrl-C stops it
    sol.converged, sol.displacements, sol.forces        # numpy arrays, model order

The package is a thin layer over libcatena (the C library, linked into the extension
catena._catena). Its classes: Model, Solution, Step, Modes; its errors: CatenaError >
ModelError, NotConvergedError, CatenaIOError. See help(catena.Model),
help(catena.Solution) and docs/python.md.
"""
from . import _catena
from .errors import CatenaError, CatenaIOError, ModelError, NotConvergedError
from .model import Model, read
from .formfind import formfind
from . import analytic
from .solution import Modes, Solution, Step

__version__ = _catena.version()
__all__ = ["read", "formfind", "analytic", "Model", "Solution", "Step", "Modes", "CatenaError", "ModelError", "NotConvergedError",
           "CatenaIOError", "__version__"]
