# SPDX-License-Identifier: BSD-3-Clause
"""Models built from numpy arrays give the results of their model files; errors carry positions."""

import numpy as np
import pytest

import kinestat


def test_braced_square_from_arrays_equals_its_file(examples):
    square = kinestat.Framework(
        nodes=np.array([[0, 0], [1, 0], [1, 1], [0, 1]]),
        node_names=["A", "B", "C", "D"],
        bars=np.array([[0, 1], [1, 2], [2, 3], [3, 0], [0, 2], [1, 3]]),
        supports={0: "fixed", "B": ["y"]},
        name="braced square")
    result = square.analyze()
    assert (result.mechanisms, result.self_stresses) == (0, 1)  # Maxwell, as in the file's comment
    assert result.to_dict() == kinestat.analyze(examples / "braced-square.yaml").to_dict()


def test_unbraced_square_is_a_mechanism():
    # Without diagonals: 4 bars, 8 - 3 = 5 coordinates, rank 4: one mechanism (the shear of the square).
    square = kinestat.Framework(nodes=[[0, 0], [1, 0], [1, 1], [0, 1]],
                                bars=[[0, 1], [1, 2], [2, 3], [3, 0]], supports={0: "fixed", 1: ["y"]})
    result = kinestat.analyze(square)
    assert (result.mechanisms, result.self_stresses) == (1, 0)
    flex = result.inf_flexes()[:, 0]
    assert abs(result.rigidity_matrix() @ flex).max() < 1e-12
    assert result.column_labels and len(result.column_labels) == 5


def test_four_bar_from_arrays_equals_its_file(examples):
    # examples/four-bar-planar.yaml: Grübler 3(4 - 1 - 4) + 4 = 1, so FN = 1, CN = 0.
    four_bar = kinestat.Network(
        types=["revolute"] * 4,
        bodies=["ground", "crank", "coupler", "rocker"],
        between=np.array([[0, 1], [1, 2], [2, 3], [3, 0]]),
        points=np.array([[0, 0], [1, 2], [4, 3], [5, 0]]),
        dimension="planar", ground="ground", name="Planar four-bar linkage")
    result = four_bar.analyze()
    assert (result.FN, result.CN) == (1, 0)
    expected = kinestat.analyze(examples / "four-bar-planar.yaml").to_dict()
    assert result.to_dict() == expected


def test_davies_network_from_arrays_equals_its_file(examples):
    nan = np.nan
    network = kinestat.Network(
        types=["spherical", "spherical", "planar", "cylindrical", "cylindrical"],
        bodies=["1", "2", "3", "4"],
        between=np.array([[2, 3], [1, 3], [0, 3], [0, 1], [0, 2]]),
        points=np.array([[0, 0, 0], [0, 0, 1], [0, 0, 0], [1, 0, 0], [0, 0, 0]]),
        axes=np.array([[nan] * 3, [nan] * 3, [nan] * 3, [0, 1, 0], [0, 1, 0]]),
        normals=np.array([[nan] * 3, [nan] * 3, [0, 0, 1], [nan] * 3, [nan] * 3]),
        dimension="spatial", ground=0, chords=["B", "E"], primary=["sa", "ta", "vc", "Ub", "We"],
        name="Davies 2-circuit network")
    result = network.analyze()
    assert (result.FN, result.CN) == (3, 2)  # seed 000
    assert result.to_dict() == kinestat.analyze(examples / "davies-2-circuit.yaml").to_dict()


def test_errors_carry_file_line_and_column(tmp_path):
    model = tmp_path / "bad.yaml"
    model.write_text("kinestat: 1\nkind: framework\nnodes: {A: [0, 0, 0], B: [1, 0, 0]}\nelements:\n  - {type: trus, nodes: [A, B]}\n")
    with pytest.raises(kinestat.InputError) as raised:
        kinestat.analyze(model)
    error = raised.value
    assert error.file == str(model)
    assert (error.line, error.column) == (5, 12)  # the value of `type`: line 5, column 12 (counted by hand)
    assert "trus" in error.problem
    assert str(error).startswith(f"{model}:5:12: error:")
    assert isinstance(error, ValueError)


def test_missing_file_is_an_input_error():
    with pytest.raises(kinestat.InputError) as raised:
        kinestat.analyze("/nonexistent-model.yaml")
    assert raised.value.file == "/nonexistent-model.yaml"


