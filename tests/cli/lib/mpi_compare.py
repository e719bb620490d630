#!/usr/bin/env python3
"""tests/cli/lib/mpi_compare.py SERIAL.json MPI.json RANKS [--verdict]: the JSON of an MPI run
against the serial CHOLMOD run of the same model (tests/cli/mpi.sh, docs/parallel.md).

Every number of the results (nodes, reactions, elements, cables, groups, steps, cases,
modes, ...) equal to 1e-10 relative: |a - b| <= 1e-10 * max(|a|, |b|, s), s the largest
magnitude of the same key over its array (a displacement of 1e-17 beside ones of 1 is
round-off of either solver); the verdicts (converged, reason, stable, the stability's
kind and count) equal; the same keys, plus "ranks" (= RANKS) and "linear_solver" (a
PETSc solver). What tells how the answer was found (iterations, histories, counts of
factorizations and solves, ordering, factor size, BLAS, threads) may differ: MUMPS is not
CHOLMOD. Modes (frequencies and shapes, each shape's sign free) to 1e-8. A run that did
not converge, or --verdict: converged, reason and stable only. Prints the first
differences; exit 1 on any."""
import json
import math
import sys

HOW = {"iterations", "residual_history", "increment_history", "factorizations", "solves",
       "reused_factorizations", "ordering", "factor_nonzeros", "factor_flops", "blas", "threads",
       "solve_threads", "ranks", "linear_solver", "iteration_log",
       "residual", "max_residual",   # an eigenpair's residual: round-off of its solver
       "worst_element",              # the first of equal utilisations (symmetric nets)
       "solver", "lanczos_restarts", "block_size", "block_solves", "max_floor",
       "reused_factor"}              # the modal analysis's eigen-solver (SLEPc under MPI)
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
    """The key's own scale, and no less than 1e-3 of its collection's: a quantity whose
    largest value is a thousand times below the largest of its collection (reactions of
    1e-9 beside ones of 1e3, a torque or an axial force that is zero but for round-off)
    is compared norm-wise with its collection."""
    top = "#" + key.split("/")[1].split("[")[0] if key.count("/") > 1 else "#"
    own = max(sa.get(key, 0.0), sb.get(key, 0.0))
    return max(own, 1e-3 * max(sa.get(top, 0.0), sb.get(top, 0.0)))


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


def repeated_modes(doc):
    """A mode whose frequency another mode shares (to 1e-6) has no unique shape (any
    combination of the pair's is one): its frequency is compared, not what depends on
    the shape (shape, participation, effective mass, node)."""
    modes = doc.get("modes") if isinstance(doc, dict) else None
    if not isinstance(modes, list):
        return
    f = [m.get("frequency", 0.0) if isinstance(m, dict) else 0.0 for m in modes]
    for i, m in enumerate(modes):
        if not isinstance(m, dict):
            continue
        near = [j for j in range(len(f)) if j != i and abs(f[j] - f[i]) <= 1e-6 * max(abs(f[i]), 1e-300)]
        if near:
            for k in ("shape", "participation", "effective_mass"):
                m.pop(k, None)
        m.pop("node", None)        # the largest amplitude's node: a tie on symmetric nets


def shape_values(m):
    return [v for row in m.get("shape", []) if isinstance(row, dict) for k, v in row.items()
            if k != "node" and isinstance(v, (int, float))]


def align_modes(a, b):
    """Each of b's mode shapes given the sign of a's (an eigenvector's sign is free):
    flipped, with its participation factors, when their dot product is negative."""
    ma, mb = a.get("modes"), b.get("modes")
    if not isinstance(ma, list) or not isinstance(mb, list):
        return
    for x, y in zip(ma, mb):
        if not (isinstance(x, dict) and isinstance(y, dict) and "shape" in y):
            continue
        if sum(p * q for p, q in zip(shape_values(x), shape_values(y))) >= 0:
            continue
        for row in y["shape"]:
            for k, v in row.items():
                if k != "node" and isinstance(v, (int, float)):
                    row[k] = -v
        part = y.get("participation")
        if isinstance(part, dict):
            for k, v in part.items():
                part[k] = -v


def verdict_only(a, b, errs):
    """What must agree where the answer itself is round-off (an absurd stiffness) or the
    run did not converge (its last converged state depends on the path)."""
    for k in ("converged", "reason", "stable"):
        if a.get(k) != b.get(k):
            errs.append("%s: %r against %r" % (k, a.get(k), b.get(k)))


def main():
    args = [x for x in sys.argv[1:] if x != "--verdict"]
    a, b = (json.load(open(f)) for f in args[:2])
    ranks = int(args[2])
    errs = []
    if b.get("ranks") != ranks:
        errs.append("ranks: %r, expected %d" % (b.get("ranks"), ranks))
    if not str(b.get("linear_solver", "")).startswith("petsc"):
        errs.append("linear_solver: %r, expected a PETSc solver" % b.get("linear_solver"))
    if "ranks" in a or "linear_solver" in a:
        errs.append("the serial run has ranks or linear_solver")
    for d in (a, b):
        repeated_modes(d)
    align_modes(a, b)
    sa, sb = {}, {}
    scales(a, sa)
    scales(b, sb)
    if "--verdict" in sys.argv or not a.get("converged"):
        verdict_only(a, b, errs)
    else:
        compare(a, b, sa, sb, "", "", errs, TOL)
    for e in errs[:12]:
        print(e)
    return 1 if errs else 0


if __name__ == "__main__":
    sys.exit(main())
