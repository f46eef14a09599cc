#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Runs every model sample of README.md and docs/*.md through the built `kinestat` command.

Conventions for the pages (what this test enforces):
  * A fenced block tagged ```yaml is a complete, runnable model or sweep spec. It is written to
    a file as if it lay in examples/sweeps/ (so a sweep's `model: ../x.yaml` names an example)
    and run with the command its `kind:` calls for (network and framework: `analyze`, structure:
    `structure`, sweep: `sweep`), which must exit with 0 and print a report.
  * A block that only shows part of a model is tagged ```yaml fragment and is not run.
  * Any other block whose text holds a `kinestat: 1` line is an error (tag it yaml or yaml fragment).
  * A block tagged ```console holds `$ kinestat ...` commands, each followed by what it prints.
    A `.yaml` argument that is no file of the source tree means the nearest runnable yaml block
    above it on the same page. The printed lines must appear in order; a line `…` (or `...`)
    stands for any number of lines, and a line ending in `…` for any line starting with the rest.
Also: every file path docs/architecture.md names in backquotes, and every relative link of every
page, must exist. Exit code 0 when everything holds, 1 with one line per failure otherwise.

Usage: check_doc_samples.py --cli build/release/kinestat --source .
"""
import argparse
import glob
import os
import re
import shlex
import subprocess
import sys
import tempfile

COMMAND_BY_KIND = {"network": "analyze", "framework": "analyze", "structure": "structure", "sweep": "sweep"}
FENCE = re.compile(r"^(\s*)```(.*)$")
ELLIPSIS = ("…", "...")


def fenced_blocks(text):
    """(line number of the opening fence, info string, body lines) of every fenced block."""
    lines = text.split("\n")
    blocks, i = [], 0
    while i < len(lines):
        match = FENCE.match(lines[i])
        if not match:
            i += 1
            continue
        indent, info = match.group(1), match.group(2).strip()
        end = i + 1
        while end < len(lines) and not re.match(r"^\s*```\s*$", lines[end]):
            end += 1
        body = [line[len(indent):] if line.startswith(indent) else line for line in lines[i + 1:end]]
        blocks.append((i + 1, info, body))
        i = end + 1
    return blocks


def model_kind(body):
    for line in body:
        match = re.match(r"^kind:\s*([A-Za-z]+)", line)
        if match:
            return match.group(1)
    return "network"


def sample_folder(source, root):
    """Makes root look like examples/ with a writable sweeps/ inside, for the samples."""
    examples = os.path.join(source, "examples")
    for name in os.listdir(examples):
        if name != "sweeps":
            os.symlink(os.path.join(examples, name), os.path.join(root, name))
    os.mkdir(os.path.join(root, "sweeps"))
    for name in os.listdir(os.path.join(examples, "sweeps")):
        os.symlink(os.path.join(examples, "sweeps", name), os.path.join(root, "sweeps", name))
    return os.path.join(root, "sweeps")


def run(argv, cwd):
    try:
        done = subprocess.run(argv, cwd=cwd, capture_output=True, text=True, timeout=300)
    except subprocess.TimeoutExpired:
        return None, "", "timed out after 300 s"
    return done.returncode, done.stdout, done.stderr


def lines_match(expected, actual):
    """True when the expected lines (with … wildcards) appear in order in the actual lines."""
    if not expected:
        return True
    head, rest = expected[0], expected[1:]
    if head.strip() in ELLIPSIS:
        return any(lines_match(rest, actual[k:]) for k in range(len(actual) + 1))
    if not actual:
        return False
    line = actual[0].rstrip()
    if head.endswith("…"):
        ok = line.startswith(head[:-1])
    else:
        ok = line == head.rstrip()
    return ok and lines_match(rest, actual[1:])


def check_console(page, line_number, body, last_model, cli, source, failures):
    commands, current = [], None
    for line in body:
        if line.startswith("$ "):
            current = [line[2:], []]
            commands.append(current)
        elif current is not None:
            current[1].append(line)
    for command, expected in commands:
        words = shlex.split(command)
        if not words or words[0] not in ("kinestat", "build/release/kinestat"):
            failures.append(f"{page}:{line_number}: a console block runs only kinestat commands: {command}")
            continue
        argv = [cli]
        for word in words[1:]:
            if word.endswith(".yaml") and not os.path.exists(os.path.join(source, word)):
                if last_model is None:
                    failures.append(f"{page}:{line_number}: {word} is no file and no yaml block precedes it")
                    break
                word = last_model
            argv.append(word)
        else:
            code, out, err = run(argv, source)
            if code != 0:
                failures.append(f"{page}:{line_number}: `{command}` exited with {code}: {err.strip()[:300]}")
            elif not lines_match(expected, out.rstrip("\n").split("\n")):
                printed = out.rstrip("\n").split("\n")
                missing = [line for line in expected if line.strip() not in ELLIPSIS
                           and not any(lines_match([line], [actual]) for actual in printed)]
                what = f"it does not print {missing[0]!r}" if missing else "the lines are in another order"
                failures.append(f"{page}:{line_number}: `{command}` no longer prints what the page shows: {what}; "
                                f"it prints:\n{out}")


