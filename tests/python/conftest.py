"""Fixtures of the Python module's suite (ctest python_module): the module from the build tree
(PYTHONPATH=build/python) and the command-line program of the same build, to compare with."""

import json
import os
import subprocess

import pytest


@pytest.fixture(scope="session")
def cli():
    """Runs `agvbench ARGS...` of this build; returns its stdout, or its JSON with json=True."""
    program = os.environ["AGVBENCH_BIN"]

    def run(*args, json_out=False):
        done = subprocess.run([program, *map(str, args)], capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        return json.loads(done.stdout) if json_out else done.stdout

    return run
