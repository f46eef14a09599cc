# SPDX-License-Identifier: BSD-3-Clause
"""kinestat.sweep gives the lines of `kinestat sweep`, and the values derived by hand (docs/sweep.md)."""

import json

import kinestat
from conftest import EXAMPLES, run_cli


def test_sweep_equals_the_command_lines():
    spec = EXAMPLES / "sweeps" / "collinear-bars.yaml"
    code, out, err = run_cli("sweep", spec, "--shard", "1/3")
    assert code == 0, err
    assert kinestat.sweep(spec, shard=(1, 3)) == [json.loads(line) for line in out.splitlines()]


def test_collinear_bars_are_a_mechanism_exactly_at_zero():
    # B of two bars A (0, 0) - B (1, y) - C (2, 0) on the line AC only at y = 0 (variant 10 of 21).
    lines = kinestat.sweep(EXAMPLES / "sweeps" / "collinear-bars.yaml")
    assert [line["variant"] for line in lines] == list(range(21))
    assert [line["mechanisms"] for line in lines] == [1 if k == 10 else 0 for k in range(21)]
    assert lines[10]["parameters"] == {"b_y": 0.0}
