"""The optional ecosystem: Solution.to_dataframe() (pandas) and Solution.plot()
(matplotlib), each skipped when its package is absent (neither is a dependency of the
package; Debian's python3-pandas and python3-matplotlib). Checked against the
solution's own arrays and the model's geometry."""
import numpy as np
import pytest

import catena
from conftest import PAPER


@pytest.fixture(scope="module")
def sol():
    return catena.read(PAPER[2]).solve()


def test_to_dataframe(sol):
    pd = pytest.importorskip("pandas")
    df = sol.to_dataframe()
    assert isinstance(df, pd.DataFrame)
    assert np.array_equal(df.index.to_numpy(), sol.model.element_ids)
    assert list(df.columns) == ["force", "stress", "strain", "length", "slack", "utilisation"]
    for col, arr in (("force", sol.forces), ("stress", sol.stresses), ("strain", sol.strains),
                     ("length", sol.lengths), ("utilisation", sol.utilisation)):
        assert df[col].to_numpy().tobytes() == np.asarray(arr, dtype=float).tobytes(), col
    assert np.array_equal(df["slack"].to_numpy(), np.asarray(sol.slack))
    first = sol.to_dataframe(step=0)                       # a step by index
    assert np.array_equal(first["force"].to_numpy(), sol.steps[0].forces)


def test_plot(sol, tmp_path):
    mpl = pytest.importorskip("matplotlib")
    mpl.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection
    ax = sol.plot()
    lc = [c for c in ax.collections if isinstance(c, LineCollection)]
    assert len(lc) == 1
    seg = np.asarray(lc[0].get_segments())                 # (ne, 2, 2): the deformed ends
    xyz = sol.model.coordinates + sol.displacements
    ends = sol.model.element_ends
    assert seg.shape == (len(ends), 2, 2)
    assert np.array_equal(seg[:, 0, :], xyz[ends[:, 0]][:, :2])   # the x-y plane: the span's
    assert np.array_equal(seg[:, 1, :], xyz[ends[:, 1]][:, :2])
    assert np.array_equal(lc[0].get_array(), sol.forces)   # coloured by force
    x0, x1 = ax.get_xlim()
    assert x0 <= xyz[:, 0].min() and x1 >= xyz[:, 0].max()
    ax.figure.savefig(tmp_path / "plot.png")
    assert (tmp_path / "plot.png").stat().st_size > 1000
    scaled = sol.plot(scale=10.0)                          # displacements magnified
    s10 = np.asarray([c for c in scaled.collections if isinstance(c, LineCollection)][0].get_segments())
    assert np.allclose(s10[:, 0, :], (sol.model.coordinates + 10 * sol.displacements)[ends[:, 0]][:, :2])
    plt.close("all")
