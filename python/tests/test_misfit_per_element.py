# SPDX-License-Identifier: BSD-3-Clause
"""A misfit per element from Python (issue 38's leftover): `over_constraint` and `eigenpairs`
take a length for every element or a dict {element name: length}, as the command's `--misfit
VALUE` and `--misfit ELEMENT=VALUE`. Values by the force method on the braced square worked by
hand in docs/stiffness.md (and tests/report/cost_scene_test.cpp)."""

import json
import math

import numpy as np
import pytest

import kinestat
from conftest import EXAMPLES, run_cli

GUIDE = EXAMPLES / "parallel-leaf-spring-guide-steel.yaml"

# The braced square by hand (mm, N): side a, every bar of area A and modulus E, on statically
# determinate supports. Its one self-stress is sides -1, diagonals sqrt(2); S^T F S =
# (4 a + 2 * 2 a sqrt(2)) / EA = 4 a (1 + sqrt(2)) / EA. A misfit delta of one bar (made delta
# short) alone gives alpha = s_bar delta EA / (4 a (1 + sqrt(2))) and forces alpha * s.
A_SIDE, AREA, E = 100.0, 3.0, 210000.0
FLEXIBILITY = 4 * A_SIDE * (1 + math.sqrt(2)) / (E * AREA)  # S^T F S
SIDES, DIAGONALS = ("s1", "s2", "s3", "s4"), ("d1", "d2")

SQUARE = f"""kinestat: 1
kind: framework
name: braced square
dimension: planar
units: mm
materials: {{steel: {{E: {E:g}, G: 80000}}}}
sections: {{bar: {{area: {AREA:g}}}}}
defaults: {{material: steel, section: bar}}
nodes: {{A: [0, 0], B: [{A_SIDE:g}, 0], C: [{A_SIDE:g}, {A_SIDE:g}], D: [0, {A_SIDE:g}]}}
supports: {{A: fixed, B: [y]}}
elements:
  - {{name: s1, type: truss, nodes: [A, B]}}
  - {{name: s2, type: truss, nodes: [B, C]}}
  - {{name: s3, type: truss, nodes: [C, D]}}
  - {{name: s4, type: truss, nodes: [D, A]}}
  - {{name: d1, type: truss, nodes: [A, C]}}
  - {{name: d2, type: truss, nodes: [B, D]}}
"""


@pytest.fixture(name="square")
def square_file(tmp_path):
    path = tmp_path / "braced-square.yaml"
    path.write_text(SQUARE)
    return path


def forces_of(cost):
    return {e["element"]: e["force"] for e in cost["misfit"]["elements"]}


def test_one_diagonal_alone_by_hand(square):
    # delta on d1 only: alpha = sqrt(2) delta EA / (4 a (1 + sqrt(2))); diagonals sqrt(2) alpha =
    # EA delta / (2 a (1 + sqrt(2))) in tension, sides -alpha; stresses over A.
    delta = 0.002
    cost = kinestat.analyze(str(square)).over_constraint("C", {"d1": delta})
    misfit = cost["misfit"]
    assert misfit["value"] is None
    assert misfit["per_element"] == {"d1": delta}
    diagonal = E * AREA * delta / (2 * A_SIDE * (1 + math.sqrt(2)))
    side = -math.sqrt(2) * E * AREA * delta / (4 * A_SIDE * (1 + math.sqrt(2)))
    forces = forces_of(cost)
    for name in DIAGONALS:
        assert math.isclose(forces[name], diagonal, rel_tol=1e-9), name
    for name in SIDES:
        assert math.isclose(forces[name], side, rel_tol=1e-9), name
    worst = misfit["worst"]
    assert worst["source"] == "d1.elongation"
    assert worst["element"] in DIAGONALS
    assert math.isclose(worst["stress"], E * delta / (2 * A_SIDE * (1 + math.sqrt(2))), rel_tol=1e-9)
    # The other diagonal alone: its own case, the same forces.
    other = kinestat.analyze(str(square)).over_constraint("C", {"d2": delta})
    assert other["misfit"]["worst"]["source"] == "d2.elongation"
    assert math.isclose(forces_of(other)["s3"], side, rel_tol=1e-9)


