# SPDX-License-Identifier: BSD-3-Clause
"""The Python results carry the command's reports: to_dict() equals `--json`, key for key."""

import json

import pytest

import kinestat
from conftest import cli_json, example_files, model_kind, run_cli


@pytest.mark.parametrize("path", example_files(), ids=lambda p: p.name)
def test_to_dict_equals_the_command_json(path):
    kind = model_kind(path)
    command = "structure" if kind == "structure" else "analyze"
    expected = cli_json(command, path)
    result = kinestat.analyze(path)
    assert result.kind == kind
    assert result.to_dict() == json.loads(expected)
    assert result.to_json() == expected  # byte for byte


@pytest.mark.parametrize("path", [p for p in example_files() if model_kind(p) == "network"], ids=lambda p: p.name)
def test_structural_groups_of_networks_equal_the_structure_command(path):
    code, out, err = run_cli("structure", path, "--json")
    if code != 0:  # couplings that are neither lower nor higher pairs: the same error in Python
        with pytest.raises(kinestat.InputError) as raised:
            kinestat.structural_groups(path)
        assert str(raised.value) == err.strip()
        return
    assert kinestat.structural_groups(path).to_dict() == json.loads(out)


def test_seed_000_davies_two_circuit(examples):
    # Seed 000, Appendix 3: FN = 3, CN = 2; F = 13, C = 17 (2 + 2 + 3 + 3 spheric/cylindric/planar freedoms).
    result = kinestat.analyze(examples / "davies-2-circuit.yaml")
    assert isinstance(result, kinestat.NetworkResult)
    assert (result.F, result.C, result.FN, result.CN) == (13, 17, 3, 2)
    assert result.primary_motions == ["sa", "ta", "vc"]
    assert result.primary_actions == ["Ub", "We"]
    flexes, stresses = result.inf_flexes(), result.stresses()
    assert flexes.shape == (13, 3) and stresses.shape == (17, 2)
    # Every basis motion satisfies the circulation law, every action the cutset law.
    assert abs(result.unit_motion_matrix() @ flexes).max() < 1e-12
    assert abs(result.unit_action_matrix() @ stresses).max() < 1e-12
    # Short decimals: exact ranks, with their distance to another rank from a floating-point SVD.
    evidence = result.rank_evidence()
    assert evidence["motion"]["status"] == "exact" and evidence["action"]["status"] == "exact"
    assert 0 < evidence["motion"]["distance"] <= 1


def test_seed_002_braced_square_has_one_self_stress(examples):
    # Maxwell's rule on the braced square (b = 6 bars, 4 joints, 3 support constraints):
    # s - m = 6 - (8 - 3) = 1, and the square is rigid, so one self-stress, no mechanism.
    result = kinestat.analyze(examples / "braced-square.yaml")
    assert isinstance(result, kinestat.FrameworkResult)
    assert (result.mechanisms, result.self_stresses) == (0, 1)
    d = result.rigidity_matrix()
    assert d.shape == (6, 5)
    stress = result.stresses()[:, 0]
    assert abs(d.T @ stress).max() < 1e-12
    # The self-stress of a braced square: sides equal, diagonals equal and of opposite sign,
    # ratio sqrt(2) (equilibrium of a corner by hand).
    sides, diagonals = stress[:4], stress[4:]
    assert abs(abs(sides) - abs(sides[0])).max() < 1e-12
    assert abs(abs(diagonals[0]) / abs(sides[0]) - 2 ** 0.5) < 1e-12
    assert len(result.singular_values()) == 5
    # Floating point, well conditioned: certain, sigma_min / sigma_max = 0.29729 (numpy SVD of the
    # six bar directions, tests/framework/rank_status_test.cpp).
    evidence = result.rank_evidence()
    assert evidence["status"] == "certain"
    assert abs(evidence["distance"] - 0.29729) < 1e-4
    # The verdict leads the report: Maxwell's count, not exactly constrained.
    assert result.verdict["extra_motions"] == 0 and result.verdict["redundant_constraints"] == 1


def test_seed_004_structural_groups(examples):
    # Saura et al., Eq. 2: three groups, {2, 3} then {4} then {5}.
    result = kinestat.structural_groups(examples / "saura-eq2.yaml")
    assert [g["number"] for g in result.groups] == [1, 2, 3]
    assert [g["stage"] for g in result.groups] == [1, 2, 3]
    assert [len(g["bodies"]) for g in result.groups] == [2, 1, 1]
    assert result.complete
    assert result.svg().lstrip().startswith("<svg") or result.svg().lstrip().startswith("<?xml")


def test_svg_drawings(examples):
    framework = kinestat.analyze(examples / "folded-sheet-guide-5-symmetric.yaml")
    code, out, _ = run_cli("draw", examples / "folded-sheet-guide-5-symmetric.yaml")
    assert code == 0 and framework.svg() == out
    network = kinestat.analyze(examples / "davies-2-circuit.yaml")
    code, out, _ = run_cli("draw", examples / "davies-2-circuit.yaml", "--what", "graph")
    assert code == 0 and network.svg("graph") == out
    with pytest.raises(ValueError):
        framework.svg("graph")


def test_html_is_a_complete_self_contained_document(examples, tmp_path):
    # The notebook's repr wraps this document in an iframe (test_notebook_html.py).
    result = kinestat.analyze(examples / "davies-2-circuit.yaml")
    if not kinestat.html_built_in():
        assert result._repr_html_() is None
        pytest.skip("built without npm: HTML output is not built in")
    html = result.html()
    assert html.lstrip().lower().startswith("<!doctype html>")
    assert html.rstrip().endswith("</html>")
    assert "<script src=" not in html and "<link " not in html  # nothing fetched from elsewhere
    out = tmp_path / "report.html"
    code, _, err = run_cli("report", examples / "davies-2-circuit.yaml", "-o", out)
    assert code == 0, err
    assert html == out.read_text()


def test_bennett_motion_is_traced_finite(examples):
    # Issue 13: Bennett's linkage moves finitely (Bennett 1903), so its one motion passes second
    # order and its trace on the loop-closure equations closes (residual below 1e-10 relative).
    motion = kinestat.analyze(examples / "bennett.yaml").to_dict()["second_order"]["motions"][0]
    assert (motion["order"], motion["order_reason"]) == ("finite", "traced")
    assert motion["trace"]["closed"] and motion["trace"]["max_residual"] < 1e-10
    assert motion["trace"]["rank_drops"] == []
