#!/usr/bin/env python3
"""bench/corpus_starts.py NEW OLD [MODEL...]: every example and tests model (examples/*/
*.cable, tests/models/*/*.cable; or the MODELs given) solved by both builds with default
settings as the file states them (`catena solve MODEL --json`): the iterations of the
model's steps and of each case and combination, new against old, and the largest
difference of the --json answers (every number but the iteration counts, histories,
timings and factorization figures), relative to the largest magnitude of that key in the
file. Prints one line per model and a summary; exit 1 if a model takes more iterations
with NEW than with OLD, converges with OLD and not with NEW, or an answer moves by more
than 1e-6 (CORPUS_TOL)."""
import glob, json, math, os, subprocess, sys

SKIP = {"iterations", "residual_history", "increment_history", "factorizations", "solves",
        "reused_factorizations", "cutbacks", "factor_nonzeros", "factor_flops", "threads",
        "solve_threads", "blas", "ordering", "timings", "residual_floor", "preshaped"}
TOL = float(os.environ.get("CORPUS_TOL", "1e-6"))


def run(binary, model):
    try:
        p = subprocess.run([binary, "solve", os.path.basename(model), "--json"], cwd=os.path.dirname(model) or ".",
                           capture_output=True, text=True, timeout=600)
        return json.loads(p.stdout), p.returncode
    except Exception:
        return None, -1


def counts(d):
    """[('steps', its), (case name, its), ...]"""
    if d is None:
        return []
    out = [("steps", d.get("iterations"), d.get("converged"))]
    for k in ("cases", "combinations"):
        for c in d.get(k) or []:
            out.append((c["name"], c.get("iterations"), c.get("converged")))
    return out


def leaves(x, path, out):
    if isinstance(x, dict):
        for k, v in x.items():
            if k in SKIP or k.startswith("t_"):
                continue
            leaves(v, path + (k,), out)
    elif isinstance(x, list):
        for i, v in enumerate(x):
            leaves(v, path + (i,), out)
    elif isinstance(x, (int, float)) and not isinstance(x, bool):
        out[path] = float(x)


def diff(a, b):
    la, lb = {}, {}
    leaves(a, (), la)
    leaves(b, (), lb)
    if set(la) != set(lb):
        return math.inf, "different keys"
    scale = {}
    for p, v in list(la.items()) + list(lb.items()):
        key = [q for q in p if isinstance(q, str)][-1] if any(isinstance(q, str) for q in p) else ""
        scale[key] = max(scale.get(key, 0.0), abs(v) if math.isfinite(v) else 0.0)
    worst, where = 0.0, ""
    for p, v in la.items():
        w = lb[p]
        key = [q for q in p if isinstance(q, str)][-1] if any(isinstance(q, str) for q in p) else ""
        s = scale[key] or 1.0
        e = abs(v - w) / s if math.isfinite(v) and math.isfinite(w) else (0.0 if v == w else math.inf)
        if e > worst:
            worst, where = e, "/".join(str(q) for q in p)
    return worst, where


def main():
    new, old = sys.argv[1], sys.argv[2]
    root = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
    models = sys.argv[3:] or sorted(glob.glob(root + "/examples/*/*.cable") + glob.glob(root + "/tests/models/*/*.cable"))
    bad = 0
    tot_new = tot_old = 0
    for m in models:
        m = os.path.abspath(m)
        dn, rn = run(os.path.abspath(new), m)
        do, ro = run(os.path.abspath(old), m)
        cn, co = counts(dn), counts(do)
        worse = []
        rows = []
        for (name, itn, okn), (_, ito, oko) in zip(cn, co):
            rows.append("%s %s/%s%s" % (name, itn, ito, "" if okn else "(not converged)"))
            if itn is not None and ito is not None:
                tot_new += itn
                tot_old += ito
                if (itn > ito and okn == oko) or (oko and not okn):
                    worse.append(name)
        e, where = diff(dn, do) if dn is not None and do is not None else (0.0 if dn is do else math.inf, "no json")
        flag = "WORSE " + ",".join(worse) if worse else ""
        if e > TOL:
            flag += " MOVED %.2g at %s" % (e, where)
        if worse or e > TOL or rn != ro:
            bad += 1
        print("%-48s exit %d/%d  %s  answers %.2g %s" % (os.path.relpath(m, root), rn, ro, "; ".join(rows), e, flag))
    print("total iterations new %d old %d; %d models flagged" % (tot_new, tot_old, bad))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
