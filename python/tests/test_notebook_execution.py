# SPDX-License-Identifier: BSD-3-Clause
"""The example notebook runs under Debian's Jupyter (`jupyter nbconvert --execute`, package
jupyter-nbconvert with python3-ipykernel) and its page holds two independent reports (issue 39,
item 3). Skipped where Jupyter is not installed."""

import html.parser
import json
import os
import pathlib
import shutil
import subprocess

import pytest

import kinestat

from conftest import EXAMPLES

NOTEBOOK = pathlib.Path(__file__).resolve().parents[1] / "notebooks" / "framework-and-network.ipynb"


class _Frames(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.sources = []

    def handle_starttag(self, tag, attrs):
        if tag == "iframe" and "srcdoc" in dict(attrs):
            self.sources.append(dict(attrs)["srcdoc"])


def _jupyter():
    jupyter = shutil.which("jupyter")
    if jupyter is None or subprocess.run([jupyter, "nbconvert", "--version"], capture_output=True, check=False).returncode:
        pytest.skip("jupyter nbconvert is not installed (Debian: jupyter-nbconvert python3-ipykernel)")
    return jupyter


@pytest.mark.skipif(not kinestat.html_built_in(), reason="kinestat was built without the HTML viewer")
def test_the_example_notebook_runs_and_shows_two_independent_reports(tmp_path):
    jupyter = _jupyter()
    environment = dict(os.environ, KINESTAT_EXAMPLES=str(EXAMPLES.resolve()))
    for kind in ("notebook", "html"):
        done = subprocess.run([jupyter, "nbconvert", "--execute", "--to", kind, "--output-dir", str(tmp_path),
                               "--ExecutePreprocessor.timeout=300", str(NOTEBOOK)],
                              capture_output=True, text=True, env=environment, timeout=600, check=False)
        assert done.returncode == 0, done.stderr[-3000:]
    executed = json.loads((tmp_path / NOTEBOOK.name).read_text())
    results = [output for cell in executed["cells"] if cell["cell_type"] == "code" for output in cell["outputs"]]
    assert not [output for output in results if output["output_type"] == "error"]
    texts = ["".join(output.get("data", {}).get("text/plain", "")) for output in results]
    # By hand: braced square (0, 1), rigid; free square 3 trivial + 1 shear; Davies FN 3, CN 2.
    assert "(0, 1, True)" in texts and "(3, 1, False)" in texts and "(3, 2)" in texts
    frames = _Frames()
    frames.feed((tmp_path / NOTEBOOK.with_suffix(".html").name).read_text())
    assert len(frames.sources) == 2
    square, davies = frames.sources
    assert "<title>braced square</title>" in square and "Not exactly constrained: 1 redundant constraint" in square
    assert "Davies" in davies and "2 extra motions, 2 redundant constraints" in davies
    assert "2 extra motions" not in square and "1 redundant constraint (a structure" not in davies
