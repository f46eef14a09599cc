# SPDX-License-Identifier: BSD-3-Clause
"""Stiffness matrix and eigenpairs of a framework as numpy arrays (issue 38, item 5), checked
against hand values for the steel parallel leaf-spring guide (docs/stiffness.md)."""

import math

import numpy as np

import kinestat
from conftest import EXAMPLES

GUIDE = EXAMPLES / "parallel-leaf-spring-guide-steel.yaml"


def test_stiffness_matrix_is_symmetric_and_labelled():
    result = kinestat.analyze(str(GUIDE))
    stiffness, labels = result._analysed.stiffness_matrix()
    assert isinstance(stiffness, np.ndarray)
    assert stiffness.shape == (len(labels), len(labels))
    assert np.allclose(stiffness, stiffness.T, rtol=0, atol=1e-9 * abs(stiffness).max())
    # The leaves' axial stiffness E A / l = 210000 * 2 / 40 = 10500 N/mm on each tip's z.
    tip = labels.index("T1.z")
    assert math.isclose(stiffness[tip, tip], 10500.0, rel_tol=1e-9)


def test_first_eigenfrequency_of_the_mass_on_the_guide():
    # k = 24 E I / l^3 = 24 * 210000 * (10 * 0.2**3 / 12) / 40**3 = 0.525 N/mm (less the platform's
    # rotation coupling, 1.6e-5 relative); m = 1e-4 t on P plus half of each leaf's
    # rho A l = 7.85e-9 * 2 * 40 t at its tip: f = sqrt(k / m) / 2 pi.
    result = kinestat.analyze(str(GUIDE))
    frequencies, shapes, labels = result._analysed.eigenpairs()
    assert np.all(np.diff(frequencies) >= 0)
    assert shapes.shape == (len(labels), len(frequencies))
    k = 24 * 210000 * (10 * 0.2**3 / 12) / 40**3
    m = 1e-4 + 7.85e-9 * 2 * 40
    assert math.isclose(frequencies[0], math.sqrt(k / m) / (2 * math.pi), rel_tol=1e-4)
    # The lowest mode moves P along x, the intended motion.
    mode = shapes[:, 0]
    assert abs(mode[labels.index("T1.x")]) > 10 * abs(mode[labels.index("T1.y")])
