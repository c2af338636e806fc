"""Shared fixtures of the Python suite: paths, the CLI, the bundled scenes.

ctest sets FIXEL_SOURCE_DIR, FIXEL_CLI and PYTHONPATH (tests/CMakeLists.txt);
run by hand: PYTHONPATH=build/python /usr/bin/python3 -m pytest tests/python
"""

import json
import os
import pathlib
import subprocess

import pytest
from hypothesis import settings

ROOT = pathlib.Path(os.environ.get("FIXEL_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
SCENE_DIR = ROOT / "data" / "scenes"
SCENES = sorted(SCENE_DIR.glob("*.json"))
CLI = os.environ.get("FIXEL_CLI", str(ROOT / "build" / "fixel"))

# No example database in the source tree; a fixed budget keeps the suite fast.
settings.register_profile("fixel", database=None, max_examples=150, deadline=None)
settings.load_profile("fixel")


def run_cli(*args):
    """(exit code, stdout, stderr) of the fixel CLI."""
    p = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


def cli_json(*args):
    code, out, err = run_cli(*args, "--json")
    assert code == 0, err
    return json.loads(out)


def cli_error(*args):
    """The CLI's error message (without its "fixel: error: " prefix)."""
    code, _, err = run_cli(*args)
    assert code == 2, err
    prefix = "fixel: error: "
    assert err.startswith(prefix)
    return err[len(prefix) :].rstrip("\n")


@pytest.fixture(scope="session")
def example2():
    import fixel

    return fixel.Scene.load(SCENE_DIR / "example2.json")
