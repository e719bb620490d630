"""Shared by the tests of the catena package: the repository, the catena command, and
`catena solve --json` of a file. Run by tests/cli/python.sh (ctest cli_python) with the
package installed into a scratch --target directory on PYTHONPATH; by hand:
    CATENA_CLI=build/catena python3 -m pytest python/tests   (catena importable)"""
import json
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(os.environ.get("CATENA_ROOT", Path(__file__).resolve().parents[2]))
CLI = Path(os.environ.get("CATENA_CLI", ROOT / "build" / "catena"))
PAPER = [ROOT / "examples" / "paper" / f for f in
         ("s200.3340.cable", "s201.3545.cable", "s250.8777.cable", "s279.6157.cable")]


def cli_json(path, *args):
    """(stdout text, exit code) of `catena solve PATH --json`."""
    r = subprocess.run([str(CLI), "solve", str(path), "--json", *args], capture_output=True, text=True)
    return r.stdout, r.returncode


def raw_json(text):
    """The JSON with every number kept as its text (no float conversion)."""
    return json.loads(text, parse_float=str, parse_int=str)


@pytest.fixture
def root():
    return ROOT
