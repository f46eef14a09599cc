# SPDX-License-Identifier: BSD-3-Clause
"""The cost of over-constraint in a framework report with elastic data (issue 38, items 2 and 5):
the Python report goes through the same pipeline as `kinestat analyze --json`, so it carries
the same `stiffness` and `misfit` keys, per mm of misfit when none is given."""

import json
import math

import kinestat
from conftest import EXAMPLES

GUIDE = EXAMPLES / "parallel-leaf-spring-guide-steel.yaml"

# By hand (mm, N): 24 E I / l^3 with I = w t^3 / 12 (docs/stiffness.md), and the peak stress per
# mm of misfit of the guide's one self-stress, E w / (4 l^2).
E, L, W, T = 210000.0, 40.0, 10.0, 0.2


def test_report_carries_the_stiffness_at_the_guided_node_and_the_misfit_per_mm():
    report = json.loads(kinestat.analyze(str(GUIDE)).to_json())
    assert report["stiffness"]["at"] == "P"
    assert math.isclose(report["stiffness"]["matrix"][0][0], 24 * E * (W * T**3 / 12) / L**3, rel_tol=1e-9)
    assert report["misfit"]["per_unit"] is True
    assert report["misfit"]["unit"] == "mm"
    assert math.isclose(report["misfit"]["worst"]["stress"], E * W / (4 * L**2), rel_tol=1e-6)


def test_report_without_elastic_data_has_no_cost_keys():
    report = json.loads(kinestat.analyze(str(EXAMPLES / "folded-sheet-guide-6.yaml")).to_json())
    assert "stiffness" not in report and "misfit" not in report
