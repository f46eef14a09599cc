# SPDX-License-Identifier: BSD-3-Clause
"""Finite motion from Python (issue 13): kinestat.trace follows a framework mode and
kinestat.solve_positions solves a planar mechanism group by group; both return the dict of
`kinestat move --json`. Expected values are derived here: bar lengths from the file's
coordinates, the four-bar's coupler pivot by intersecting two circles with numpy."""

import json
import math

import numpy as np
import pytest

import kinestat
from conftest import cli_json, run_cli

# examples/four-bar-linkage.yaml: ground A (0, 0), B (2, 0); bars A-D, D-C, C-B.
FOUR_BAR_NODES = {"A": (0.0, 0.0), "B": (2.0, 0.0), "C": (2.0, 1.5), "D": (0.0, 1.0)}
FOUR_BAR_BARS = [("A", "D"), ("D", "C"), ("C", "B")]


def distance(p, q):
    return math.dist(p, q)


def test_trace_of_the_four_bar_of_bars_keeps_every_bar_length(examples):
    path = kinestat.trace(examples / "four-bar-linkage.yaml", mode=1, amplitude=0.1, steps=20)
    assert path["closed"] is True and path["failed_step"] is None
    assert path["order"] == "finite"
    assert len(path["path"]) == 21  # the start and 20 steps
    # Three independent bars on the four coordinates of C and D: rank 3 all along (no branch point).
    assert [p["rank"] for p in path["path"]] == [3] * 21
    assert path["rank_drops"] == []
    assert path["path"][-1]["parameter"] == pytest.approx(0.1, rel=0.02)
    rest = {bar: distance(FOUR_BAR_NODES[bar[0]], FOUR_BAR_NODES[bar[1]]) for bar in FOUR_BAR_BARS}
    assert rest[("D", "C")] == pytest.approx(math.sqrt(4.25))
    moved = 0.0
    for point in path["path"]:
        positions = point["positions"]
        assert positions["A"] == [0, 0] and positions["B"] == [2, 0]  # the supports stay
        for bar, length in rest.items():
            # Positions are printed to ten significant digits: 1e-9 covers the rounding.
            assert distance(positions[bar[0]], positions[bar[1]]) == pytest.approx(length, abs=1e-9)
        moved = max(moved, distance(positions["D"], FOUR_BAR_NODES["D"]))
    assert moved > 0.05  # it moves (0.1 of the characteristic length of arc)


def test_trace_equals_the_command_json(examples):
    model = examples / "truss-12.yaml"
    expected = cli_json("move", model, "--mode", 1, "--amplitude", 0.05, "--steps", 10)
    assert kinestat.trace(model, mode=1, amplitude=0.05, steps=10) == json.loads(expected)
    assert kinestat.analyze(model).trace(mode=1, amplitude=0.05, steps=10) == json.loads(expected)


def test_trace_of_the_truss_keeps_its_bars_at_root_two(examples):
    # Seed 002, Fig. 2: every bar joins points √2 apart (e.g. A (-1, -1, 0) to E (0, -1, 1)).
    path = kinestat.trace(examples / "truss-12.yaml", mode=1)
    bars = [("A", "E"), ("B", "E"), ("B", "F"), ("C", "F"), ("C", "G"), ("D", "G"), ("D", "H"), ("A", "H"),
            ("E", "F"), ("F", "G"), ("G", "H"), ("H", "E")]
    assert path["closed"]
    for point in path["path"]:
        for a, b in bars:
            assert distance(point["positions"][a], point["positions"][b]) == pytest.approx(math.sqrt(2), abs=1e-9)


def test_an_infinitesimal_mode_does_not_trace(examples):
    # Two collinear bars: the middle node's mode is blocked at second order (the tension of a
    # self-stress does work on it), so the corrector cannot close the first step.
    path = kinestat.trace(examples / "pellegrino-calladine-two-bar.yaml", mode=1)
    assert path["order"] == "infinitesimal"
    assert path["closed"] is False and path["failed_step"] == 1