@pytest.mark.parametrize("side_misfit, worst_source", [(1.5e-3, "s1.elongation"), (1.3e-3, "d1.elongation")])
def test_a_side_tolerance_beats_the_diagonal_only_when_sqrt2_delta_s_over_4_exceeds_delta_d_over_2(square, side_misfit,
                                                                                                   worst_source):
    # The diagonals' |force| is sqrt(2) delta_s EA / (4 a (1 + sqrt(2))) from a side and
    # delta_d EA / (2 a (1 + sqrt(2))) from a diagonal: 1.5e-3 * sqrt(2) / 4 = 5.30e-4 > 5e-4 >
    # 1.3e-3 * sqrt(2) / 4 = 4.60e-4 for delta_d = 1e-3.
    delta_d = 1e-3
    cost = kinestat.analyze(str(square)).over_constraint("C", {"d1": delta_d, "s1": side_misfit})
    worst = cost["misfit"]["worst"]
    assert worst["source"] == worst_source
    assert worst["element"] in DIAGONALS
    if worst_source.startswith("s1"):
        # A side made short: the diagonals are pushed, compression.
        expected = -math.sqrt(2) * side_misfit * E * AREA / (4 * A_SIDE * (1 + math.sqrt(2)))
    else:
        expected = delta_d * E * AREA / (2 * A_SIDE * (1 + math.sqrt(2)))
    assert math.isclose(worst["force"], expected, rel_tol=1e-9)
    assert math.isclose(worst["stress"], abs(expected) / AREA, rel_tol=1e-9)


def test_a_number_is_the_same_misfit_for_every_element(square):
    result = kinestat.analyze(str(square))
    delta = 0.002
    plain = result.over_constraint("C", delta)["misfit"]
    named = result.over_constraint("C", {name: delta for name in SIDES + DIAGONALS})["misfit"]
    assert plain["value"] == delta and "per_element" not in plain
    # Every element the same: the worst case is a diagonal's (delta / 2 > sqrt(2) delta / 4).
    assert math.isclose(plain["worst"]["stress"], E * delta / (2 * A_SIDE * (1 + math.sqrt(2))), rel_tol=1e-9)
    assert named["worst"] == plain["worst"]
    assert named["elements"] == plain["elements"]


def test_python_gives_the_commands_per_element_block(square):
    code, out, err = run_cli("stiffness", square, "--at", "C", "--misfit", "d1=0.002", "--misfit", "s1=0.0015", "--json")
    assert code == 0, err
    command = json.loads(out)["misfit"]
    python = kinestat.analyze(str(square)).over_constraint("C", {"s1": 0.0015, "d1": 0.002})["misfit"]
    assert command["per_element"] == {"d1": 0.002, "s1": 0.0015}
    assert python == command


def test_eigenpairs_take_a_misfit_per_element():
    result = kinestat.analyze(str(GUIDE))
    unstressed, _ = result.eigenpairs()
    # The platform is a rigid body: no misfit for it (a length does not size its rotations), so
    # naming only it locks in nothing, and zero for every leaf locks in nothing either.
    assert np.array_equal(result.eigenpairs(misfit={"platform": 0.01})[0], unstressed)
    assert np.array_equal(result.eigenpairs(misfit={"leaf1": 0.0, "leaf2": 0.0})[0], unstressed)
    # Both leaves named with the plain value: the same misfit as the plain value.
    assert np.array_equal(result.eigenpairs(misfit={"leaf1": 0.01, "leaf2": 0.01})[0], result.eigenpairs(misfit=0.01)[0])
    # As the command gives them (10 significant digits in its JSON).
    code, out, err = run_cli("stiffness", GUIDE, "--at", "P", "--misfit", "leaf1=0.01", "--json")
    assert code == 0, err
    command = json.loads(out)["frequencies_with_misfit"]
    frequencies, _ = result.eigenpairs(misfit={"leaf1": 0.01})
    assert np.allclose(frequencies[: len(command)], command, rtol=1e-9, atol=0)
    assert result.over_constraint("P", {"leaf1": 0.01})["frequencies_with_misfit"] == command


def test_bad_misfits_are_refused_naming_what_is_wrong(square):
    result = kinestat.analyze(str(square))
    with pytest.raises(ValueError, match="misfit: the model has no element named 'd9'"):
        result.over_constraint("C", {"d1": 0.001, "d9": 0.001})
    with pytest.raises(ValueError, match="misfit of element 'd1' must be a finite length, zero or more, not -0.001"):
        result.over_constraint("C", {"d1": -0.001})
    with pytest.raises(ValueError, match="misfit of element 's2' must be a finite length, zero or more, not nan"):
        result.over_constraint("C", {"s2": float("nan")})
    with pytest.raises(ValueError, match="misfit must be a finite length, zero or more, not inf"):
        result.over_constraint("C", math.inf)
    with pytest.raises(ValueError, match="names no element"):
        result.over_constraint("C", {})
    with pytest.raises(ValueError, match="1 is not an element name"):
        result.over_constraint("C", {1: 0.001})
    with pytest.raises(ValueError, match="misfit of element 'd1': '0.001' is not a number"):
        result.over_constraint("C", {"d1": "0.001"})
    guide = kinestat.analyze(str(GUIDE))
    with pytest.raises(ValueError, match="no element named 'leaf3'"):
        guide.eigenpairs(misfit={"leaf3": 0.01})
