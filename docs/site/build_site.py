#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Builds kinestat's documentation site from the sources (issue 39, item 6):

- the pages of docs/site/ (home, the tutorial path network -> flexure -> structure -> sweep ->
  Python, the Python API by autodoc) with docs/*.md as the guide;
- the gallery: every model of examples/*.yaml drawn by `kinestat draw` (SVG) with the verdict
  and counts `kinestat analyze --json` gives;
- the C++ API reference by Doxygen (Doxyfile), as cpp/;
- the tutorial's command outputs: a line `<!-- kinestat ARGS -->` in a page becomes a console
  block with what the built command prints for ARGS (so the pages cannot drift from the program);
then sphinx-build (Debian: python3-sphinx, python3-myst-parser) and doxygen. Output: OUT/html/index.html.

  docs/site/build_site.py --cli build/release/kinestat --python build/release/python --out build/release/docs

`cmake --build <build> --target docs` runs it; the CTest test `docs_site` too. Exit 0 built,
1 failed, 77 skipped (doxygen, sphinx-build or myst_parser missing, unless KINESTAT_REQUIRE_DOCS=1)."""

import argparse
import concurrent.futures
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys
import time

SOURCE = pathlib.Path(__file__).resolve().parents[2]
SITE = SOURCE / "docs" / "site"


def run_command(cli, arguments, cwd):
    done = subprocess.run([cli, *arguments], capture_output=True, text=True, cwd=cwd, timeout=120, check=False)
    return done.returncode, done.stdout, done.stderr


def expand_runs(text, cli):
    """`<!-- kinestat ARGS -->` (optionally `| head -N`) -> the command and its output."""
    def replace(match):
        arguments, head = match.group(1).split(), match.group(2)
        code, out, err = run_command(cli, arguments, SOURCE)
        if code not in (0, 1):
            raise SystemExit(f"build_site: `kinestat {' '.join(arguments)}` failed ({code}): {err.strip()}")
        lines = out.rstrip("\n").split("\n")
        if head and len(lines) > int(head):
            lines = lines[:int(head)] + ["…"]
        return "```console\n$ kinestat " + " ".join(arguments) + "\n" + "\n".join(lines) + "\n```"
    return re.sub(r"^<!-- kinestat (.*?)(?: \| head -(\d+))? -->$", replace, text, flags=re.M)


def analyse_example(cli, model, pictures):
    """Verdict, counts and picture of one example (kinestat analyze --json, kinestat draw)."""
    code, out, err = run_command(cli, ["analyze", "--json", str(model)], SOURCE)
    if code not in (0, 1) and "kinestat structure" in err:  # a structure model: its own command
        code, out, err = run_command(cli, ["structure", "--json", str(model)], SOURCE)
    if code not in (0, 1):
        return {"name": model.stem, "error": err.strip().splitlines()[-1] if err.strip() else f"exit {code}"}
    report = json.loads(out)
    kind = report.get("kind", "")
    if "FN" in report:
        counts = f"FN = {report['FN']}, CN = {report['CN']}"
    elif "mechanisms" in report:
        counts = f"{report['mechanisms']} mechanism(s), {report['self_stresses']} self-stress(es)"
    else:
        groups = report.get("groups", [])
        counts = f"{len(groups)} structural group(s), mobility {report.get('mobility')}"
    picture = pictures / f"{model.stem}.svg"
    # The model itself (networks: bodies, couplings and their axes; frameworks: with the first
    # mode and self-stress); structures: the structural diagram.
    what = ["--what", "mechanism"] if kind == "network" else []
    code, _, err = run_command(cli, ["draw", str(model), *what, "-o", str(picture)], SOURCE)
    return {"name": model.stem, "title": report.get("name", report.get("model", model.stem)), "kind": kind,
            "summary": (report.get("verdict") or {}).get("summary", ""), "counts": counts,
            "picture": picture.name if code == 0 and picture.exists() else None,
            "comment": first_comment(model)}


def first_comment(model):
    """The first sentence of the model file's leading comment (its source and what it shows)."""
    lines = []
    for line in model.read_text().splitlines():
        if not line.startswith("#"):
            break
        lines.append(line.lstrip("# ").strip())
    text = " ".join(lines)
    # The first sentence: a full stop after a word of two letters or more, then a capital.
    end = re.search(r"(?<=[a-z0-9)\]]{2})\.(?= [A-Z(])", text)
    text = text[:end.end()] if end else text
    return text if len(text) <= 240 else text[:text.rfind(" ", 0, 240)] + " …"


def gallery(cli, stage):
    folder = stage / "gallery"
    folder.mkdir()
    models = sorted((SOURCE / "examples").glob("*.yaml"))
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        entries = list(pool.map(lambda m: analyse_example(cli, m, folder), models))
    page = ["# Gallery", "",
            f"Every model of `examples/` ({len(entries)} files), drawn by `kinestat draw` and analysed by",
            "`kinestat analyze`: the picture, the verdict and the counts, made when this site was built.",
            "Each file's comment names its source and the expected result. Frameworks show their first",
            "mode (orange arrows, the undeformed shape in grey) and self-stress (tension red, compression",
            "blue); networks their bodies and couplings; structures their structural diagram.", ""]
    for kind, heading in (("network", "Coupling networks"), ("framework", "Frameworks and flexures"),
                          ("structure", "Structures")):
        chosen = [e for e in entries if e.get("kind") == kind]
        if not chosen:
            continue
        page += [f"## {heading}", "", "::::{container} gallery", ""]
        for entry in chosen:
            caption = f"**{entry['name']}.yaml** — {entry['summary']} {entry['counts']}. {entry['comment']}"
            if entry["picture"]:
                page += [f"```{{figure}} {entry['picture']}", ":figclass: gallery-item", f":alt: {entry['name']}", "",
                         caption.replace("\n", " "), "```", ""]
            else:
                page += [f"- {caption}", ""]
        page += ["::::", ""]
    failed = [e for e in entries if "error" in e]
    if failed:
        raise SystemExit("build_site: examples that did not analyse: " + "; ".join(f"{e['name']}: {e['error']}" for e in failed))
    (folder / "index.md").write_text("\n".join(page) + "\n")
    return entries


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cli", required=True, help="the built kinestat command")
    parser.add_argument("--python", help="the folder holding the built Python package (for the API reference)")
    parser.add_argument("--out", required=True, help="output folder: OUT/html/index.html")
    parser.add_argument("--version", default="")
    arguments = parser.parse_args()
    doxygen, sphinx = shutil.which("doxygen"), shutil.which("sphinx-build")
    try:
        import myst_parser  # noqa: F401  (Debian python3-myst-parser)
    except ImportError:
        sphinx = None
    if not doxygen or not sphinx:
        # CI sets KINESTAT_REQUIRE_DOCS=1 so that a missing tool fails instead of skipping.
        required = os.environ.get("KINESTAT_REQUIRE_DOCS") == "1"
        print(("FAILED: " if required else "SKIP: ") +
              "the site needs doxygen, sphinx-build and myst_parser (Debian: doxygen python3-sphinx python3-myst-parser)")
        return 1 if required else 77
    cli = str(pathlib.Path(arguments.cli).resolve())
    out = pathlib.Path(arguments.out).resolve()
    stage = out / "source"
    shutil.rmtree(out, ignore_errors=True)
    start = time.monotonic()

    # The pages: docs/site/ and docs/*.md (as guide/), with the command outputs filled in.
    shutil.copytree(SITE, stage, ignore=shutil.ignore_patterns("build_site.py", "cpp-mainpage.md", "__pycache__"))
    (stage / "guide").mkdir()
    for page in sorted((SOURCE / "docs").glob("*.md")):
        shutil.copy(page, stage / "guide" / page.name)
    shutil.copytree(SOURCE / "docs" / "images", stage / "guide" / "images")
    for page in stage.rglob("*.md"):
        text = page.read_text()
        if "<!-- kinestat " in text:
            page.write_text(expand_runs(text, cli))
    entries = gallery(cli, stage)
    staged = time.monotonic()

    environment = dict(os.environ, KINESTAT_VERSION=arguments.version, KINESTAT_DOXYGEN_OUT=str(out / "doxygen"))
    if arguments.python:
        environment["PYTHONPATH"] = str(pathlib.Path(arguments.python).resolve())
    (out / "doxygen").mkdir(parents=True)
    subprocess.run([doxygen, str(SOURCE / "Doxyfile")], cwd=SOURCE, env=environment, check=True)
    documented = time.monotonic()
    done = subprocess.run([sphinx, "-b", "html", "-q", "-j", "2", "-w", str(out / "sphinx-warnings.log"),
                           str(stage), str(out / "html")], env=environment, check=False)
    if done.returncode != 0:
        print("build_site: sphinx-build failed (above)", file=sys.stderr)
        return 1
    shutil.copytree(out / "doxygen" / "html", out / "html" / "cpp")
    finished = time.monotonic()

    # What the site must hold.
    problems = []
    for page in ["index.html", "gallery/index.html", "python-api.html", "cpp/index.html", "guide/network.html",
                 *(f"tutorial/{step}.html" for step in ("network", "flexure", "structure", "sweep", "python"))]:
        if not (out / "html" / page).exists():
            problems.append(f"{page} was not written")
    built_gallery = (out / "html" / "gallery" / "index.html").read_text() if not problems else ""
    pictures = [e for e in entries if e.get("picture")]
    if built_gallery and built_gallery.count("<figure") != len(pictures):
        problems.append(f"the gallery shows {built_gallery.count('<figure')} pictures of {len(pictures)}")
    if arguments.python and "kinestat.analyze" not in (out / "html" / "python-api.html").read_text():
        problems.append("python-api.html does not document kinestat.analyze")
    warnings = (out / "sphinx-warnings.log").read_text().strip().splitlines()
    print(f"docs: {out / 'html' / 'index.html'}: {len(entries)} gallery models ({len(pictures)} pictures), "
          f"{len(warnings)} Sphinx warnings ({out / 'sphinx-warnings.log'}); pages and gallery {staged - start:.1f} s, "
          f"Doxygen {documented - staged:.1f} s, Sphinx {finished - documented:.1f} s")
    for problem in problems:
        print("FAILED: " + problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