def check_page(page, source, cli, folder, counts, failures):
    text = open(os.path.join(source, page), encoding="utf-8").read()
    last_model = None
    for line_number, info, body in fenced_blocks(text):
        words = info.split()
        language = words[0] if words else ""
        if language == "yaml" and "fragment" in words[1:]:
            counts["fragments"] += 1
            continue
        if language == "yaml":
            kind = model_kind(body)
            if kind not in COMMAND_BY_KIND:
                failures.append(f"{page}:{line_number}: unknown kind '{kind}'")
                continue
            path = os.path.join(folder, f"{page.replace('/', '-')}-{line_number}.yaml")
            with open(path, "w", encoding="utf-8") as sample:
                sample.write("\n".join(body) + "\n")
            code, out, err = run([cli, COMMAND_BY_KIND[kind], path], source)
            counts["models"] += 1
            if code != 0 or not out.strip():
                failures.append(f"{page}:{line_number}: `kinestat {COMMAND_BY_KIND[kind]}` exited with {code}: "
                                f"{err.strip()[:300]}")
            last_model = path
        elif language == "console":
            counts["console"] += 1
            check_console(page, line_number, body, last_model, cli, source, failures)
        elif any(re.match(r"^kinestat:\s*\d", line) for line in body):
            failures.append(f"{page}:{line_number}: a model in a block tagged '{info}': tag it yaml or yaml fragment")


def check_paths(source, pages, failures):
    """Backquoted paths of docs/architecture.md and relative links of every page exist."""
    architecture = os.path.join(source, "docs", "architecture.md")
    if os.path.exists(architecture):
        text = open(architecture, encoding="utf-8").read()
        for token in sorted(set(re.findall(r"`([^`\n]+)`", text))):
            token = token.strip()
            include = re.match(r"^(?:#include\s*)?<([^>]+)>$", token)
            if include:
                token = include.group(1)
            if not re.match(r"^[\w.*/-]+$", token):
                continue
            if not (token.endswith("/") or re.search(r"\.(cpp|hpp|h|md|yaml|json|py|sh|txt|cmake|mjs)$", token)):
                continue
            if "/" not in token:
                # A bare file name (`petsc_handover.cpp`): some file of that name in the tree.
                if not token.startswith(".") and not any(
                        glob.glob(os.path.join(source, root, "**", token), recursive=True) for root in ("src", "python", "tests", "docs")):
                    failures.append(f"docs/architecture.md names {token}, which is no file of src/, python/, tests/ or docs/")
                continue
            roots = ["", "src/", "src/kinestat/", "include/", "python/"]
            if not any(glob.glob(os.path.join(source, root, token)) for root in roots):
                failures.append(f"docs/architecture.md names {token}, which does not exist")
    for page in pages:
        text = open(os.path.join(source, page), encoding="utf-8").read()
        for target in re.findall(r"\]\(([^)\s]+)\)", text):
            if re.match(r"^[a-z]+:", target) or target.startswith("#"):
                continue
            path = os.path.normpath(os.path.join(source, os.path.dirname(page), target.split("#")[0]))
            if not os.path.exists(path):
                failures.append(f"{page}: the link to {target} leads nowhere")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--cli", required=True, help="the built kinestat command")
    parser.add_argument("--source", required=True, help="the source tree")
    arguments = parser.parse_args()
    source = os.path.abspath(arguments.source)
    cli = os.path.abspath(arguments.cli)
    pages = ["README.md"] + sorted(os.path.relpath(p, source) for p in glob.glob(os.path.join(source, "docs", "*.md")))
    counts = {"models": 0, "fragments": 0, "console": 0}
    failures = []
    with tempfile.TemporaryDirectory(prefix="kinestat-doc-samples-") as root:
        folder = sample_folder(source, root)
        for page in pages:
            check_page(page, source, cli, folder, counts, failures)
    check_paths(source, pages, failures)
    for failure in failures:
        print(failure)
    print(f"{counts['models']} yaml samples run, {counts['fragments']} fragments skipped, "
          f"{counts['console']} console blocks compared, {len(pages)} pages; {len(failures)} failures")
    return 1 if failures or counts["models"] == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
