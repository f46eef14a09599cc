# SPDX-License-Identifier: BSD-3-Clause
"""Networks above 300 couplings take the sparse body-twist path from Python, as `kinestat
analyze` does (Davies' dense matrices grow as the cube of the network: a ring of 3,000
revolutes ran the machine out of memory before)."""

import numpy as np
import pytest

import kinestat
from conftest import cli_json


def ring(e):
    # e revolutes with parallel axes (z) joining e bodies in one loop: a planar e-bar linkage.
    angles = np.arange(e) * 2 * np.pi / e
    return kinestat.Network(["revolute"] * e, np.c_[np.arange(e), (np.arange(e) + 1) % e],
                            points=np.c_[np.cos(angles), np.sin(angles), np.zeros(e)],
                            axes=np.tile([0.0, 0.0, 1.0], (e, 1)), ground=0, name=f"ring of {e}")


def test_a_ring_above_the_dense_limit_takes_the_sparse_path(tmp_path):
    # By hand: F = e (one freedom per revolute), C = 5e, l = 1, so FN - CN = F - 6l = e - 6. A
    # planar loop of e bars moves with e - 3 freedoms: FN = e - 3, CN = 3 (the three constraints
    # out of the plane are redundant).
    e = 400
    result = kinestat.analyze(ring(e))
    assert result.method == "sparse"
    assert (result.F, result.C, result.l) == (e, 5 * e, 1)
    assert (result.FN, result.CN) == (e - 3, 3)
    assert (result.m, result.a) == (3, 5 * e - 3)  # Davies' ranks: F - FN, C - CN
    assert result.rank_evidence()["motion"]["rank"] == 6 * (e - 1) - (e - 3)  # rank K = d(n - 1) - FN
    path = tmp_path / "ring.json"
    path.write_text(ring(e).to_json())
    assert kinestat.analyze(path).to_json() == cli_json("analyze", path)
    with pytest.raises(ValueError, match="method='dense'"):
        result.inf_flexes()
    svg = result.svg()  # the coupling graph, as `kinestat draw` draws a sparse network
    assert "<svg" in svg[:500] and svg.rstrip().endswith("</svg>")


def test_method_chooses_the_path(examples):
    path = examples / "davies-2-circuit.yaml"
    sparse = kinestat.analyze(path, method="sparse")
    assert sparse.method == "sparse" and (sparse.FN, sparse.CN) == (3, 2)  # seed 000
    assert sparse.to_json() == cli_json("analyze", "--sparse", path)
    dense = kinestat.analyze(path, method="dense")
    assert dense.method == "dense" and dense.to_json() == kinestat.analyze(path).to_json()
    with pytest.raises(ValueError, match="method='dense'"):
        kinestat.analyze(path, method="sparse", arithmetic="exact")
    with pytest.raises(ValueError):
        kinestat.analyze(path, method="fast")
