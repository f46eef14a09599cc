# SPDX-License-Identifier: BSD-3-Clause
"""Framework.from_pyrigi / to_pyrigi (issue 39, item 2). PyRigi is optional: these tests are
skipped when `import pyrigi` fails, except the one that checks the ImportError itself.

The counts are by hand (Maxwell: flexes = d n - rank, rank = bars when no bar is redundant;
trivial flexes 3 in the plane, 6 in space), not from either program."""

import math
import sys

import numpy as np
import pytest

import kinestat


@pytest.fixture
def pyrigi():
    return pytest.importorskip("pyrigi")


def _square(**options):
    # The unit square without a diagonal: 2*4 - 4 = 4 flexes, 3 of them rigid motions, 1 shear.
    return kinestat.Framework([[0, 0], [1, 0], [1, 1], [0, 1]], bars=[[0, 1], [1, 2], [2, 3], [3, 0]], **options)


def _edges(graph):
    return {frozenset(edge) for edge in graph.edge_list()}


def test_missing_pyrigi_is_an_import_error_naming_it(monkeypatch):
    monkeypatch.setitem(sys.modules, "pyrigi", None)  # `import pyrigi` now raises ImportError
    with pytest.raises(ImportError, match="PyRigi"):
        _square().to_pyrigi()
    with pytest.raises(ImportError, match="PyRigi"):
        kinestat.Framework.from_pyrigi(object())


def test_triangle_to_pyrigi_and_back(pyrigi):
    triangle = kinestat.Framework([[0, 0], [1, 0], [0, 1]], bars=[[0, 1], [1, 2], [2, 0]])
    converted = triangle.to_pyrigi()
    assert isinstance(converted, pyrigi.Framework)
    assert converted.dim == 2
    assert converted.graph.vertex_list() == [0, 1, 2]  # default names "0", "1", "2" -> PyRigi's integers
    assert _edges(converted.graph) == {frozenset({0, 1}), frozenset({1, 2}), frozenset({0, 2})}
    assert converted.realization(as_points=True) == {0: [0, 0], 1: [1, 0], 2: [0, 1]}  # exact integers
    # 2*3 - 3 = 3 flexes, all rigid motions: infinitesimally rigid in both programs.
    assert converted.is_inf_rigid() is True
    back = kinestat.Framework.from_pyrigi(converted)
    assert back.node_names == ["0", "1", "2"]
    np.testing.assert_array_equal(back.nodes, [[0, 0], [1, 0], [0, 1]])
    assert {frozenset(bar) for bar in back.bars.tolist()} == {frozenset({0, 1}), frozenset({1, 2}), frozenset({0, 2})}
    result = back.analyze()
    assert (result.mechanisms, result.self_stresses) == (3, 0)
    assert result.is_inf_rigid() and result.nontrivial_inf_flexes().shape[1] == 0


def test_square_without_diagonal_has_one_flex_in_both(pyrigi):
    converted = _square().to_pyrigi()
    assert _edges(converted.graph) == {frozenset({0, 1}), frozenset({1, 2}), frozenset({2, 3}), frozenset({0, 3})}
    assert converted.is_inf_rigid() is False
    assert len(converted.inf_flexes()) == 1  # PyRigi's non-trivial flexes: the shear
    back = kinestat.Framework.from_pyrigi(converted)
    result = back.analyze()
    assert (result.mechanisms, result.self_stresses) == (4, 0)  # 2*4 - 4
    assert not result.is_inf_rigid()
    assert result.trivial_inf_flexes().shape[1] == 3
    assert result.nontrivial_inf_flexes().shape[1] == 1


def test_supports_are_refused_or_dropped_on_request(pyrigi):
    held = _square(supports={0: "fixed", 1: ["y"]})
    with pytest.raises(ValueError, match="drop_supports=True"):
        held.to_pyrigi()
    # Held in place: 8 - 3 held = 5 coordinates, 4 bars: 1 mechanism, the shear; the free PyRigi
    # framework has the same one non-trivial flex.
    assert held.analyze().mechanisms == 1
    free = held.to_pyrigi(drop_supports=True)
    assert _edges(free.graph) == _edges(_square().to_pyrigi().graph)
    assert len(free.inf_flexes()) == 1
    with pytest.raises(ValueError, match="drop_supports=True"):
        _square(independent={0: ["x"]}).to_pyrigi()


