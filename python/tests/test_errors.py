"""Errors are exceptions that carry what the CLI prints: every case of the malformed-input
corpus (tests/errors/, "# expect: CODE: SUBSTRING" on its first line) gives, from Python,
the exception of its exit code (2 ModelError with .path and .line, 3 a solution that did
not converge, 4 CatenaIOError), with the CLI's message."""
import re

import pytest

import catena
from conftest import ROOT, cli_json

CASES = sorted((ROOT / "tests" / "errors").glob("*.cable"))


def expectation(path):
    first = path.read_text(errors="replace").splitlines()[0]
    m = re.match(r"# expect: (\d+): ?(.*)", first)
    return (int(m.group(1)), m.group(2)) if m else (None, None)


def run(path):
    """('model' | 'noconv' | 'io' | 'ok', exception or solution)."""
    try:
        sol = catena.read(str(path)).solve()
    except catena.ModelError as e:
        return "model", e
    except catena.CatenaIOError as e:
        return "io", e
    return ("ok" if sol.converged else "noconv"), sol


@pytest.mark.parametrize("path", CASES, ids=lambda p: p.name)
def test_corpus_case(path):
    code, substring = expectation(path)
    if code is None:
        pytest.skip("no expect line")
    kind, r = run(path)
    assert kind == {0: "ok", 2: "model", 3: "noconv", 4: "io"}[code], f"{path.name}: {kind}: {r}"
    if code in (2, 4):
        for piece in substring.split(" ... "):
            assert piece.replace("FILE", str(path)) in str(r), f"{path.name}: {r}"
    if code == 2:
        m = re.search(r"FILE:(\d+):", substring)
        if m:
            assert r.path == str(path) and r.line == int(m.group(1)) and isinstance(r.line, int)
        assert str(r).startswith(str(path) + ":")


def test_message_is_the_clis():
    path = ROOT / "tests" / "errors" / "area_negative.cable"
    with pytest.raises(catena.ModelError) as e:
        catena.read(path)
    import subprocess
    r = subprocess.run([str(__import__("conftest").CLI), "solve", str(path)], capture_output=True, text=True)
    assert r.returncode == 2
    assert r.stderr.strip() == "catena: " + str(e.value)
    assert isinstance(e.value, catena.CatenaError) and e.value.line > 0


def test_missing_file_is_io_error(tmp_path):
    with pytest.raises(catena.CatenaIOError) as e:
        catena.read(tmp_path / "none.cable")
    assert isinstance(e.value, OSError) and isinstance(e.value, catena.CatenaError)


def test_not_converged_carries_last_state():
    text = (ROOT / "examples" / "paper" / "s250.8777.cable").read_text()
    m = catena.Model.from_string(text.replace("maxit=50", "maxit=2"), name="short.cable")
    sol = m.solve()
    assert sol.converged is False
    _, code = cli_json_text(text.replace("maxit=50", "maxit=2"))
    assert code == 3
    with pytest.raises(catena.NotConvergedError) as e:
        m.solve(check=True)
    assert e.value.solution.converged is False and e.value.solution.displacements.shape == (21, 3)


def cli_json_text(text):
    import tempfile, os
    with tempfile.NamedTemporaryFile("w", suffix=".cable", delete=False) as f:
        f.write(text)
    try:
        return cli_json(f.name)
    finally:
        os.unlink(f.name)


def test_bad_option():
    m = catena.read(ROOT / "examples" / "paper" / "s200.3340.cable")
    with pytest.raises(TypeError):
        m.solve(frobnicate=1)
    with pytest.raises(ValueError):
        m.solve(method="bisection")
    with pytest.raises(catena.CatenaError):
        m.solve(tol=-1)
    assert m.solve().converged                                   # still usable
