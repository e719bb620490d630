"""numpy, for the package's arrays.

The extension itself does not need numpy (it hands out buffers); the package returns
numpy arrays. A Python that has no numpy of its own (a pyenv or venv interpreter on a
Debian machine without network) may use Debian's python3-numpy when it is built for the
same Python version: only then is Debian's dist-packages directory appended (not
prepended) to sys.path, and only if the import failed.
"""
import sys

try:
    import numpy
except ImportError:  # pragma: no cover - depends on the interpreter
    _DEBIAN = "/usr/lib/python3/dist-packages"
    if _DEBIAN in sys.path:
        raise
    sys.path.append(_DEBIAN)
    try:
        import numpy
    except ImportError as e:
        sys.path.remove(_DEBIAN)
        raise ImportError("catena needs numpy: install it (Debian: apt-get install python3-numpy)") from e

np = numpy