def test_what_pyrigi_cannot_hold_is_refused(pyrigi):
    with pytest.raises(ValueError, match="beams"):
        kinestat.Framework([[0, 0], [1, 0], [1, 1]], bars=[[0, 1]], beams=[[1, 2]]).to_pyrigi()
    with pytest.raises(ValueError, match="rigid_bodies"):
        kinestat.Framework([[0, 0], [1, 0], [1, 1]], rigid_bodies=[[0, 1, 2]]).to_pyrigi()
    with pytest.raises(ValueError, match="released"):
        _square(released={0: ["elongation"]}).to_pyrigi()
    with pytest.raises(ValueError, match="bars 0 and 1 join the same nodes"):
        kinestat.Framework([[0, 0], [1, 0]], bars=[[0, 1], [1, 0]]).to_pyrigi()


def test_pyrigi_labels_and_symbolic_coordinates(pyrigi):
    sympy = pytest.importorskip("sympy")
    # An equilateral triangle with an exact apex, and a pendant bar: 2*4 - 4 = 4 flexes, 3
    # trivial, 1 the pendant bar turning about "c".
    graph = pyrigi.Graph([("a", "b"), ("b", "c"), ("a", "c"), ("c", "d")])
    realization = {"a": [0, 0], "b": [1, 0], "c": [sympy.Rational(1, 2), sympy.sqrt(3) / 2], "d": [2, 3]}
    framework = kinestat.Framework.from_pyrigi(pyrigi.Framework(graph, realization), name="pendant")
    assert framework.node_names == ["a", "b", "c", "d"]
    assert framework.name == "pendant"
    np.testing.assert_array_equal(framework.nodes, [[0, 0], [1, 0], [0.5, math.sqrt(3) / 2], [2, 3]])
    assert len(framework.bars) == 4
    result = framework.analyze()
    assert (result.mechanisms, result.self_stresses) == (4, 0)
    assert result.nontrivial_inf_flexes().shape[1] == 1
    back = framework.to_pyrigi()
    assert back.graph.vertex_list() == ["a", "b", "c", "d"]  # names that are not the default stay names
    assert _edges(back.graph) == _edges(graph)
    assert back.realization(as_points=True)["d"] == [2, 3]
    assert back.realization(as_points=True, numerical=True)["c"] == [0.5, math.sqrt(3) / 2]


def test_spatial_tetrahedron(pyrigi):
    # 3*4 - 6 = 6 flexes, all rigid motions of space.
    nodes = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
    bars = [[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]]
    converted = kinestat.Framework(nodes, bars=bars).to_pyrigi()
    assert converted.dim == 3
    assert converted.is_inf_rigid() is True
    result = kinestat.Framework.from_pyrigi(converted).analyze()
    assert (result.dimension, result.mechanisms, result.self_stresses) == (3, 6, 0)
    assert result.is_inf_rigid()


def test_from_pyrigi_refusals(pyrigi):
    sympy = pytest.importorskip("sympy")
    with pytest.raises(TypeError, match="pyrigi.Framework"):
        kinestat.Framework.from_pyrigi({"nodes": []})
    with pytest.raises(ValueError, match="1-dimensional"):
        kinestat.Framework.from_pyrigi(pyrigi.Framework(pyrigi.Graph([(0, 1)]), {0: [0], 1: [1]}))
    x = sympy.Symbol("x")
    with pytest.raises(ValueError, match="vertex 1: coordinate x is not a number"):
        kinestat.Framework.from_pyrigi(pyrigi.Framework(pyrigi.Graph([(0, 1)]), {0: [0, 0], 1: [x, 0]}))
    with pytest.raises(ValueError, match="same name '1'"):
        kinestat.Framework.from_pyrigi(pyrigi.Framework(pyrigi.Graph([(1, "1")]), {1: [0, 0], "1": [1, 0]}))
