"""Models built from numpy arrays: written to .cable, read back by `catena solve` and by
catena.read, they give the same results; against closed forms."""
import numpy as np
import pytest

import catena
from conftest import PAPER, ROOT, cli_json


def paper_model(length):
    """The founding paper's span from keywords (examples/paper/s*.cable)."""
    m = catena.Model(units=("kN", "m"))
    m.material("steel", E=2.0e8)
    m.section("strand", material="steel", A=3.14e-4, w=0.1)
    m.gravity(0, -1, 0)
    m.nodes([1, 2], [[0, 0, 0], [200, 0, 0]], fix="xyz")
    m.cable(1, 2, section="strand", n=20, length=length, shape="arc")
    m.options(method="newton", tol=1e-10, maxit=50)
    return m


@pytest.mark.parametrize("path", PAPER, ids=lambda p: p.name)
def test_paper_from_keywords_equals_the_file(path, tmp_path):
    length = float(path.stem[1:])
    m = paper_model(length)
    out = tmp_path / "paper.cable"
    m.write(out)
    text, code = cli_json(out)
    assert code == 0
    sol = m.solve()
    ref = catena.read(path).solve()
    assert sol.to_json() == text.rstrip("\n")               # the CLI on the written file
    assert np.array_equal(sol.displacements, ref.displacements)
    assert np.array_equal(sol.forces, ref.forces)


def net(nx=12, ny=9, spacing=2.0, prestress=30.0):
    """A flat prestressed cable net from arrays: a grid of nodes, the border fixed, members
    along both directions, a load at every interior node."""
    ii, jj = np.meshgrid(np.arange(nx), np.arange(ny), indexing="ij")
    ids = (ii * ny + jj + 1).ravel()
    X = np.stack([ii.ravel() * spacing, jj.ravel() * spacing, np.zeros(ids.size)], axis=1)
    border = ((ii == 0) | (ii == nx - 1) | (jj == 0) | (jj == ny - 1)).ravel()
    fix = np.where(border, "xyz", "")
    a = np.concatenate([(ids.reshape(nx, ny)[:-1, 1:-1]).ravel(), (ids.reshape(nx, ny)[1:-1, :-1]).ravel()])
    b = np.concatenate([(ids.reshape(nx, ny)[1:, 1:-1]).ravel(), (ids.reshape(nx, ny)[1:-1, 1:]).ravel()])
    m = catena.Model(units=("kN", "m"), name="net.cable")
    m.material("steel", E=1.6e8, strain="engineering")
    m.section("rope", material="steel", A=1.5e-4)
    m.nodes(ids, X, fix=fix)
    m.elements(np.arange(1, a.size + 1), np.stack([a, b], axis=1), section="rope", N0=prestress)
    inner = ids[~border]
    m.loads(inner, np.tile([0.0, 0.0, -1.5], (inner.size, 1)))
    return m, ids, X, border


def test_net_from_arrays_round_trips(tmp_path):
    m, ids, X, border = net()
    path = tmp_path / "net.cable"
    m.write(path)
    back = catena.read(path)
    assert back.to_cable() == m.to_cable()                   # the text, exactly
    assert np.array_equal(back.node_ids, ids) and np.array_equal(back.coordinates, X)
    assert np.array_equal(back.fix != 0, border)
    a, b = m.solve(), back.solve()
    assert a.converged and np.array_equal(a.displacements, b.displacements) and np.array_equal(a.forces, b.forces)
    text, code = cli_json(path)
    assert code == 0 and b.to_json() == text.rstrip("\n")


def test_net_equilibrium():
    """The support reactions carry the applied load (sum over the supports = -sum of loads)."""
    m, ids, X, border = net()
    sol = m.solve()
    total_load = np.array([0.0, 0.0, -1.5]) * (~border).sum()
    assert np.allclose(sol.reactions.sum(axis=0), -total_load, rtol=1e-9, atol=1e-9)
    assert np.all(sol.reactions[~border] == 0)
    assert np.all(sol.forces > 0)


def test_prestress_returns_without_load():
    """Bracing rods prestressed to N0 = 25 (docs/format.md, `element`): a solve without load
    returns 25 kN in every member to round-off."""
    m = catena.Model(units=("kN", "m"))
    m.material("steel", E=2.0e8, tension_only=True)
    m.section("rod", material="steel", A=2e-4)
    m.nodes([1, 2, 3, 4, 5], [[0, 0, 0], [8, 0, 0], [0, 6, 0], [8, 6, 0], [4, 3, 0]],
            fix=["xyz", "xyz", "xyz", "xyz", "z"])
    m.elements([1, 2, 3, 4], [[1, 5], [5, 4], [2, 5], [5, 3]], section="rod", N0=25)
    assert "tension-only" in m.to_cable()
    sol = m.solve()
    assert sol.converged and np.allclose(sol.forces, 25.0, rtol=1e-12)
    assert not sol.slack.any()


def test_two_bar_truss_closed_form():
    """Two springs k from supports at (+-a, 0) to a node loaded by P down: in equilibrium
    P = 2 k (l - l0) y / l with l = sqrt(a^2 + y^2) (exact, engineering law)."""
    k, a, P = 1000.0, 3.0, 50.0
    m = catena.Model()
    m.nodes([1, 2, 3], [[-a, 0, 0], [a, 0, 0], [0, -1, 0]], fix=["xyz", "xyz", "z"])
    m.elements([1, 2], [[1, 3], [2, 3]], family="spring", k=k)
    m.load(3, 0, -P, 0)
    sol = m.solve()
    y = -(sol.coordinates[2, 1])
    l = np.hypot(a, y)
    l0 = np.hypot(a, 1.0)
    assert sol.converged
    assert abs(2 * k * (l - l0) * y / l - P) < 1e-9 * P
    assert np.allclose(sol.forces, k * (l - l0), rtol=1e-10)


def test_keywords_check():
    m = catena.Model()
    with pytest.raises(ValueError):
        m.material("a b", E=1)
    with pytest.raises(catena.ModelError) as e:
        catena.Model.from_string("units kN m\nmaterial steel E=-1\n", name="bad.cable")
    assert e.value.line == 2 and e.value.path == "bad.cable"
