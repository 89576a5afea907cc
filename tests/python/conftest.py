"""Shared fixtures of the Python tests: the built program and the repository's files. ctest sets
CATENA_CLI (the built `catena`), CATENA_SOURCE_DIR and PYTHONPATH (the build tree's package)."""

import json
import os
import pathlib
import subprocess

import pytest

SOURCE = pathlib.Path(os.environ.get("CATENA_SOURCE_DIR", pathlib.Path(__file__).parents[2]))


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("CATENA_CLI")
    if not path:
        pytest.fail("CATENA_CLI (the built catena program) is not set; run through ctest")
    return path


def run_cli(cli, *args, cwd=None):
    """Runs the program; returns (exit status, stdout, stderr)."""
    p = subprocess.run([cli, *args], capture_output=True, text=True, cwd=cwd, timeout=120)
    return p.returncode, p.stdout, p.stderr


def cli_json(cli, *args, cwd=None):
    status, out, err = run_cli(cli, *args, cwd=cwd)
    assert status == 0, err
    return json.loads(out)
