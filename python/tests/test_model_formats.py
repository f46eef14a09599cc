# SPDX-License-Identifier: BSD-3-Clause
"""Model files of other programs (SPACAR, URDF, SDFormat, MJCF) read from Python as
`kinestat analyze` reads them. Expected counts are hand derivations (Grübler–Kutzbach and the
known mobility of each linkage), not kinestat's output."""

import pytest

import kinestat
from conftest import cli_json

ROBOT_FILES = {"URDF": "urdf", "SDFormat": "sdf", "MJCF": "xml"}

# (file stem, FN, CN). FN − CN = F − 6l (Davies' identity).
# four-bar: 4 revolutes with parallel axes, one loop: F − 6l = 4 − 6 = −2; it moves with one
#   freedom (planar four-bar), so FN = 1 and CN = 3 (the planar linkage's 3 redundant
#   constraints in space).
# stewart-6ups: 6 U-P-S legs, 5 independent loops: F = 6·(2 + 1 + 3) = 36, 36 − 30 = 6; the
#   platform has its 6 freedoms and nothing is redundant: FN = 6, CN = 0.
# delta: 3 translational freedoms (Clavel's Delta robot); its parallelograms of revolutes make
#   FN − CN = −9, so CN = 12.
ROBOTS = [("four-bar", 1, 3), ("stewart-6ups", 6, 0), ("delta", 3, 12)]


def test_formats_always_include_kinestat_and_spacar():
    assert {"kinestat", "SPACAR"} <= set(kinestat.formats())


@pytest.mark.parametrize("format_name,extension", sorted(ROBOT_FILES.items()))
@pytest.mark.parametrize("stem,fn,cn", ROBOTS)
def test_robot_files_read_from_python(examples, format_name, extension, stem, fn, cn):
    if format_name not in kinestat.formats():
        pytest.skip(f"{format_name} is not built in")
    path = examples / "robots" / f"{stem}.{extension}"
    result = kinestat.analyze(path)
    assert result.kind == "network"
    assert (result.FN, result.CN) == (fn, cn)
    assert result.FN - result.CN == result.F - 6 * result.to_dict()["l"]
    # The same report as the command's, key for key.
    assert result.to_json() == cli_json("analyze", path)


def test_spacar_file_is_a_framework_with_its_notices(examples):
    # The parallel leaf-spring guide: two leaf springs in parallel guide the shuttle along one
    # direction; the pair is statically indeterminate once (both leaves resist the same
    # in-plane rotation), the classic overconstraint of this guide.
    path = examples / "spacar" / "parallel-leaf-spring-guide.dat"
    result = kinestat.analyze(path)
    assert result.kind == "framework"
    assert result.to_dict()["self_stresses"] == 1
    assert result.to_dict()["mechanisms"] == 0
    assert any("ignored after the kinematic part" in notice for notice in result.notices)
    assert result.to_json() == cli_json("analyze", path)


def test_kinestat_files_have_no_notices(examples):
    assert kinestat.analyze(examples / "davies-2-circuit.yaml").notices == []


def test_unknown_xml_root_is_an_input_error(tmp_path):
    path = tmp_path / "model.xml"
    path.write_text("<scene/>\n")
    with pytest.raises(kinestat.InputError) as raised:
        kinestat.analyze(path)
    assert raised.value.line == 1
    assert "expected <mujoco>, <robot> or <sdf>" in str(raised.value)
