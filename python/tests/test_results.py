"""Results as arrays: load steps, modes against the taut string's closed form, the .vtu
writer, the JSON of the solution."""
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import catena
from conftest import PAPER, ROOT


STEPS = """units kN m
gravity 0 -1 0
material steel E=2.0e8
section strand material=steel A=3.14e-4 w=0.1
node 1 0 0 0 fix=xyz
node 2 200 0 0 fix=xyz
cable 1 2 section=strand n=20 length=200.3340
step self-weight
step point-load substeps=4
load 13 0 -5 0
step pull
displace 2 x=0.5
"""


def test_steps_match_the_json():
    sol = catena.Model.from_string(STEPS, name="steps.cable").solve()
    assert sol.converged and len(sol.steps) == 3
    j = sol.to_dict()
    for st, js in zip(sol.steps, j["steps"]):
        assert st.name == js["name"] and st.converged == js["converged"]
        ref = np.array([[n["ux"], n["uy"], n["uz"]] for n in js["nodes"]])
        assert np.allclose(st.displacements, ref, rtol=0, atol=1e-15 * 200)
        assert np.allclose(st.forces, [e["force"] for e in js["elements"]], rtol=4e-16 * 4, atol=0)
    # the pull moves support 2 by 0.5 along x in the last step only
    assert sol.steps[1].displacements[1, 0] == 0 and sol.steps[2].displacements[1, 0] == 0.5
    # self-weight: the two reactions carry the cable's weight w S
    assert abs(sol.steps[0].reactions[:, 1].sum() - 0.1 * 200.3340) < 1e-9


def test_taut_string_frequencies():
    """A string of tension T and mass m per length between two supports L apart:
    f_k = k / (2 L) sqrt(T / m). 200 elements, consistent mass: converges from above at
    O(h^2); the first three modes within 1e-4."""
    L, T, mass, EA = 10.0, 1000.0, 0.5, 1e9
    n = 200
    x = np.linspace(0, L, n + 1)
    m = catena.Model(units=("N", "m"))
    m.material("wire", E=EA, strain="engineering")
    m.section("s", material="wire", A=1.0, mass=mass)
    m.nodes(np.arange(1, n + 2), np.stack([x, 0 * x, 0 * x], axis=1),
            fix=["xyz"] + ["x"] * (n - 1) + ["xyz"])
    m.elements(np.arange(1, n + 1), np.stack([np.arange(1, n + 1), np.arange(2, n + 2)], axis=1),
               section="s", N0=T)
    sol = m.solve(modes=6)
    modes = sol.modes
    assert sol.converged and len(modes) == 6
    # y and z vibrate alike: the frequencies come in pairs
    f = modes.frequencies[::2]
    exact = np.arange(1, 4) / (2 * L) * np.sqrt(T / mass)
    assert np.all(f >= exact * (1 - 1e-12)) and np.all(f / exact - 1 < 1e-4)
    assert modes.shapes.shape == (6, n + 1, 3)
    assert np.all(modes.shapes[:, 0] == 0) and np.all(modes.shapes[:, -1] == 0)
    assert list(modes.kinds) == ["vibration"] * 6


def test_to_vtu(tmp_path):
    sol = catena.read(PAPER[2]).solve()
    out = tmp_path / "cable.vtu"
    sol.to_vtu(out)
    root = ET.parse(out).getroot()
    piece = root.find(".//Piece")
    assert int(piece.get("NumberOfPoints")) == 21 and int(piece.get("NumberOfCells")) == 20
    with pytest.raises(catena.CatenaIOError):
        sol.to_vtu(tmp_path / "missing" / "dir" / "x.vtu")
    sol.write(tmp_path / "set")
    assert (tmp_path / "set" / "result.json").read_text().rstrip("\n") == sol.to_json()


def test_element_arrays_are_consistent():
    sol = catena.read(PAPER[1]).solve()
    m = sol.model
    xyz = sol.coordinates
    ends = m.element_ends
    assert np.allclose(sol.lengths, np.linalg.norm(xyz[ends[:, 1]] - xyz[ends[:, 0]], axis=1), rtol=1e-14)
    lam = sol.lengths / m.l0
    assert np.allclose(sol.strains, (lam ** 2 - 1) / 2, rtol=1e-10)            # Green-Lagrange
    assert np.allclose(sol.forces, 2.0e8 * 3.14e-4 * sol.strains * lam, rtol=1e-12)
    assert np.allclose(sol.stresses, sol.forces / 3.14e-4, rtol=1e-15)
    assert sol.residual_history.size == sol.iterations + 1
    assert sol.increment_history.size == sol.iterations
    assert sol.stability["stable"] is True


def test_groups_and_cable_targets():
    """A cable set by its sag (docs/format.md, `cable`): the target is reached, the JSON's
    cables and groups are the arrays'."""
    text = """units kN m
gravity 0 0 -1
material steel E=2e8 strain=engineering
section s material=steel A=3.14e-4 w=0.1 mbl=300
node 1 0 0 0 fix=xyz
node 2 200 0 30 fix=xyz
cable 1 2 section=s n=40 sag=12 group=main
"""
    sol = catena.Model.from_string(text, name="sag.cable").solve(check=True)
    (cab,) = sol.cables
    assert cab["target"] == "sag" and abs(cab["target_achieved"] - 12) < 1e-9 * 12
    j = sol.to_dict()
    assert cab["length"] == j["cables"][0]["length"] or abs(cab["length"] - j["cables"][0]["length"]) < 1e-12 * 250
    g = sol.groups()["main"]
    assert g["elements"] == 40 and g["max_force"] == sol.forces.max() and g["min_force"] == sol.forces.min()
    assert g["max_utilisation"] == pytest.approx(sol.utilisation.max(), rel=0, abs=0)
    assert np.allclose(sol.utilisation, sol.forces / 300, rtol=1e-15)
    assert g["weight"] == pytest.approx(0.1 * sol.model.l0.sum(), rel=1e-12)


def test_accessor_errors_are_catena_errors():
    sol = catena.read(PAPER[0]).solve()
    with pytest.raises(catena.CatenaError):
        sol.catenary(0)                          # a cable element, not a catenary
    with pytest.raises(IndexError):
        sol._c.elements(5)                       # a step out of range
    assert sol.modes is None                     # no modal analysis asked
