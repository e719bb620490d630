"""One whole process of the paired runs of issue 24's overhead (farm-bench times the
process from outside, interpreter start and imports included): overhead.py's net of
N x N nodes built from numpy arrays and solved from Python (the result arrays read;
--cli-heap: after catena.use_cli_heap(), the command's process-wide heap settings), or
with --write PATH the same model written as .cable for `catena solve PATH --quiet`.
    PYTHONPATH=DIR python3 python/bench/net_solve.py N [--write PATH | --cli-heap]
    farm-bench -n 5 -- python3 python/bench/net_solve.py 225 --vs 'build/catena solve net.cable --quiet'"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from overhead import net  # noqa: E402


def main():
    n = int(sys.argv[1])
    if "--cli-heap" in sys.argv[2:]:
        import catena
        catena.use_cli_heap()
    m = net(n)
    if len(sys.argv) > 3 and sys.argv[2] == "--write":
        m.write(sys.argv[3])
        return
    sol = m.solve(check=True)
    assert sol.forces.shape == (len(m),) and sol.displacements.shape == (n * n, 3)


if __name__ == "__main__":
    main()
