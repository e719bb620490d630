"""catena.analytic: the closed forms from Python, checked against their own equations and
against the finite elements."""
import math

import numpy as np
import pytest

import catena


def test_catenary_equations():
    l, h, w, S = 200.0, 0.0, 0.1, 250.8777
    c = catena.analytic.catenary(l, h, w, S)
    # c solves sqrt(S^2 - h^2) = 2 c sinh(l / (2 c))
    assert abs(2 * c.c * math.sinh(l / (2 * c.c)) - math.sqrt(S * S - h * h)) < 1e-10 * S
    assert abs(c.H - w * c.c) < 1e-12 * c.H
    assert c.y[0] == pytest.approx(0, abs=1e-12) and c.y[-1] == pytest.approx(h, abs=1e-9)
    assert c.reaction_left[1] + c.reaction_right[1] == pytest.approx(w * S, rel=1e-12)
    assert c.T_max == pytest.approx(c.T.max(), rel=1e-12)
    # level span: T = H cosh((x - l/2) / c)
    assert np.allclose(c.T, c.H * np.cosh((c.x - l / 2) / c.c), rtol=1e-12)


def test_elastic_catenary_against_fea():
    """The paper's span with engineering strain in 400 elements: the FE horizontal reaction
    and mid-span sag approach Irvine's elastic catenary (O(h^2): within 1e-4)."""
    EA, w, L0 = 2.0e8 * 3.14e-4, 0.1, 250.8777
    ec = catena.analytic.elastic_catenary(200.0, 0.0, w, EA, L0, x=[100.0])
    m = catena.Model(units=("kN", "m"), gravity=(0, -1, 0))
    m.material("steel", E=2.0e8, strain="engineering").section("s", material="steel", A=3.14e-4, w=w)
    m.nodes([1, 2], [[0, 0, 0], [200, 0, 0]], fix="xyz").cable(1, 2, section="s", n=400, length=L0)
    sol = m.solve(check=True)
    assert abs(abs(sol.reactions[0, 0]) - ec.H) < 1e-4 * ec.H
    assert abs(-sol.coordinates[:, 1].min() - ec.sag_mid) < 1e-4 * ec.sag_mid
    assert ec.y[0] == pytest.approx(-ec.sag_mid, rel=1e-12)


def test_parabola_sag():
    p = catena.analytic.parabola(100.0, 0.0, 2.0, 102.0)
    assert p.sag_mid == pytest.approx(2.0 * 100.0 ** 2 / (8 * p.H), rel=1e-12)


def test_no_solution_is_an_error():
    with pytest.raises(catena.CatenaError):
        catena.analytic.catenary(200.0, 0.0, 0.1, 199.0)      # shorter than the chord


def test_catenary_element_is_irvines():
    """One `catenary` element over the paper's span (any EA, w) gives Irvine's H, V and
    sag, as the closed form solved from the unstressed length does."""
    EA, w, L0 = 2.0e8 * 3.14e-4, 0.1, 250.8777
    m = catena.Model(units=("kN", "m"), gravity=(0, -1, 0))
    m.material("steel", E=2.0e8).section("s", material="steel", A=3.14e-4, w=w)
    m.nodes([1, 2], [[0, 0, 0], [200, 30, 0]], fix="xyz")
    m.elements([1], [[1, 2]], family="catenary", section="s", length=L0)
    sol = m.solve(check=True)
    ec = catena.analytic.elastic_catenary(200.0, 30.0, w, EA, L0)
    r = sol.catenary(0)
    assert r["H"] == pytest.approx(ec.H, rel=1e-10)
    assert r["V"][0] == pytest.approx(ec.V_left, rel=1e-10)
    assert r["stretched_length"] == pytest.approx(ec.length, rel=1e-10)
    pts = sol.element_shape(0, n=5)
    assert pts.shape == (5, 3) and np.allclose(pts[0], [0, 0, 0]) and np.allclose(pts[-1], [200, 30, 0])
    assert sol.reactions[0, 0] == pytest.approx(-ec.H, rel=1e-10)
