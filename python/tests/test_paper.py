"""The founding paper's four cables from Python equal `catena solve --json` bit for bit.

The CLI prints a number with 15 significant digits when they read back to the same
double, else 17 (cJSON's layout with an exact test). So the JSON of the Python solution
(to_json, the C writer) is byte for byte the CLI's stdout, every number of the arrays,
printed by that rule (below, independent of the C writer), is the JSON's token, and
every token reads back to exactly the array's double."""
import numpy as np
import pytest

import catena
from conftest import PAPER, cli_json, raw_json

def json_text(v):
    """The JSON text of a finite double: 15 digits when they read back to it, else 17."""
    if v == 0:
        return "-0" if np.signbit(v) else "0"
    s = "%1.15g" % v
    if float(s) != v:
        s = "%1.17g" % v
    return s


def same(values, tokens, what):
    values = np.asarray(values, dtype=float).ravel()
    assert len(values) == len(tokens), what
    for v, tok in zip(values.tolist(), tokens):
        assert json_text(v) == tok, f"{what}: {v!r} prints {json_text(v)}, the CLI {tok}"
        assert float(tok) == v, f"{what}: {tok} does not read back to {v!r}"


@pytest.mark.parametrize("path", PAPER, ids=lambda p: p.name)
def test_paper_cable_equals_cli(path):
    text, code = cli_json(path)
    assert code == 0
    sol = catena.read(path).solve()
    assert sol.converged is True
    assert sol.to_json() == text.rstrip("\n")                      # the whole result, byte for byte
    j = raw_json(text)
    assert sol.iterations == int(j["iterations"])
    nodes, elements = j["nodes"], j["elements"]
    assert sol.displacements.shape == (len(nodes), 3) and sol.displacements.dtype == np.float64
    assert sol.forces.shape == (len(elements),) and sol.forces.dtype == np.float64
    same(sol.displacements, [n[k] for n in nodes for k in ("ux", "uy", "uz")], "displacements")
    assert np.array_equal(sol.coordinates, sol.model.coordinates + sol.displacements)
    same(sol.model.coordinates, [n[k] for n in nodes for k in ("x", "y", "z")], "coordinates")
    same(sol.forces, [e["force"] for e in elements], "forces")
    same(sol.stresses, [e["stress"] for e in elements], "stresses")
    same(sol.strains, [e["strain"] for e in elements], "strains")
    same(sol.lengths, [e["length"] for e in elements], "lengths")
    same(sol.residual_history, j["residual_history"], "residual history")
    fixed = {int(r["node"]): r for r in j["reactions"]}
    ids = sol.model.node_ids
    rows = [i for i, nid in enumerate(ids.tolist()) if nid in fixed]
    same(sol.reactions[rows], [fixed[nid][k] for nid in ids[rows].tolist() for k in ("fx", "fy", "fz")], "reactions")
    assert [int(n["id"]) for n in nodes] == ids.tolist()
    assert [int(e["id"]) for e in elements] == sol.model.element_ids.tolist()


def test_arrays_are_views_not_copies():
    sol = catena.read(PAPER[0]).solve()
    d = sol.displacements
    assert not d.flags.owndata and not d.flags.writeable         # the C solution's own memory
    assert sol.steps[-1].displacements.ctypes.data == d.ctypes.data