def test_errors_in_models_built_in_code_name_the_item():
    network = kinestat.Network(types=["revolute", "hinge"], between=[[0, 1], [1, 0]],
                               points=[[0, 0, 0], [1, 0, 0]], axes=[[0, 0, 1], [0, 0, 1]])
    with pytest.raises(kinestat.InputError) as raised:
        network.analyze()
    assert raised.value.file == "<network>"
    assert raised.value.line > 0 and "hinge" in raised.value.problem


def test_framework_document_holds_every_item_one_per_line():
    # Nodes and bars are written by a fast path, beams and bodies by the encoder: the document
    # must hold exactly what was given (written out here by hand), each item on a line of its own.
    fw = kinestat.Framework([[0, 0, 0], [1, 0, 0], [0.5, 0.8660254037844386, 0], [0, 0, 1e-300]],
                            bars=[[0, 1], [1, 2]], beams=[[2, 0]], beam_z=[[0, 0, 1]], rigid_bodies=[[0, 1, 3]],
                            supports={0: "fixed"}, released={2: ["torsion"], -4: ["elongation"]},
                            node_names=['a "q"', "b\\x", "\u00e7", "d"], name="every item")
    expected = {
        "kinestat": 1, "kind": "framework", "name": "every item", "dimension": "spatial",
        "nodes": {'a "q"': [0, 0, 0], "b\\x": [1, 0, 0], "\u00e7": [0.5, 0.8660254037844386, 0], "d": [0, 0, 1e-300]},
        "supports": {'a "q"': "fixed"},
        "elements": [
            {"type": "truss", "nodes": ['a "q"', "b\\x"], "released": ["elongation"]},
            {"type": "truss", "nodes": ["b\\x", "\u00e7"]},
            {"type": "beam", "nodes": ["\u00e7", 'a "q"'], "orientation": {"z": [0, 0, 1]}, "released": ["torsion"]},
            {"type": "rigid_body", "nodes": ['a "q"', "b\\x", "d"]},
        ],
    }
    assert fw.to_dict() == expected
    lines = fw.to_json().splitlines()
    assert '  {"type": "truss", "nodes": ["b\\\\x", "\\u00e7"]},' in lines
    assert '  "d": [0, 0, 1e-300]' in lines
    with pytest.raises(ValueError):
        kinestat.Framework([[0, 0], [1, float("nan")]], bars=[[0, 1]]).to_json()
    with pytest.raises(IndexError):
        kinestat.Framework([[0, 0], [1, 0]], bars=[[0, 1]], released={5: ["elongation"]}).to_json()


def test_network_document_holds_every_coupling_one_per_line():
    nan = float("nan")
    network = kinestat.Network(["revolute", "helical", "spherical"], [["g", "a"], ["a", "b"], ["b", "g"]],
                               points=[[0, 0, 0], [1.5, 0, 0], [0, 2, 0]], axes=[[0, 0, 1], [1, 0, 0], [nan, nan, nan]],
                               pitches=[nan, 0.25, nan], bodies=["g", "a", "b"], coupling_names=['R "1"', "H", "S"],
                               ground="g", name="loop")
    expected = {
        "kinestat": 1, "kind": "network", "name": "loop", "dimension": "spatial", "ground": "g", "bodies": ["g", "a", "b"],
        "couplings": [
            {"name": 'R "1"', "type": "revolute", "between": ["g", "a"], "point": [0, 0, 0], "axis": [0, 0, 1]},
            {"name": "H", "type": "helical", "between": ["a", "b"], "point": [1.5, 0, 0], "axis": [1, 0, 0], "pitch": 0.25},
            {"name": "S", "type": "spherical", "between": ["b", "g"], "point": [0, 2, 0]},
        ],
    }
    assert network.to_dict() == expected
    assert '  {"name": "H", "type": "helical", "between": ["a", "b"], "point": [1.5, 0, 0], "axis": [1, 0, 0], ' \
           '"pitch": 0.25},' in network.to_json().splitlines()
    with pytest.raises(ValueError):
        kinestat.Network(["revolute"], [[0, 1]], points=[[0, nan, 0]], axes=[[0, 0, 1]]).to_json()
