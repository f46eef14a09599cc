# SPDX-License-Identifier: BSD-3-Clause
"""kinestat installs the Python way (issue 39, item 2): `pip install --no-build-isolation .` into a
venv of Debian's interpreter, offline; the type stubs cover the public API."""

import ast
import inspect
import os
import pathlib
import subprocess
import sys

import pytest

import kinestat

ROOT = pathlib.Path(__file__).resolve().parents[2]
STUB = ROOT / "python" / "kinestat" / "__init__.pyi"


def test_pip_installs_into_a_venv_and_the_module_analyses(tmp_path):
    for module in ("ensurepip", "setuptools", "wheel"):  # Debian: python3-venv, python3-setuptools, python3-wheel
        pytest.importorskip(module)
    venv = tmp_path / "v"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)], check=True, timeout=300)
    environment = {key: value for key, value in os.environ.items() if key != "PYTHONPATH"}
    # The extension this test session runs, packaged as is: pip's CMake build of it is the same
    # command the CMake build ran (setup.py, KINESTAT_CORE_MODULE).
    environment["KINESTAT_CORE_MODULE"] = kinestat._core.__file__
    done = subprocess.run([str(venv / "bin" / "pip"), "install", "--no-build-isolation", "--no-index", "--quiet", str(ROOT)],
                          capture_output=True, text=True, env=environment, cwd=tmp_path, timeout=600, check=False)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    script = ("import kinestat, sys\n"
              "r = kinestat.analyze(sys.argv[1])\n"
              "print(kinestat.__file__)\nprint(kinestat.__version__, r.FN, r.CN)\n")
    run = subprocess.run([str(venv / "bin" / "python"), "-c", script, str(ROOT / "examples" / "davies-2-circuit.yaml")],
                         capture_output=True, text=True, env=environment, cwd=tmp_path, timeout=300, check=False)
    assert run.returncode == 0, run.stderr[-3000:]
    where, counts = run.stdout.splitlines()
    assert where.startswith(str(venv))  # the installed copy, not the build tree
    assert counts.split() == [kinestat.__version__, "3", "2"]  # seed 000: FN 3, CN 2
    files = {p.name for p in pathlib.Path(where).parent.iterdir()}
    assert {"__init__.pyi", "py.typed"} <= files


def _stub_names():
    tree = ast.parse(STUB.read_text())
    names, members = set(), {}
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, (ast.Assign, ast.AnnAssign)):
            for target in node.targets if isinstance(node, ast.Assign) else [node.target]:
                if isinstance(target, ast.Name):
                    names.add(target.id)
        if isinstance(node, ast.ClassDef):
            members[node.name] = {item.name for item in node.body if isinstance(item, ast.FunctionDef)} | {
                item.target.id for item in node.body if isinstance(item, ast.AnnAssign)}
    return names, members


def test_the_stubs_declare_every_public_name_and_method():
    names, members = _stub_names()
    assert set(kinestat.__all__) <= names
    for cls in (kinestat.NetworkResult, kinestat.FrameworkResult, kinestat.StructureResult):
        declared = set().union(*(members.get(base.__name__, set()) for base in cls.__mro__))
        public = {name for name, _ in inspect.getmembers(cls) if not name.startswith("_")}
        assert public <= declared, (cls.__name__, public - declared)


def test_a_missing_extension_says_so(tmp_path):
    # The package's Python files without kinestat._core, as while the build is still running.
    package = tmp_path / "kinestat"
    package.mkdir()
    (package / "__init__.py").write_text((ROOT / "python" / "kinestat" / "__init__.py").read_text())
    environment = dict(os.environ, PYTHONPATH=str(tmp_path))
    done = subprocess.run([sys.executable, "-c", "import kinestat"], capture_output=True, text=True, env=environment,
                          cwd=tmp_path, timeout=120, check=False)
    last = done.stderr.strip().splitlines()[-1]
    assert done.returncode != 0 and last.startswith("ImportError: kinestat's compiled part, kinestat._core, is missing")
    assert "is its build finished?" in last
