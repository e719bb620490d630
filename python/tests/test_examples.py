"""Every example of examples/python/ runs (exit 0) with the package installed, and what it
prints agrees with the library's own checks where it states a result."""
import os
import subprocess
import sys

import pytest

from conftest import ROOT

EXAMPLES = sorted((ROOT / "examples" / "python").glob("*.py"))


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_example_runs(path, tmp_path):
    env = dict(os.environ)
    r = subprocess.run([sys.executable, str(path), str(tmp_path)], capture_output=True, text=True, env=env,
                       cwd=tmp_path, timeout=600)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip()


def test_examples_exist():
    names = {p.name for p in EXAMPLES}
    assert {"paper_sweep.py", "net_from_arrays.py", "modal_study.py", "formfind_then_load.py"} <= names


def test_net_example_writes_a_model_the_cli_solves(tmp_path):
    subprocess.run([sys.executable, str(ROOT / "examples" / "python" / "net_from_arrays.py"), str(tmp_path)],
                   check=True, capture_output=True)
    from conftest import cli_json
    import catena
    text, code = cli_json(tmp_path / "net.cable")
    assert code == 0
    assert catena.read(tmp_path / "net.cable").solve().to_json() == text.rstrip("\n")
    assert (tmp_path / "net.vtu").stat().st_size > 0


def test_formfind_found_model_is_at_rest(tmp_path):
    """The found net under its own prestress and no other load stays where it was found."""
    import catena
    import numpy as np
    found, rep = catena.formfind(ROOT / "examples" / "formfind" / "hypar_net.cable", path=tmp_path / "f.cable")
    assert rep["converged"]
    sol = found.solve(check=True)
    assert np.abs(sol.displacements).max() < 1e-9
    from conftest import cli_json
    text, code = cli_json(tmp_path / "f.cable")
    assert code == 0 and sol.to_json() == text.rstrip("\n")
