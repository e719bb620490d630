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