def test_trace_rejects_what_the_command_rejects(examples):
    with pytest.raises(kinestat.InputError, match="numbered 1 to 1"):
        kinestat.trace(examples / "truss-12.yaml", mode=2)
    with pytest.raises(ValueError, match="framework"):
        kinestat.trace(examples / "four-bar-planar.yaml", mode=1)
    code, _, err = run_cli("move", examples / "truss-12.yaml", "--mode", 2)
    assert code == 2 and "numbered 1 to 1" in err


# examples/four-bar-planar.yaml: pivots A (0, 0) and D (5, 0) on the ground, B (1, 2), C (4, 3).
A, B, C, D = np.array([0.0, 0.0]), np.array([1.0, 2.0]), np.array([4.0, 3.0]), np.array([5.0, 0.0])


def coupler_pivot(theta):
    """C with the crank turned by theta: the intersection of the circles about B' (radius |BC|)
    and D (radius |DC|) on the side of the line B'D that C is on in the file (the assembly
    branch of the file's configuration); None when the circles do not meet."""
    rotation = np.array([[math.cos(theta), -math.sin(theta)], [math.sin(theta), math.cos(theta)]])
    b = rotation @ B
    r1, r2 = np.linalg.norm(C - B), np.linalg.norm(C - D)
    d = np.linalg.norm(D - b)
    if d > r1 + r2 or d < abs(r1 - r2):
        return None
    along = (d * d + r1 * r1 - r2 * r2) / (2 * d)
    h = math.sqrt(max(r1 * r1 - along * along, 0.0))
    u = (D - b) / d
    normal = np.array([-u[1], u[0]])
    cross = lambda p, q: p[0] * q[1] - p[1] * q[0]
    side = np.sign(cross(D - B, C - B))  # file's configuration: C is to the left of B->D
    return b + along * u + side * h * normal


@pytest.mark.parametrize("theta", [0.0, 0.3, -0.4, 0.8, -1.5, -3.0])
def test_solve_positions_of_the_four_bar_matches_the_circle_intersection(examples, theta):
    solved = kinestat.solve_positions(examples / "four-bar-planar.yaml", inputs={"A": theta})
    step = solved["steps"][0]
    expected = coupler_pivot(theta)
    assert expected is not None
    assert step["assembled"] is True
    assert step["couplings"]["C"]["point"] == pytest.approx(list(expected), abs=1e-9)
    b = np.array([[math.cos(theta), -math.sin(theta)], [math.sin(theta), math.cos(theta)]]) @ B
    assert step["couplings"]["B"]["point"] == pytest.approx(list(b), abs=1e-9)
    assert step["couplings"]["D"]["point"] == pytest.approx([5, 0], abs=1e-12)


def test_the_four_bar_cannot_be_assembled_with_the_crank_pointing_away(examples):
    # Turned so that B' = -|AB| (1, 0): |B'D| = √5 + 5 > |BC| + |CD| = 2√10, no intersection.
    theta = math.pi - math.atan2(2, 1)
    assert coupler_pivot(theta) is None
    solved = kinestat.solve_positions(examples / "four-bar-planar.yaml", inputs={"A": theta})
    assert solved["steps"][0]["assembled"] is False
    assert len(solved["not_assembled"]) == 1


def test_solve_positions_equals_the_command_json(examples):
    model = examples / "four-bar-planar.yaml"
    assert kinestat.solve_positions(model, inputs={"A": 0.3}) == json.loads(cli_json("move", model, "--input", "A=0.3"))
    swept = kinestat.solve_positions(model, sweep=("A", 0, 6.283185307179586, 12))
    assert swept == json.loads(cli_json("move", model, "--sweep", "A=0:6.283185307179586:12"))
    with pytest.raises(kinestat.InputError, match="names no coupling"):
        kinestat.solve_positions(model, inputs={"Z": 0.1})


def test_the_html_report_carries_the_traced_motion(examples, tmp_path):
    result = kinestat.analyze(examples / "four-bar-linkage.yaml")
    if not kinestat.html_built_in():
        pytest.skip("built without npm: HTML output is not built in")
    html = result.html()
    assert '"trace":{"max_residual":' in html
    out = tmp_path / "report.html"
    code, _, err = run_cli("report", examples / "four-bar-linkage.yaml", "-o", out)
    assert code == 0, err
    assert html == out.read_text()
