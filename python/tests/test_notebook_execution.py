# SPDX-License-Identifier: BSD-3-Clause
"""The example notebooks (python/notebooks) run under Debian's Jupyter (`jupyter nbconvert
--execute`, packages jupyter-nbconvert and python3-ipykernel), and the HTML page of each holds
its two reports, each with its own verdict (issue 39, item 3); with node, playwright-core and
Chromium (tests/browser/check_notebooks.mjs) the pages are also opened in headless Chromium:
every frame draws its scene and shows its own verdict, and the notebook keeps its layout.
Every expected value is derived by hand in the notebook's text (Grübler, Maxwell, the papers).
Skipped where Jupyter is not installed; CTest runs this file as the test `python_notebooks`."""

import html
import html.parser
import json
import os
import pathlib
import shutil
import subprocess

import pytest

import kinestat

from conftest import EXAMPLES

NOTEBOOKS = pathlib.Path(__file__).resolve().parents[1] / "notebooks"
BROWSER_CHECK = pathlib.Path(__file__).resolve().parents[2] / "tests" / "browser" / "check_notebooks.mjs"

# Per notebook: text that the executed code cells print or return (hand-derived counts), and for
# each report in page order, what its verdict says and what it must not (the other report's).
EXPECTED = {
    "framework-and-network": {
        # Braced square (0, 1), rigid; free square 3 trivial + 1 shear; Davies FN 3, CN 2.
        "outputs": ["(0, 1, True)", "(3, 1, False)", "(3, 2)"],
        "reports": [{"verdict": ["Not exactly constrained", "1 redundant constraint"], "not": ["2 extra motions"]},
                    {"verdict": ["2 extra motions, 2 redundant constraints"], "not": ["1 redundant constraint ("]}],
    },
    "network": {
        # Four-bar: Grübler 3 (4 - 1 - 4) + 4 = 1, CN 0. Double parallelogram: FN 1, FN - CN = 6 - 3 * 2.
        "outputs": ["(1, 0)", "(1, 1)"],
        "reports": [{"verdict": ["Exactly constrained: 1 intended motion"], "not": ["redundant constraint"]},
                    {"verdict": ["Not exactly constrained", "1 redundant constraint"], "not": ["Exactly constrained: 1"]}],
    },
    "flexure": {
        # Leaf springs: 12 x 11 of rank 11, one self-stress; folded sheets: 35 x 35 non-singular.
        "outputs": ["(0, 1)", "(0, 0)"],
        "reports": [{"verdict": ["Not exactly constrained", "1 redundant constraint"]},
                    {"verdict": ["Exactly constrained"], "not": ["Not exactly constrained", "redundant constraint"]}],
    },
    "structure": {
        # Saura et al. Eq. 2: SG-I {2, 3}, SG-II {4}, SG-III {5}; the over-actuated four-bar is not.
        "outputs": ["([(1, ['wheel', 'arm']), (2, ['follower']), (3, ['link'])], True)", "False"],
        "reports": [{"verdict": ["Exactly constrained"], "not": ["Not exactly constrained"]},
                    {"verdict": ["Not exactly constrained"]}],
    },
    "sweep": {
        # 21 variants of y from -1 to 1; only y = 0 (collinear bars): 1 mechanism, 1 self-stress.
        "outputs": ["(21, [(0.0, 1, 1)])", "(0, 0)", "(1, 1)"],
        "reports": [{"verdict": ["Exactly constrained"], "not": ["Not exactly constrained"]},
                    {"verdict": ["Not exactly constrained", "1 extra motion", "1 redundant constraint"]}],
    },
}


