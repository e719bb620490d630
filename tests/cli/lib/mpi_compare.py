#!/usr/bin/env python3
"""tests/cli/lib/mpi_compare.py SERIAL.json MPI.json RANKS: the JSON of an MPI run
against the serial CHOLMOD run of the same model (tests/cli/mpi.sh, docs/parallel.md).

Every number of the results (nodes, reactions, elements, cables, groups, steps, cases,
modes, ...) equal to 1e-10 relative: |a - b| <= 1e-10 * max(|a|, |b|, s), s the largest
magnitude of the same key over its array (a displacement of 1e-17 beside ones of 1 is
round-off of either solver); the verdicts (converged, reason, stable, the stability's
kind and count) equal; the same keys, plus "ranks" (= RANKS) and "linear_solver" (a
PETSc solver). What tells how the answer was found (iterations, histories, counts of
factorizations and solves, ordering, factor size, BLAS, threads) may differ: MUMPS is not
CHOLMOD. Modes (frequencies and shapes, each shape's sign free) to 1e-8. Prints the
first differences; exit 1 on any."""
import json
import math
import sys

HOW = {"iterations", "residual_history", "increment_history", "factorizations", "solves",
       "reused_factorizations", "ordering", "factor_nonzeros", "factor_flops", "blas", "threads",
       "solve_threads", "ranks", "linear_solver", "iteration_log",
       "residual", "max_residual",   # an eigenpair's residual: round-off of its solver
       "worst_element"}              # the first of equal utilisations (symmetric nets)
TOL = 1e-10
MODE_TOL = 1e-8


def group(k):
    """A key's group: the components of one vector together (dx, dy, dz; fx, fy, fz)."""
    return k[:-1] + "?" if len(k) <= 3 and k[-1:] in ("x", "y", "z") else k


def scales(v, out, path=""):
    """Largest |number| per key path (list indices dropped, vector components grouped),
    and per collection (the top-level key) under "#" + its name."""
    if isinstance(v, dict):
        for k, x in v.items():
            scales(x, out, path + "/" + group(k))
    elif isinstance(v, list):
        for x in v:
            scales(x, out, path + "[]")
    elif isinstance(v, (int, float)) and not isinstance(v, bool):
        out[path] = max(out.get(path, 0.0), abs(v))
        top = "#" + path.split("/")[1].split("[")[0] if path.count("/") > 1 else "#"
        out[top] = max(out.get(top, 0.0), abs(v))


def scale_of(sa, sb, key):
    """The key's own scale, and no less than 1e-6 of its collection's: a value a million
    times below the largest of its collection (a reaction of 1e-9 beside ones of 1e3, a
    torque that is zero but for round-off) is round-off of either solver."""
    top = "#" + key.split("/")[1].split("[")[0] if key.count("/") > 1 else "#"
    own = max(sa.get(key, 0.0), sb.get(key, 0.0))
    return max(own, 1e-6 * max(sa.get(top, 0.0), sb.get(top, 0.0)))


def compare(a, b, sa, sb, path, key, errs, tol):
    if len(errs) > 12:
        return
    if isinstance(a, dict) and isinstance(b, dict):
        ka, kb = set(a) - HOW, set(b) - HOW
        if ka != kb:
            errs.append("%s: keys differ: %s" % (path or "/", sorted(ka ^ kb)))
        for k in sorted(ka & kb):
            t = MODE_TOL if k in ("modes", "frequencies", "shapes") or tol == MODE_TOL else tol
            compare(a[k], b[k], sa, sb, path + "/" + k, key + "/" + group(k), errs, t)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            errs.append("%s: %d entries against %d" % (path, len(a), len(b)))
            return
        for i, (x, y) in enumerate(zip(a, b)):
            compare(x, y, sa, sb, "%s[%d]" % (path, i), key + "[]", errs, tol)
    elif isinstance(a, bool) or isinstance(b, bool) or isinstance(a, str) or isinstance(b, str):
        if a != b:
            errs.append("%s: %r against %r" % (path, a, b))
    elif isinstance(a, (int, float)) and isinstance(b, (int, float)):
        s = scale_of(sa, sb, key)
        if not (math.isfinite(a) and math.isfinite(b)) or abs(a - b) > tol * max(abs(a), abs(b), s):
            errs.append("%s: %.17g against %.17g (scale %.3g)" % (path, a, b, s))
    elif a != b:
        errs.append("%s: %r against %r" % (path, a, b))


def signless_modes(doc):
    """Each mode shape's sign set by its largest component (eigenvectors' sign is free)."""
    modes = doc.get("modes") if isinstance(doc, dict) else None
    if not isinstance(modes, dict):
        return
    for m in modes.get("modes", []) if isinstance(modes.get("modes"), list) else []:
        shape = m.get("shape") if isinstance(m, dict) else None
        if not isinstance(shape, list):
            continue
        flat = [x for row in shape for x in (row if isinstance(row, list) else [row])
                if isinstance(x, (int, float))]
        if flat and max(flat, key=abs) < 0:
            m["shape"] = [[-x for x in row] if isinstance(row, list) else -row for row in shape]


def main():
    a, b = (json.load(open(f)) for f in sys.argv[1:3])
    ranks = int(sys.argv[3])
    errs = []
    if b.get("ranks") != ranks:
        errs.append("ranks: %r, expected %d" % (b.get("ranks"), ranks))
    if not str(b.get("linear_solver", "")).startswith("petsc"):
        errs.append("linear_solver: %r, expected a PETSc solver" % b.get("linear_solver"))
    if "ranks" in a or "linear_solver" in a:
        errs.append("the serial run has ranks or linear_solver")
    signless_modes(a)
    signless_modes(b)
    sa, sb = {}, {}
    scales(a, sa)
    scales(b, sb)
    compare(a, b, sa, sb, "", "", errs, TOL)
    for e in errs[:12]:
        print(e)
    return 1 if errs else 0


if __name__ == "__main__":
    sys.exit(main())
