# SPDX-License-Identifier: BSD-3-Clause
"""The Python API refuses what the command refuses (issue 40, items 6 and 7): tolerances that are
not positive finite numbers, NaN coordinates, indices out of range; a missing file is a
FileNotFoundError. Every refusal is also a kinestat.InputError (a ValueError)."""

import errno
import math
import os
import subprocess
import sys

import pytest

import kinestat

TRIANGLE = dict(nodes=[[0, 0], [1, 0], [0, 1]], bars=[[0, 1], [1, 2], [2, 0]], supports={0: "fixed", 1: ["y"]})
BAD_TOLERANCES = [math.nan, -1, 0, math.inf, -math.inf, "1e-9", True]


@pytest.mark.parametrize("tolerance", BAD_TOLERANCES)
def test_a_tolerance_is_a_positive_finite_number(tolerance, examples):
    calls = [
        lambda: kinestat.analyze(examples / "davies-2-circuit.yaml", tolerance=tolerance),
        lambda: kinestat.Framework(**TRIANGLE).analyze(tolerance=tolerance),
        lambda: kinestat.trace(examples / "four-bar-linkage.yaml", tolerance=tolerance),
        lambda: kinestat.sweep(examples / "sweeps" / "collinear-bars.yaml", tolerance=tolerance),
    ]
    for call in calls:
        with pytest.raises(kinestat.InputError, match="tolerance") as raised:
            call()
        assert isinstance(raised.value, ValueError)
        assert "expected a positive number" in raised.value.problem


def test_a_valid_tolerance_is_used():
    # The triangle is rigid (3 bars, 3 free coordinates) whatever reasonable tolerance is given.
    result = kinestat.Framework(**TRIANGLE).analyze(tolerance=1e-6)
    assert (result.mechanisms, result.self_stresses) == (0, 0)


def test_nan_and_infinite_coordinates_are_refused_naming_the_node():
    for bad in (math.nan, math.inf):
        with pytest.raises(kinestat.InputError, match="node 'B'") as raised:
            kinestat.Framework([[0, 0], [1, bad], [0, 1]], bars=[[0, 1]], node_names=["A", "B", "C"])
        assert isinstance(raised.value, ValueError) and "not a finite number" in raised.value.problem
    with pytest.raises(kinestat.InputError, match="beam 0"):
        kinestat.Framework([[0, 0, 0], [1, 0, 0]], beams=[[0, 1]], beam_z=[[0, math.nan, 1]])


def test_a_bar_index_out_of_range_names_the_bar_and_the_node():
    with pytest.raises(kinestat.ModelIndexError) as raised:
        kinestat.Framework([[0, 0], [1, 0], [0, 1]], bars=[[0, 1], [1, 3]])
    error = raised.value
    assert isinstance(error, IndexError) and isinstance(error, kinestat.InputError) and isinstance(error, ValueError)
    assert "bars[1] = [1, 3]" in str(error) and "node index 3" in str(error) and "3 nodes, 0 to 2" in str(error)
    # A negative index is refused too (numpy would silently take the last node).
    with pytest.raises(IndexError, match="node index -1"):
        kinestat.Framework([[0, 0], [1, 0]], bars=[[0, -1]])
    with pytest.raises(IndexError, match=r"rigid_bodies\[0\]: node index 2"):
        kinestat.Framework([[0, 0], [1, 0]], rigid_bodies=[[0, 2]])
    with pytest.raises(IndexError, match="supports: node index 5"):
        kinestat.Framework([[0, 0], [1, 0]], bars=[[0, 1]], supports={5: "fixed"})
    with pytest.raises(IndexError, match=r"between\[1\] \(coupling 'B'\): body index 4"):
        kinestat.Network(["revolute", "revolute"], [[0, 1], [1, 4]], points=[[0, 0], [1, 0]], dimension="planar",
                         bodies=["g", "a"]).to_json()


def test_a_missing_file_is_file_not_found(tmp_path):
    missing = tmp_path / "no-such-model.yaml"
    for call in (kinestat.analyze, kinestat.structural_groups, kinestat.trace, kinestat.solve_positions, kinestat.sweep):
        with pytest.raises(FileNotFoundError) as raised:
            call(missing)
        error = raised.value
        assert error.errno == errno.ENOENT and error.filename == str(missing)
        assert isinstance(error, kinestat.InputError) and error.file == str(missing)
    with pytest.raises(kinestat.InputError):  # code that catches InputError still catches it
        kinestat.analyze(os.fspath(missing))


def test_every_node_supported_counts_the_redundant_bar():
    # By hand (issue 40): a planar framework of two fixed nodes and one bar between them has no
    # free coordinate (D(c) has 1 row, 0 columns, rank 0): no mechanism and CN = 1 - 0 = 1
    # self-stress. In a subprocess: this crashed the interpreter before the fix.
    script = ("import kinestat\n"
              "r = kinestat.Framework([[0, 0], [1, 0]], bars=[[0, 1]], supports={0: 'fixed', 1: 'fixed'}).analyze()\n"
              "print(r.mechanisms, r.self_stresses)\n")
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120, check=False)
    assert done.returncode == 0, done.stderr[-2000:]
    assert done.stdout.split() == ["0", "1"]


@pytest.mark.parametrize("bad", [math.nan, math.inf, -1.0, 0.0])
def test_trace_and_position_numbers_are_finite(bad, examples):
    # As `kinestat move`: the amplitude a positive finite number, inputs and sweep ends finite.
    with pytest.raises(ValueError, match="amplitude"):
        kinestat.trace(examples / "four-bar-linkage.yaml", amplitude=bad)
    if not math.isfinite(bad):
        with pytest.raises(ValueError, match="not a finite number"):
            kinestat.solve_positions(examples / "four-bar-planar.yaml", inputs={"A": bad})
        with pytest.raises(ValueError, match="finite"):
            kinestat.solve_positions(examples / "four-bar-planar.yaml", sweep=("A", 0.0, bad, 10))
