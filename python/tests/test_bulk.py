"""Models built from arrays reach the library in bulk (ctn_model_add_nodes,
ctn_model_add_elements, the loads in one C loop: no .cable text for the arrays), and
are the model of their text: solved, the same JSON bit for bit as the file written by
model.write() and read back; errors in the rows are the reader's, on the row's line."""
import numpy as np
import pytest

import catena
from test_build import net


def reader_error(m):
    """The reader's ModelError for the model's text (the independent route)."""
    with pytest.raises(catena.ModelError) as e:
        catena.Model.from_string(m.to_cable(), m.name).solve()
    return e.value


def bulk_error(m):
    with pytest.raises(catena.ModelError) as e:
        m.solve()
    return e.value


def test_net_in_bulk_equals_the_file(tmp_path):
    m, ids, X, border = net(nx=14, ny=11)
    sol = m.solve()
    assert m._bulk == 3                                      # nodes, elements, loads
    path = tmp_path / "net.cable"
    m.write(path)
    ref = catena.read(path).solve()
    assert sol.converged and ref.converged
    assert sol.to_json() == ref.to_json()                    # every number, bit for bit
    for a in ("displacements", "reactions", "forces", "stresses", "lengths"):
        assert getattr(sol, a).tobytes() == getattr(ref, a).tobytes(), a
    assert np.array_equal(m.node_ids, ids) and np.array_equal(m.fix != 0, border)


def test_every_bulk_key(tmp_path):
    """Springs with k per row, cable elements with l0 per row, fix as a bool array, masses,
    a group: the bulk model equals the file's, tables and results."""
    m = catena.Model(units=("kN", "m"), gravity=(0, 0, -1), name="keys.cable")
    m.material("steel", E=2.0e8)
    m.section("rope", material="steel", A=2e-4, w=0.05)
    X = np.array([[0, 0, 0], [3, 0, 0], [6, 0, 0], [9, 0, 0], [3, 1, 0], [6, 1, 0]], dtype=float)
    fix = np.zeros((6, 3), dtype=bool)
    fix[[0, 3]] = True
    fix[[4, 5]] = True
    m.nodes(np.arange(1, 7), X, fix=fix, mass=np.array([0, 1.5, 2.5, 0, 0, 0]))
    m.elements([1, 2, 3], [[1, 2], [2, 3], [3, 4]], section="rope", l0=np.array([2.999, 2.998, 2.999]), group="span")
    m.elements([4, 5], [[2, 5], [3, 6]], family="spring", k=np.array([50.0, 70.0]), l0=0.9)
    m.loads([2, 3], [[0, 0, -2.0], [0, 0.5, -1.0]])
    m.modes(2)
    sol = m.solve()
    assert m._bulk == 4
    path = tmp_path / "keys.cable"
    m.write(path)
    back = catena.read(path)
    ref = back.solve()
    assert sol.converged and sol.to_json() == ref.to_json()
    assert np.array_equal(m.l0, back.l0) and np.array_equal(m.fix, back.fix)
    assert sol.modes.frequencies.tobytes() == ref.modes.frequencies.tobytes()   # the masses


@pytest.mark.parametrize("case", ["dup_node", "undefined_node", "undefined_section", "dup_element", "node_zero",
                                  "bad_fix", "l0_negative"])
def test_row_errors_are_the_readers(case):
    m, ids, X, border = net(nx=5, ny=4)
    nodes, elements = m._lines[3], m._lines[4]               # units material section nodes elements
    if case == "dup_node":
        nodes.ids = nodes.ids.copy()
        nodes.ids[7] = nodes.ids[2]
    elif case == "undefined_node":
        elements.conn = elements.conn.copy()
        elements.conn[4, 1] = 999
    elif case == "undefined_section":
        elements.keys["section"] = elements.words["section"] = "wire"
    elif case == "dup_element":
        elements.ids = elements.ids.copy()
        elements.ids[5] = elements.ids[1]
    elif case == "node_zero":                                # the reader's route: its id rule
        nodes.ids = nodes.ids.copy()
        nodes.ids[3] = 0
    elif case == "bad_fix":
        nodes.fix = nodes.fix.copy()
        nodes.fix[2] = "xq"
    elif case == "l0_negative":
        m.elements([100], [[1, 2]], section="rope", l0=np.array([-1.0]))
    want = reader_error(m)
    got = bulk_error(m)
    assert str(got) == str(want) and got.line == want.line and got.path == want.path == "net.cable"
    assert got.line > 3 and f"net.cable:{got.line}: " in str(got)
    assert m.to_cable().splitlines()[got.line - 1].split()[0] in ("node", "element")


