#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Validates every example and every JSON report against the schemas in schemas/ (issue 39, item 4).

  * Each schema is a valid JSON Schema (draft 2020-12).
  * Every kinestat model in examples/ (YAML and JSON; network, framework, structure) validates against
    model-v1 (and so against its kind's schema), every sweep spec in examples/sweeps/ against sweep-v1,
    and the files of every earlier spelling in tests/io/data/ too.
  * The JSON report of every example (`analyze --json`, `structure --json`; a network also on the sparse
    path) validates against report-v1, every line of every example sweep against sweep-line-v1, every
    `move --json` of an example that moves (its first mode or primary motion traced; planar positions at
    an input and over a sweep) against move-v1, and all of them, and every `--brief --json` verdict,
    carry the version `kinestat --version` prints and report_version 1.
  * Bad documents are refused (the schemas are not vacuous): a report without its verdict, a model with
    an unknown key, a sweep line without its version, a move report without its path or with a step's
    `assembled` not a boolean.

--sample N (the sanitizer suite: N = 4, tests/CMakeLists.txt): every model file is still validated, but the
command's reports only of the sorted examples 0, N, 2N, ... (each report costs ten times as much under
AddressSanitizer; the release suite checks them all).

Needs Debian's python3-jsonschema and python3-yaml; without them exits 77 (skipped) unless
KINESTAT_REQUIRE_SCHEMAS=1. Usage: schema_validation.py --cli build/release/kinestat --source .
"""
import argparse
import copy
import glob
import json
import os
import subprocess
import sys

try:
    import jsonschema
    import yaml
except ImportError as missing:
    print(f"schema_validation: skipped: {missing} (install python3-jsonschema and python3-yaml)")
    sys.exit(1 if os.environ.get("KINESTAT_REQUIRE_SCHEMAS") == "1" else 77)


def load_schemas(folder):
    schemas = {}
    for path in sorted(glob.glob(os.path.join(folder, "*.schema.json"))):
        with open(path, encoding="utf-8") as f:
            schema = json.load(f)
        jsonschema.Draft202012Validator.check_schema(schema)
        schemas[os.path.basename(path)] = schema
    return schemas


def validator(schemas, name):
    store = {schema["$id"]: schema for schema in schemas.values()}
    resolver = jsonschema.RefResolver.from_schema(schemas[name], store=store)
    return jsonschema.Draft202012Validator(schemas[name], resolver=resolver)


def as_json(document):
    """A YAML document as JSON would carry it (keys as strings)."""
    return json.loads(json.dumps(document, default=str))


def read_document(path):
    with open(path, encoding="utf-8") as f:
        return as_json(yaml.safe_load(f))


def run(cli, *args):
    done = subprocess.run([cli, *args], capture_output=True, text=True, timeout=600)
    return done.returncode, done.stdout, done.stderr


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cli", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--sample", type=int, default=1, help="check the reports of every N-th example only")
    options = parser.parse_args()
    failures = []
    schemas = load_schemas(os.path.join(options.source, "schemas"))
    expected = {"model-v1.schema.json", "network-v1.schema.json", "framework-v1.schema.json", "structure-v1.schema.json",
                "sweep-v1.schema.json", "report-v1.schema.json", "sweep-line-v1.schema.json", "move-v1.schema.json"}
    if set(schemas) != expected:
        failures.append(f"schemas/ holds {sorted(schemas)}, expected {sorted(expected)}")
    model, sweep, report, line, move = (validator(schemas, f"{n}-v1.schema.json")
                                        for n in ("model", "sweep", "report", "sweep-line", "move"))
    version = run(options.cli, "--version")[1].split("\n")[0].split(" ")[-1]

    def check(valid, document, what):
        errors = sorted(valid.iter_errors(document), key=lambda e: list(e.path))
        for error in errors[:3]:
            failures.append(f"{what}: {'/'.join(map(str, error.path)) or '(root)'}: {error.message[:200]}")
        return not errors

    def check_versions(document, what):
        if document.get("kinestat_version") != version or document.get("report_version") != 1:
            failures.append(f"{what}: versions {document.get('kinestat_version')!r}, {document.get('report_version')!r}; "
                            f"expected {version!r}, 1")

    def check_report(document, what, valid=report):
        check(valid, document, what)
        check_versions(document, what)

    examples = os.path.join(options.source, "examples")
    models = sorted(glob.glob(os.path.join(examples, "*.yaml")) + glob.glob(os.path.join(examples, "json", "*.json")))
    old_spellings = sorted(glob.glob(os.path.join(options.source, "tests", "io", "data", "format-1-*.yaml")))
    counted = {"network": 0, "framework": 0, "structure": 0}
    moved = 0
    for index, path in enumerate(models + old_spellings):
        name = os.path.relpath(path, options.source)
        document = read_document(path)
        check(model, document, name)
        kind = document.get("kind", "network")
        counted[kind] += 1
        if path in old_spellings or index % options.sample != 0:
            continue
        command = ["structure", "--json", path] if kind == "structure" else ["analyze", "--json", path]
        code, out, err = run(options.cli, *command)
        if code != 0:
            failures.append(f"{name}: kinestat {' '.join(command[:2])} exit {code}: {err.strip()[:200]}")
            continue
        check_report(json.loads(out), f"report of {name}")
        code, out, err = run(options.cli, command[0], "--json", "--brief", path)
        if code == 0:
            check_versions(json.loads(out), f"--brief --json of {name}")
        else:
            failures.append(f"{name}: {command[0]} --brief --json exit {code}: {err.strip()[:200]}")
        if kind != "structure":
            # Exit 2 when the model has nothing to move (no mode, no motion): no report to check.
            code, out, err = run(options.cli, "move", "--json", "--mode", "1", path)
            if code == 0:
                moved += 1
                check_report(json.loads(out), f"move report of {name}", move)
            elif code != 2:
                failures.append(f"{name}: move --json --mode 1 exit {code}: {err.strip()[:200]}")
        if kind == "network":
            code, out, err = run(options.cli, "analyze", "--json", "--sparse", path)
            if code == 0:
                check_report(json.loads(out), f"sparse report of {name}")
            else:
                failures.append(f"{name}: analyze --sparse exit {code}: {err.strip()[:200]}")
    if min(counted.values()) == 0:
        failures.append(f"examples of every kind expected, found {counted}")
    # Positions of a planar mechanism at one input and over a sweep (a full turn of the crank).
    four_bar_path = os.path.join(examples, "four-bar-planar.yaml")
    positions = {}
    for inputs in (["--input", "A=1.0"], ["--sweep", "A=0:6.283185307179586:12"]):
        code, out, err = run(options.cli, "move", "--json", *inputs, four_bar_path)
        if code == 0:
            positions[inputs[0]] = json.loads(out)
            check_report(positions[inputs[0]], f"move {' '.join(inputs)} of examples/four-bar-planar.yaml", move)
        else:
            failures.append(f"examples/four-bar-planar.yaml: move {' '.join(inputs)} exit {code}: {err.strip()[:200]}")
    if moved == 0:
        failures.append("no example moved (move --json --mode 1)")

    for path in sorted(glob.glob(os.path.join(examples, "sweeps", "*.yaml"))):
        document = read_document(path)
        if document.get("kind") != "sweep":
            continue
        name = os.path.relpath(path, options.source)
        check(sweep, document, name)
        # Every variant of the small sweeps, one shard in a hundred of the large one.
        code, out, err = run(options.cli, "sweep", path, "--shard", "0/100") if "guide-6" in path else run(options.cli, "sweep", path)
        if code not in (0, 1) or not out.strip():  # 1: some variants failed (their lines say why)
            failures.append(f"{name}: kinestat sweep exit {code}: {err.strip()[:200]}")
            continue
        for k, text in enumerate(out.strip().split("\n")):
            document = json.loads(text)
            check(line, document, f"{name} line {k + 1}")
            if document.get("kinestat_version") != version:
                failures.append(f"{name} line {k + 1}: kinestat_version {document.get('kinestat_version')!r}")

    # The schemas refuse what they must.
    code, out, _ = run(options.cli, "analyze", "--json", os.path.join(examples, "four-bar-planar.yaml"))
    good = json.loads(out)
    for broken, what in ((lambda d: d.pop("verdict"), "a report without its verdict"),
                         (lambda d: d.pop("report_version"), "a report without report_version"),
                         (lambda d: d.update(report_version=2), "a report of version 2"),
                         (lambda d: d["verdict"].pop("exactly_constrained"), "a verdict without exactly_constrained")):
        document = copy.deepcopy(good)
        broken(document)
        if report.is_valid(document):
            failures.append(f"report-v1 accepts {what}")
    four_bar = read_document(os.path.join(examples, "four-bar-planar.yaml"))
    for broken, what in ((lambda d: d.update(spelling_mistake=1), "a model with an unknown key"),
                         (lambda d: d.update(kinestat=2), "a model of format version 2"),
                         (lambda d: d["couplings"][0].update(type="hinge"), "an unknown coupling type")):
        document = copy.deepcopy(four_bar)
        broken(document)
        if model.is_valid(document):
            failures.append(f"model-v1 accepts {what}")
    if line.is_valid({"variant": 0, "of": 1, "parameters": {}, "kind": "network", "verdict": {"exactly_constrained": True, "summary": "x"}}):
        failures.append("sweep-line-v1 accepts a line without versions")
    code, out, _ = run(options.cli, "move", "--json", "--mode", "1", os.path.join(examples, "bennett.yaml"))
    traced = json.loads(out) if code == 0 else {}
    for broken, what in ((lambda d: d.pop("path"), "a trace without its path"),
                         (lambda d: d.pop("report_version"), "a move report without report_version"),
                         (lambda d: d.update(command="analyze"), "a report of another command")):
        document = copy.deepcopy(traced)
        broken(document)
        if move.is_valid(document):
            failures.append(f"move-v1 accepts {what}")
    if "--sweep" in positions:
        document = copy.deepcopy(positions["--sweep"])
        document["steps"][0]["assembled"] = "yes"
        if move.is_valid(document):
            failures.append("move-v1 accepts a step whose 'assembled' is no boolean")

    for failure in failures:
        print(failure)
    sampled = f" (reports of every {options.sample}th example)" if options.sample > 1 else ""
    print(f"schema_validation: {len(models)} example models ({counted}){sampled}, {moved} move reports, "
          f"{len(old_spellings)} files of earlier spellings, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
