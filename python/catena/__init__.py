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


def use_cli_heap() -> bool:
    """Give this process the catena command's memory settings, for large solves: glibc's
    heap for every block and never trimmed (mallopt M_MMAP_MAX 0, M_TRIM_THRESHOLD -1),
    CHOLMOD's blocks and the heap advised for transparent huge pages. They save the page
    faults of each factorization's fresh memory (the 1e5-member net: about 1 s of CPU in
    8), at the cost of memory kept by the process after it is freed.

    PROCESS-WIDE and permanent: they apply to every module of the process and cannot be
    undone; the package never calls this itself (a library leaves the process as it
    found it). Call it first thing in a program that solves large models, not from a
    library. Returns False where the platform has no such settings (nothing changed)."""
    return _catena.use_cli_heap()

__all__ = ["read", "formfind", "analytic", "Model", "Solution", "Step", "Modes", "CatenaError", "ModelError", "NotConvergedError",
           "CatenaIOError", "use_cli_heap", "__version__"]
