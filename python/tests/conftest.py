# SPDX-License-Identifier: BSD-3-Clause
"""Shared fixtures: the command-line tool and the examples (paths from CTest's environment)."""

import json
import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXAMPLES = pathlib.Path(os.environ.get("KINESTAT_EXAMPLES", ROOT / "examples"))
CLI = os.environ.get("KINESTAT_CLI", str(ROOT / "build" / "release" / "kinestat"))


def run_cli(*arguments):
    """Runs the kinestat command; returns (exit code, stdout, stderr)."""
    done = subprocess.run([CLI, *map(str, arguments)], capture_output=True, text=True, check=False)
    return done.returncode, done.stdout, done.stderr


def cli_json(*arguments):
    code, out, err = run_cli(*arguments, "--json")
    assert code == 0, err
    return out


def model_kind(path):
    """The `kind:` of a model file, read with a plain text scan (independent of kinestat)."""
    for line in pathlib.Path(path).read_text().splitlines():
        stripped = line.strip().strip(",").replace('"', "")
        if stripped.startswith("kind:"):
            return stripped.split(":", 1)[1].strip()
    return "network"


def example_files():
    return sorted(EXAMPLES.glob("*.yaml")) + sorted((EXAMPLES / "json").glob("*.json"))


@pytest.fixture
def examples():
    return EXAMPLES
