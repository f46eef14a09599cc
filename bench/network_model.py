#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes a generated coupling network (kind: network) of about N couplings to stdout.

  rss N      R-S-S chain (as BM_SparseRssChain in bench/network_bench.cpp): unit i is the closed
             loop base(i-1) -R- a_i -S- b_i -S- base(i-1), and b_i is the base of unit i + 1;
             3 couplings, 2 bodies, 1 circuit per unit. Each unit has one motion (b_i spins
             about the line through its two spherical joints): FN = N/3 units, CN = 0.
  lattice N  planar lattice (as BM_SparsePlanarLattice): a side x side grid of bodies, each joined
             to its right and upper neighbour by a revolute at a slightly perturbed midpoint.
             Overconstrained: FN - CN = 3(n - 1) - 2e < 0.
  random N   random graph (as BM_SparseRandomGraph): a random spanning tree on 0.6 N bodies, then
             random pairs of distinct bodies until N couplings; each a revolute, cylindrical or
             spherical joint at a random integer point. An expander: no ordering splits it by small
             separators, so a direct factorisation fills in (bench/README.md).
Joints at random integer (rss) or tenth (lattice) points, Python's fixed-seed random (not the
same networks as the C++ benchmarks, the same shapes). The ladder: bench/ladder_network.py.
Usage: bench/network_model.py rss 3000 > rss.yaml
"""
import math
import random
import sys

from ladder_network import random_joint  # the ladder's joints, in the same directory


def rss(couplings):
    units = max(1, couplings // 3)
    rng = random.Random(99)
    out = ["kinestat: 1", "kind: network", f"name: R-S-S chain of {units} units", "dimension: spatial",
           "ground: ground", "couplings:"]
    count = 0

    def point():
        return [rng.randint(-20, 20) for _ in range(3)]

    base = "ground"
    for i in range(units):
        a, b = f"a{i}", f"b{i}"
        axis = [0, 0, 0]
        while axis == [0, 0, 0]:
            axis = [rng.randint(-4, 4) for _ in range(3)]
        out.append(f"  - {{name: J{count}, type: revolute, between: [{base}, {a}], point: {point()}, axis: {axis}}}")
        p, q = point(), point()
        while q == p:
            q = point()
        out.append(f"  - {{name: J{count + 1}, type: spherical, between: [{a}, {b}], point: {p}}}")
        out.append(f"  - {{name: J{count + 2}, type: spherical, between: [{b}, {base}], point: {q}}}")
        count += 3
        base = b
    return out


def lattice(couplings):
    side = max(2, round(math.sqrt(couplings / 2.0)) + 1)
    rng = random.Random(31)
    out = ["kinestat: 1", "kind: network", f"name: planar lattice {side} x {side}", "dimension: planar",
           "ground: b0", "couplings:"]
    count = 0

    def add(a, b, x, y):
        nonlocal count
        px = x + rng.randint(-3, 3) / 10
        py = y + rng.randint(-3, 3) / 10
        out.append(f"  - {{name: R{count}, type: revolute, between: [b{a}, b{b}], point: [{px:g}, {py:g}]}}")
        count += 1

    for j in range(side):
        for i in range(side):
            b = j * side + i
            if i + 1 < side:
                add(b, b + 1, i + 0.5, j)
            if j + 1 < side:
                add(b, b + side, i, j + 0.5)
    return out


def random_graph(couplings):
    bodies = max(2, couplings * 3 // 5)
    rng = random.Random(777)
    out = ["kinestat: 1", "kind: network", f"name: random graph of {couplings} couplings", "dimension: spatial",
           "ground: b0", "couplings:"]
    header = len(out)

    def add(a, b):
        out.append(random_joint(rng, f"J{len(out) - header}", f"b{a}", f"b{b}"))

    for i in range(1, bodies):
        add(rng.randrange(i), i)
    while len(out) - header < couplings:
        a, b = rng.randrange(bodies), rng.randrange(bodies)
        if a != b:
            add(a, b)
    return out


def main():
    kind, couplings = sys.argv[1], int(sys.argv[2])
    print("\n".join({"rss": rss, "lattice": lattice, "random": random_graph}[kind](couplings)))


if __name__ == "__main__":
    main()
