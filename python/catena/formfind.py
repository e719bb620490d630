"""Form finding by force density (Schek), as `catena formfind` does it."""
import os
import tempfile

from . import _catena, errors
from .model import Model, _main_thread


def formfind(model, path=None, tol=None, maxit=None):
    """Find the shape of a model whose members carry q= (force density) or force=
    (target force): -> (found Model, report dict).

    The found model is the source's text with the free nodes moved to the shape found and
    every member's l0= for its force (`catena formfind -o`), written to path (or a
    temporary file, removed) and read back, so that found.solve() is the load analysis of
    the found net and found.write() writes it. report: converged, reason, iterations,
    force_mismatch, residual, force_min, force_max, ... A shape not found (maxit, stalled)
    raises NotConvergedError with the report in .report; a bad model ModelError."""
    if isinstance(model, (str, os.PathLike)):
        model = Model.read(model)
    text = model.to_cable()
    tmp = None
    if path is None:
        fd, tmp = tempfile.mkstemp(suffix=".cable")
        os.close(fd)
    out = os.fspath(path) if path is not None else tmp
    try:
        rep = errors.call(_catena.formfind, model.path or model.name, text, out, tol or -1.0, maxit or -1,
                          _main_thread(), path=model.path or model.name)
        if not rep["converged"]:
            e = errors.NotConvergedError(f"form finding: {rep['reason']}")
            e.report = rep
            raise e
        if path is not None:
            return Model.read(out), rep
        with open(out, encoding="utf-8") as f:
            return Model.from_string(f.read(), name=model.name + ".found"), rep
    finally:
        if tmp is not None and os.path.exists(tmp):
            os.unlink(tmp)
