# SPDX-License-Identifier: BSD-3-Clause
"""Stiffness matrix, eigenpairs and the cost of over-constraint of a framework as numpy arrays
and dicts (issue 38, item 5), checked against hand values for the steel parallel leaf-spring
guide (docs/stiffness.md)."""

import math

import numpy as np
import pytest

import kinestat
from conftest import EXAMPLES

GUIDE = EXAMPLES / "parallel-leaf-spring-guide-steel.yaml"

# The guide by hand (mm, N): E, leaf length l, width w (along y), thickness t (along x).
E, L, W, T = 210000.0, 40.0, 10.0, 0.2
I_Y = W * T**3 / 12  # bending in the x z plane (the leaves' motion)
I_Z = T * W**3 / 12  # bending in the stiff y plane


def test_stiffness_matrix_is_symmetric_and_labelled():
    result = kinestat.analyze(str(GUIDE))
    stiffness, labels = result.stiffness_matrix(), result.stiffness_labels
    assert isinstance(stiffness, np.ndarray)
    assert labels == result._analysed.stiffness_matrix()[1]
    assert stiffness.shape == (len(labels), len(labels))
    assert np.allclose(stiffness, stiffness.T, rtol=0, atol=1e-9 * abs(stiffness).max())
    # The leaves' axial stiffness E A / l = 210000 * 2 / 40 = 10500 N/mm on each tip's z.
    tip = labels.index("T1.z")
    assert math.isclose(stiffness[tip, tip], 10500.0, rel_tol=1e-9)


def test_stiffness_matrix_entries_of_a_leaf_tip():
    # A leaf along +z clamped at its base, seen from its tip: 12 E I / l^3 sideways in each plane,
    # and the tip moving +x turns about +y: K_x,ry = -6 E I_y / l^2 (docs/stiffness.md's signs).
    result = kinestat.analyze(str(GUIDE))
    stiffness, labels = result.stiffness_matrix(), result.stiffness_labels
    at = labels.index
    assert math.isclose(stiffness[at("T1.x"), at("T1.x")], 12 * E * I_Y / L**3, rel_tol=1e-9)
    assert math.isclose(stiffness[at("T2.y"), at("T2.y")], 12 * E * I_Z / L**3, rel_tol=1e-9)
    assert math.isclose(stiffness[at("T1.x"), at("T1.ry")], -6 * E * I_Y / L**2, rel_tol=1e-9)
    # Nothing couples the two leaves' tips directly (the platform is a constraint, not stiffness).
    assert stiffness[at("T1.x"), at("T2.x")] == 0.0


def test_first_eigenfrequency_of_the_mass_on_the_guide():
    # k = 24 E I / l^3 = 24 * 210000 * (10 * 0.2**3 / 12) / 40**3 = 0.525 N/mm (less the platform's
    # rotation coupling, 1.6e-5 relative); m = 1e-4 t on P plus half of each leaf's
    # rho A l = 7.85e-9 * 2 * 40 t at its tip: f = sqrt(k / m) / 2 pi.
    result = kinestat.analyze(str(GUIDE))
    frequencies, shapes = result.eigenpairs()
    labels = result.stiffness_labels
    assert isinstance(frequencies, np.ndarray) and isinstance(shapes, np.ndarray)
    assert np.all(np.diff(frequencies) >= 0)
    assert shapes.shape == (len(labels), len(frequencies))
    k = 24 * E * I_Y / L**3
    m = 1e-4 + 7.85e-9 * 2 * 40
    assert math.isclose(frequencies[0], math.sqrt(k / m) / (2 * math.pi), rel_tol=1e-4)
    # The lowest mode moves P along x, the intended motion.
    mode = shapes[:, 0]
    assert abs(mode[labels.index("T1.x")]) > 10 * abs(mode[labels.index("T1.y")])


def test_over_constraint_worst_misfit_stress_by_hand():
    # One self-stress: the leaves twist against each other about x. A misfit delta of one leaf
    # end's bending_xy gives a moment delta E I_z / (2 l^2) in both leaves and a peak stress
    # M (w / 2) / I_z = delta E w / (4 l^2) = 3.28125 N/mm^2 for 0.01 mm (docs/stiffness.md).
    delta = 0.01
    cost = kinestat.analyze(str(GUIDE)).over_constraint("P", delta)
    worst = cost["misfit"]["worst"]
    assert cost["misfit"]["value"] == delta
    assert worst["element"] in ("leaf1", "leaf2")
    assert worst["force"] == 0.0
    assert math.isclose(worst["moment"], delta * E * I_Z / (2 * L**2), rel_tol=1e-9)
    assert math.isclose(worst["stress"], delta * E * W / (4 * L**2), rel_tol=1e-9)
    assert cost["frequencies"] == sorted(cost["frequencies"])
    # Linear in the misfit.
    tenfold = kinestat.analyze(str(GUIDE)).over_constraint("P", 10 * delta)
    assert math.isclose(tenfold["misfit"]["worst"]["stress"], 10 * worst["stress"], rel_tol=1e-9)


def test_exactly_constrained_guide_takes_a_misfit_without_stress(tmp_path):
    # The verdict's release (platform.T2.rx) removes the self-stress: no misfit stress at all.
    model = tmp_path / "guide-released.yaml"
    model.write_text(GUIDE.read_text().replace("nodes: [P, T1, T2]}", "nodes: [P, T1, T2], released: [T2.rx]}"))
    result = kinestat.analyze(str(model))
    assert result.exactly_constrained
    cost = result.over_constraint("P", 0.01)
    assert cost["misfit"]["worst"] is None
    frequencies, _ = result.eigenpairs(misfit=0.01)
    assert np.array_equal(frequencies, result.eigenpairs()[0])


def test_stiffness_refusals():
    result = kinestat.analyze(str(GUIDE))
    with pytest.raises(ValueError, match="misfit"):
        result.over_constraint("P", -1.0)
    with pytest.raises(ValueError, match="no node named"):
        result.over_constraint("nowhere", 0.01)
    plain = kinestat.analyze(str(EXAMPLES / "parallel-leaf-spring-guide.yaml"))
    with pytest.raises(ValueError, match="elastic data"):
        plain.stiffness_matrix()
