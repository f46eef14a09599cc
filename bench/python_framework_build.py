#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Time of building a large framework in Python (kinestat.Framework from numpy arrays), writing its
model document and analysing it, beside the standard library's indented json.dumps of the same
document (what Framework.to_json used before), in the same run.

Usage: PYTHONPATH=build/release/python /usr/bin/python3 bench/python_framework_build.py [N] [ROUNDS]
(an N x N square grid of nodes joined by bars along rows and columns; default 400, 3 rounds)."""

import json
import sys
import time

import numpy as np

import kinestat


def grid(n):
    xs, ys = np.meshgrid(np.arange(n, dtype=float), np.arange(n, dtype=float))
    nodes = np.c_[xs.ravel() * 0.7, ys.ravel() * 1.3]
    index = np.arange(n * n).reshape(n, n)
    bars = np.vstack([np.c_[index[:, :-1].ravel(), index[:, 1:].ravel()],
                      np.c_[index[:-1, :].ravel(), index[1:, :].ravel()]])
    return kinestat.Framework(nodes, bars=bars, supports={0: "pinned", 1: ["y"]})


def seconds(call):
    start = time.perf_counter()
    value = call()
    return time.perf_counter() - start, value


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 400
    rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 3
    framework = grid(n)
    document = framework.to_dict()
    print(f"{n} x {n} grid: {len(document['nodes'])} nodes, {len(document['elements'])} bars")
    for _ in range(rounds):
        to_json, text = seconds(framework.to_json)
        indented, old_text = seconds(lambda: json.dumps(document, indent=1))
        analyse, result = seconds(lambda: kinestat.analyze(framework))
        assert json.loads(text) == json.loads(old_text) == document
        print(f"to_json {to_json:.2f} s ({len(text) / 1e6:.1f} MB) | json.dumps(indent=1) of the same document "
              f"{indented:.2f} s ({len(old_text) / 1e6:.1f} MB) | analyze(framework) {analyse:.2f} s "
              f"(mechanisms {result.mechanisms})")


if __name__ == "__main__":
    main()
