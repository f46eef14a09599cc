# SPDX-License-Identifier: BSD-3-Clause
"""The API a rigidity user expects (issue 39, item 2): PyRigi's names on framework results, one
set of names for the counts of every kind, a repr with the counts and the verdict, a version,
nothing but the API in the package's namespace. Expected values are counted by hand."""

import pathlib
import re

import numpy as np
import pytest

import kinestat

ROOT = pathlib.Path(__file__).resolve().parents[2]


def framework(nodes, bars, **keywords):
    return kinestat.Framework(np.array(nodes, dtype=float), bars=bars, **keywords).analyze()


def test_a_free_triangle_is_infinitesimally_rigid():
    # 3 nodes in the plane: 6 coordinates, 3 independent bars: 3 flexes, all of them the rigid
    # motions of the plane (2 translations, 1 rotation).
    result = framework([[0, 0], [1, 0], [0.3, 1]], [[0, 1], [1, 2], [2, 0]])
    assert (result.mechanisms, result.self_stresses) == (3, 0)
    assert result.trivial_inf_flexes().shape == (6, 3)
    assert result.is_inf_rigid()
    assert result.inf_flexes().shape == (6, 0)  # PyRigi's default: without the trivial ones
    assert result.inf_flexes(include_trivial=True).shape == (6, 3)
    assert result.rigid_components() == [["0", "1", "2"]]


def test_a_free_square_has_one_nontrivial_flex():
    # 4 nodes, 8 coordinates, 4 bars: 4 flexes, 3 of them rigid motions; the fourth is the shear.
    nodes = [[0, 0], [1, 0], [1, 1], [0, 1]]
    result = framework(nodes, [[0, 1], [1, 2], [2, 3], [3, 0]])
    assert result.mechanisms == 4 and not result.is_inf_rigid()
    trivial, flex = result.trivial_inf_flexes(), result.nontrivial_inf_flexes()
    assert trivial.shape == (8, 3) and flex.shape == (8, 1)
    assert np.allclose(trivial.T @ trivial, np.eye(3)) and abs(trivial.T @ flex).max() < 1e-12
    D = result.rigidity_matrix()
    assert abs(D @ flex).max() < 1e-12 and abs(D @ trivial).max() < 1e-12
    # The shear by hand: the top nodes 2 and 3 move along x, the bottom ones stay (columns are x,
    # y of each node in order). The non-trivial flex lies in the span of the shear and the rigid
    # motions.
    shear = np.zeros(8)
    shear[[4, 6]] = 1.0
    span = np.column_stack([trivial, shear])
    assert np.linalg.matrix_rank(np.column_stack([span, flex]), tol=1e-9) == 4
    # Each bar is its own generic rigid component.
    assert sorted(map(sorted, result.rigid_components())) == [["0", "1"], ["0", "3"], ["1", "2"], ["2", "3"]]


def test_a_free_tetrahedron_has_the_six_rigid_motions_of_space():
    # 12 coordinates, 6 bars of a tetrahedron (independent): 6 flexes, the rigid motions.
    result = framework([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
                       [[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]])
    assert result.dimension == 3 and result.mechanisms == 6
    assert result.trivial_inf_flexes().shape == (12, 6) and result.is_inf_rigid()


def test_collinear_nodes_in_space_have_five_rigid_motions():
    # Three nodes on the x axis, two bars: 9 - 2 = 7 flexes. The rotation about the x axis moves
    # no node, so only 5 rigid motions are flexes; the middle node's two sideways motions remain.
    result = framework([[0, 0, 0], [1, 0, 0], [2, 0, 0]], [[0, 1], [1, 2]])
    assert result.mechanisms == 7
    assert result.trivial_inf_flexes().shape[1] == 5
    assert result.nontrivial_inf_flexes().shape[1] == 2 and not result.is_inf_rigid()


def test_supports_leave_no_trivial_flex():
    # Node 0 fixed, node 1 held in y: no rigid motion of the plane is allowed. The braced square
    # is rigid (Maxwell 6 - 5 = 1 self-stress); without diagonals it shears (1 mechanism).
    supports = {0: "fixed", 1: ["y"]}
    square = [[0, 0], [1, 0], [1, 1], [0, 1]]
    braced = framework(square, [[0, 1], [1, 2], [2, 3], [3, 0], [0, 2], [1, 3]], supports=supports)
    assert braced.trivial_inf_flexes().shape == (5, 0) and braced.is_inf_rigid()
    assert braced.stresses().shape == (6, 1)
    open_square = framework(square, [[0, 1], [1, 2], [2, 3], [3, 0]], supports=supports)
    assert not open_square.is_inf_rigid()
    assert np.array_equal(open_square.inf_flexes(), open_square.inf_flexes(include_trivial=True))


def test_the_sparse_rigidity_matrix_is_the_dense_one():
    pytest.importorskip("scipy.sparse")
    result = framework([[0, 0], [1, 0], [1, 1], [0, 1]], [[0, 1], [1, 2], [2, 3], [3, 0], [0, 2]])
    sparse = result.rigidity_matrix(sparse=True)
    assert sparse.shape == (5, 8) and sparse.nnz < 5 * 8
    assert np.array_equal(sparse.toarray(), result.rigidity_matrix())


def test_every_kind_answers_to_the_same_count_names(examples):
    network = kinestat.analyze(examples / "davies-2-circuit.yaml")
    assert (network.mechanisms, network.self_stresses) == (network.FN, network.CN) == (3, 2)  # seed 000
    braced = kinestat.analyze(examples / "braced-square.yaml")
    assert (braced.FN, braced.CN) == (braced.mechanisms, braced.self_stresses) == (0, 1)
    for result in (network, braced):
        assert result.exactly_constrained is False
        assert result.summary == result.to_dict()["verdict"]["summary"]


def test_repr_shows_the_counts_and_the_verdict(examples):
    text = repr(kinestat.analyze(examples / "braced-square.yaml"))
    assert "braced-square.yaml" in text and "mechanisms = 0, self_stresses = 1" in text
    assert text.splitlines()[1].strip().startswith("Not exactly constrained: 1 redundant constraint")
    assert "FN = 3, CN = 2" in repr(kinestat.analyze(examples / "davies-2-circuit.yaml"))
    groups = repr(kinestat.structural_groups(examples / "saura-eq2.yaml"))
    assert "3 structural groups, complete" in groups  # SG-I, SG-II, SG-III (seed 004, eq. 2)


def test_the_version_is_the_projects():
    # Read from CMakeLists.txt independently of the build.
    version = re.search(r"project\(kinestat VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text()).group(1)
    assert kinestat.__version__ == version


def test_only_the_api_is_in_the_namespace():
    for private in ("np", "json", "os", "math", "errno", "numbers"):
        assert not hasattr(kinestat, private), private
    for name in kinestat.__all__:
        assert hasattr(kinestat, name), name