def test_bulk_build_is_not_a_text_round_trip():
    """The arrays do not become text: a net's bulk compile formats no line."""
    m, ids, X, border = net(nx=8, ny=8)
    for part in m._lines:
        if not isinstance(part, str):
            part.lines = None                                # would fail if called
    assert m.solve().converged and m._bulk == 3


def test_use_cli_heap_changes_no_result():
    """catena.use_cli_heap() (process-wide: in a child process) leaves every number as it is."""
    import subprocess
    import sys
    from conftest import PAPER
    code = ("import sys, catena; ok = catena.use_cli_heap(); "
            "sys.stdout.write(str(ok) + '\\n' + catena.read(sys.argv[1]).solve().to_json())")
    r = subprocess.run([sys.executable, "-c", code, str(PAPER[2])], capture_output=True, text=True, check=True)
    ok, text = r.stdout.split("\n", 1)
    assert ok == "True" and text == catena.read(PAPER[2]).solve().to_json()


def families_model(bad=None):
    """Beams (meshed, an orient per row, a release), catenaries with an H per row, a pulley
    of four nodes and a rotational spring, each family a block of arrays; bad: one row
    made wrong (the reader's message expected)."""
    m = catena.Model(units=("kN", "m"), gravity=(0, 0, -1), name="fam.cable")
    m.material("m", E=2e8, G=7.7e7)
    m.material("rope", E=1e5, strain="engineering")
    m.section("b", material="m", A=1e-2, Iy=1e-4, Iz=2e-4, J=3e-4, w=0.5)
    m.section("r", material="rope", A=0.01, w=0.01)
    X = np.array([[0, 0, 0], [6, 0, 0], [12, 0, 0], [0, 5, 0], [30, 5, 2], [0, 9, 0], [40, 9, 0],
                  [0, 20, 0], [4, 20, 0], [8, 20, 3], [8, 20, -2], [12, 0, -3]], dtype=float)
    ids = np.array([1, 2, 3, 4, 5, 6, 7, 11, 12, 13, 14, 21])
    fix = np.array(["xyzrxryrz", "", "xyzrxryrz", "xyz", "xyz", "xyz", "xyz", "xyz", "xyz", "xyz", "", "xyzrxryrz"])
    m.nodes(ids, X, fix=fix)
    conn = np.array([[1, 2], [2, 3]])
    if bad == "beam":
        conn[1, 1] = 98
    m.elements([1, 2], conn, family="beam", section="b", orient=np.array([[0, 0, 1], [0, 1, 1.0]]), n=3,
               release="2:ryrz")
    m.elements([3, 4], [[4, 5], [6, 7]], family="catenary", section="wire" if bad == "catenary" else "r",
               H=np.array([5.0, 8.0]), group="cat")
    m.elements([5], [[11, 12, 13, 99 if bad == "pulley" else 14]], family="pulley", section="r", length=15.0)
    m.elements([6], [[3, 21]], family="rspring", k=40.0)
    m.loads([14], [[0, 0, -20.0]])
    return m


def test_every_family_in_bulk(tmp_path):
    """Each family's block goes in bulk, and solves to the file's JSON bit for bit."""
    m = families_model()
    sol = m.solve()
    assert m._bulk == 6                                      # nodes, four element blocks, loads
    path = tmp_path / "fam.cable"
    m.write(path)
    back = catena.read(path)
    ref = back.solve()
    assert sol.converged and ref.converged
    assert sol.to_json() == ref.to_json()
    assert np.array_equal(m.l0, back.l0)                     # the catenaries' lengths found
    assert len(sol.forces) == 10                             # 2 x 3 beams, 2, 1, 1


@pytest.mark.parametrize("bad", ["beam", "catenary", "pulley"])
def test_family_row_errors_are_the_readers(bad):
    m = families_model(bad)
    want = reader_error(m)
    got = bulk_error(m)
    assert str(got) == str(want) and got.line == want.line and got.path == want.path == "fam.cable"
    assert m.to_cable().splitlines()[got.line - 1].split()[0] in ("beam", "catenary", "pulley")


def test_rows_the_bulk_route_refuses_go_as_text():
    """A zero orient (the spec's default, the reader's error), a release the reader refuses,
    n=0: those blocks go through the reader, with its message."""
    for keys, msg in (({"orient": "0,0,0"}, "orient must not be the zero vector"),
                      ({"release": "3:rx"}, "release must be END:DOFS"),
                      ({"n": 0}, "n must be an integer from 1")):
        m = families_model()
        blk = m._lines[[i for i, p in enumerate(m._lines) if getattr(p, "family", "") == "beam"][0]]
        blk.keys.update(keys)
        blk.words.update({k: str(v) for k, v in keys.items()})
        got = bulk_error(m)
        assert msg in str(got) and str(got) == str(reader_error(m)), (keys, str(got))