class _Frames(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.sources = []

    def handle_starttag(self, tag, attrs):
        if tag == "iframe" and "srcdoc" in dict(attrs):
            self.sources.append(dict(attrs)["srcdoc"])


@pytest.fixture(scope="module")
def executed(tmp_path_factory):
    """Every notebook executed once (all at a time: most of the time is kernels starting), then
    the executed notebooks converted to HTML without running them again."""
    jupyter = shutil.which("jupyter")
    if jupyter is None or subprocess.run([jupyter, "nbconvert", "--version"], capture_output=True, check=False).returncode:
        pytest.skip("jupyter nbconvert is not installed (Debian: jupyter-nbconvert python3-ipykernel)")
    if not kinestat.html_built_in():
        pytest.skip("kinestat was built without the HTML viewer")
    out = tmp_path_factory.mktemp("notebooks")
    environment = dict(os.environ, KINESTAT_EXAMPLES=str(EXAMPLES.resolve()))

    def execute(name):
        return subprocess.Popen([jupyter, "nbconvert", "--execute", "--to", "notebook", "--output-dir", str(out),
                                 "--ExecutePreprocessor.timeout=300", str(NOTEBOOKS / f"{name}.ipynb")],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=environment)

    runs = {name: execute(name) for name in EXPECTED}
    for name, run in runs.items():
        _, errors = run.communicate(timeout=600)
        if run.returncode != 0 and _kernel_failed_to_start(errors):
            # Kernels started side by side can race for the same free TCP port (jupyter_client picks
            # a port, releases it, and the kernel binds it later: "Address already in use", then
            # "Kernel died before replying to kernel_info"); no notebook cell has run. Run that
            # notebook again alone: a failure of the notebook itself fails again.
            again = execute(name)
            _, errors = again.communicate(timeout=600)
            run = again
        assert run.returncode == 0, (name, _error_lines(errors), errors[-3000:])
    done = subprocess.run([jupyter, "nbconvert", "--to", "html", "--output-dir", str(out)]
                          + [str(out / f"{name}.ipynb") for name in EXPECTED],
                          capture_output=True, text=True, timeout=600, check=False)
    assert done.returncode == 0, done.stderr[-3000:]
    return out


def _kernel_failed_to_start(errors):
    return "Kernel died before replying to kernel_info" in errors or "Address already in use" in errors


def _error_lines(errors):
    # The kernel's own error (it shares nbconvert's stderr) comes before nbconvert's long traceback.
    return [line for line in errors.splitlines() if "Error" in line][:10]


def test_every_notebook_is_tested():
    assert sorted(path.stem for path in NOTEBOOKS.glob("*.ipynb")) == sorted(EXPECTED)


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_the_notebook_runs_and_its_page_holds_two_independent_reports(executed, name):
    expected = EXPECTED[name]
    notebook = json.loads((executed / f"{name}.ipynb").read_text())
    results = [output for cell in notebook["cells"] if cell["cell_type"] == "code" for output in cell["outputs"]]
    assert not [output for output in results if output["output_type"] == "error"]
    texts = ["".join(output.get("data", {}).get("text/plain", "")) for output in results]
    for text in expected["outputs"]:
        assert text in texts, (text, texts)
    frames = _Frames()
    frames.feed((executed / f"{name}.html").read_text())
    assert len(frames.sources) == len(expected["reports"]) == 2
    for source, report in zip(frames.sources, expected["reports"]):
        verdict = html.unescape(source)
        for text in report["verdict"]:
            assert text in verdict
        for text in report.get("not", []):
            assert text not in _summary(source)
    assert frames.sources[0] != frames.sources[1]


def _summary(document):
    # The report's verdict sentence (its <title> and panels may name other things).
    start = document.find('"summary":"')
    return document[start:document.find('"', start + 11)] if start >= 0 else document


def test_the_pages_in_chromium(executed):
    """Each page opened in headless Chromium: every frame draws its own scene and verdict."""
    node = os.environ.get("KINESTAT_NODE") or shutil.which("node")
    modules = os.environ.get("KINESTAT_VIEWER_MODULES")
    if not node or not modules:
        pytest.skip("KINESTAT_NODE / KINESTAT_VIEWER_MODULES not set (CTest sets them)")
    spec = [{"html": str(executed / f"{name}.html"), "reports": EXPECTED[name]["reports"]} for name in sorted(EXPECTED)]
    (executed / "spec.json").write_text(json.dumps(spec))
    out = os.environ.get("KINESTAT_BROWSER_OUT", str(executed / "screenshots"))
    done = subprocess.run([node, str(BROWSER_CHECK), "--modules", modules, "--chromium",
                           os.environ.get("KINESTAT_CHROMIUM", "/usr/bin/chromium"), "--out", out,
                           "--spec", str(executed / "spec.json")],
                          capture_output=True, text=True, timeout=600, check=False)
    if done.returncode == 77:
        pytest.skip(done.stdout.strip())
    assert done.returncode == 0, done.stdout[-4000:] + done.stderr[-2000:]
