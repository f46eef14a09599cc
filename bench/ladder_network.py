#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes a spatial ladder network (kind: network) of about N couplings to stdout.

Rails u0..uL and v0..vL, rungs ui-vi; loop i is u(i-1) ui vi v(i-1): 3L + 1 couplings,
2L + 2 bodies, L circuits. Random revolute, cylindrical and spherical joints at random integer
points with random integer axes (fixed seed), like BM_Ladder in bench/network_bench.cpp.
Usage: bench/ladder_network.py 10000 > ladder.yaml
"""
import random
import sys


def random_joint(rng, name, a, b):
    """The line of a random revolute, cylindrical or spherical joint named `name` between bodies
    a and b, at a random integer point (with a random non-zero integer axis)."""
    kind = rng.choice(["revolute", "cylindrical", "spherical"])
    point = [rng.randint(-20, 20) for _ in range(3)]
    text = f"  - {{name: {name}, type: {kind}, between: [{a}, {b}], point: {point}"
    if kind != "spherical":
        axis = [0, 0, 0]
        while axis == [0, 0, 0]:
            axis = [rng.randint(-5, 5) for _ in range(3)]
        text += f", axis: {axis}"
    return text + "}"


def main():
    couplings = int(sys.argv[1])
    loops = max(1, (couplings - 1) // 3)
    rng = random.Random(12345)
    out = ["kinestat: 1", "kind: network", f"name: spatial ladder of {loops} loops", "dimension: spatial",
           "ground: u0", "couplings:"]
    count = 0

    def joint(a, b):
        nonlocal count
        out.append(random_joint(rng, f"J{count}", a, b))
        count += 1

    joint("u0", "v0")
    for i in range(1, loops + 1):
        joint(f"u{i-1}", f"u{i}")
        joint(f"v{i-1}", f"v{i}")
        joint(f"u{i}", f"v{i}")
    print("\n".join(out))


if __name__ == "__main__":
    main()
