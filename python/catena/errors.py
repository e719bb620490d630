"""The exceptions of catena, one small hierarchy:

    CatenaError                 every error of the library
    ├── ModelError              a bad model: .path and .line (the CLI's exit 2)
    ├── NotConvergedError       a solve that did not converge, when asked to raise;
    │                           .solution holds the last converged state (exit 3)
    └── CatenaIOError           a file that cannot be read or written (also an OSError; exit 4)

A Ctrl-C during a read or a solve raises KeyboardInterrupt; the model stays usable.
"""
import re

from . import _catena

# catena status codes (include/catena/core.h)
NOMEM, INVALID, MODEL, IO, LINALG, NOCONV, DOMAIN, INTERRUPTED = range(1, 9)


class CatenaError(Exception):
    """An error of libcatena: .code is its status (catena/core.h), str() its message."""

    def __init__(self, message, code=INVALID):
        super().__init__(message)
        self.message = message
        self.code = code


class ModelError(CatenaError, ValueError):
    """A bad model. The message is what `catena solve` prints after "catena: ", starting
    with "file:line: " when the model came from a file; .path is that file (None for a
    model built in Python and not yet written) and .line the line (an int; 0 when the
    error belongs to no line)."""

    def __init__(self, message, path=None, line=0, code=MODEL):
        super().__init__(message, code)
        self.path = path
        self.line = line


class NotConvergedError(CatenaError):
    """A solve that did not converge (Model.solve(check=True) or Solution.check()).
    .solution is the Solution: its arrays hold the last converged state; .reason names
    why it stopped."""

    def __init__(self, message, solution=None):
        super().__init__(message, NOCONV)
        self.solution = solution
        self.reason = solution.reason if solution is not None else None


class CatenaIOError(CatenaError, OSError):
    """A file that cannot be read or written (.path when known)."""

    def __init__(self, message, path=None, code=IO):
        CatenaError.__init__(self, message, code)
        self.path = path

    def __str__(self):
        return self.message


_LINE = re.compile(r"^(.*?):(\d+): ")


def _where(message, path):
    """(path, line) of a message "file:line: ..."."""
    if path is not None and message.startswith(path + ":"):
        m = re.match(r"(\d+): ", message[len(path) + 1:])
        return path, int(m.group(1)) if m else 0
    m = _LINE.match(message)
    return (m.group(1), int(m.group(2))) if m else (path, 0)


def translate(e, path=None):
    """The catena exception of an _catena.Error(code, message)."""
    code, message = e.args
    if code == MODEL:
        where, line = _where(message, path)
        if path is not None and where == path and not message.startswith(path + ":"):
            message = f"{path}: {message}"
        return ModelError(message, where, line)
    if code == IO:
        return CatenaIOError(message, path)
    return CatenaError(message, code)


def call(fn, *args, path=None):
    """fn(*args), its _catena.Error raised as the catena exception."""
    try:
        return fn(*args)
    except _catena.Error as e:
        raise translate(e, path) from None
