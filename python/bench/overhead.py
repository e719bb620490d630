"""Overhead of Python over the catena command (issue 24): a cable net of about 1e5
members built from numpy arrays and solved from Python, against `catena solve` of the
same model written as .cable, in paired runs (alternating, the median of each).
    PYTHONPATH=DIR python3 python/bench/overhead.py build/catena [RUNS] [N]
Prints the times and the ratio; also the peak memory (ru_maxrss) of a solve in a fresh
Python process next to the CLI's."""
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import catena


def net(n):
    ii, jj = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    ids = (ii * n + jj + 1).ravel()
    X = np.stack([ii.ravel() * 2.0, jj.ravel() * 2.0, np.zeros(ids.size)], axis=1)
    border = ((ii == 0) | (ii == n - 1) | (jj == 0) | (jj == n - 1)).ravel()
    g = ids.reshape(n, n)
    ends = np.concatenate([np.stack([g[:-1, 1:-1].ravel(), g[1:, 1:-1].ravel()], axis=1),
                           np.stack([g[1:-1, :-1].ravel(), g[1:-1, 1:].ravel()], axis=1)])
    m = catena.Model(units=("kN", "m"), name="net.cable")
    m.material("strand", E=1.6e8, strain="engineering")
    m.section("rope", material="strand", A=1.5e-4)
    m.nodes(ids, X, fix=np.where(border, "xyz", ""))
    m.elements(np.arange(1, len(ends) + 1), ends, section="rope", N0=30.0)
    m.loads(ids[~border], [0.0, 0.0, -1.5])
    return m


def python_run(n):
    t0 = time.perf_counter()
    sol = net(n).solve(check=True)
    f = sol.forces
    return time.perf_counter() - t0, f


def cli_run(cli, path):
    t0 = time.perf_counter()
    subprocess.run([cli, "solve", path, "--quiet"], check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - t0


def main():
    cli = sys.argv[1]
    runs = int(sys.argv[2]) if len(sys.argv) > 2 else 5
    n = int(sys.argv[3]) if len(sys.argv) > 3 else 225
    if n < 0:   # child: one solve, its peak memory before and after reading every result
        sol = net(-n).solve(check=True)
        before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
        arrays = [sol.displacements, sol.reactions, sol.coordinates, sol.forces, sol.stresses, sol.strains,
                  sol.lengths, sol.slack, sol.utilisation]
        after = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
        print(before, after, sum(a.nbytes for a in arrays))
        return
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "net.cable")
        m = net(n)
        m.write(path)
        print(f"net {n} x {n}: {len(m.node_ids)} nodes, {len(m)} members")
        py, cl = [], []
        for _ in range(runs):
            py.append(python_run(n)[0])
            cl.append(cli_run(cli, path))
        p, c = statistics.median(py), statistics.median(cl)
        print(f"python (build from arrays + solve): median {p:.3f} s  runs {[round(t, 3) for t in py]}")
        print(f"catena solve --quiet (read + solve): median {c:.3f} s  runs {[round(t, 3) for t in cl]}")
        print(f"ratio {p / c:.3f}")
        before, after, nbytes = map(int, subprocess.run([sys.executable, __file__, cli, "1", str(-n)],
                                                        capture_output=True, text=True, check=True).stdout.split())
        r = subprocess.run(["/usr/bin/time", "-f", "%M", cli, "solve", path, "--quiet"], capture_output=True, text=True)
        print(f"peak memory: python after the solve {before / 1024:.1f} MB, after reading every result array "
              f"{after / 1024:.1f} MB (+{100 * (after - before) / before:.1f} %; the arrays {nbytes / 2**20:.1f} MB); "
              f"catena solve {int(r.stderr.split()[-1]) / 1024:.1f} MB")


if __name__ == "__main__":
    main()
