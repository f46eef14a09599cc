#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Independent positions of the six-bar test mechanisms (tests/kinematics/position_solver_test.cpp).

Not kinestat's method: every moving joint position is an unknown at once, every link keeps
the pairwise distances of its joints (a ternary link: its three sides), and the whole
mechanism is solved by one Newton iteration on all distance equations, continued from the
file's configuration in steps of 1 degree of the crank. kinestat instead solves group by
group (closed-form dyads, Newton on the triad alone). Prints, for each mechanism, the joint
positions at the crank inputs the test checks (rad, relative to the file).

Run: /usr/bin/python3 tests/kinematics/data/independent_positions.py
"""
import math
import numpy as np

# Each mechanism: joint coordinates in the file, joints on the frame, the crank (pivot, pin),
# and the moving links as lists of joints. Mirrors the YAML files next to this script.
MECHANISMS = {
    "watt-six-bar-planar": dict(
        joints={"A": (0, 0), "B": (0, 1), "C": (4, 3), "D": (4, 0), "E": (6, 2), "F": (8, 4), "G": (9, 0)},
        frame=["A", "D", "G"], crank=("A", "B"),
        links=[["B", "C"], ["C", "D", "E"], ["E", "F"], ["F", "G"]]),
    "stephenson-six-bar-planar": dict(
        joints={"A": (0, 0), "B": (0, 1), "C": (4, 3), "D": (4, 0), "E": (2, 4), "F": (-1, 5), "G": (-2, 2)},
        frame=["A", "D", "G"], crank=("A", "B"),
        links=[["B", "C", "E"], ["C", "D"], ["E", "F"], ["F", "G"]]),
    "class-iii-triad-planar": dict(
        joints={"A": (0, 0), "B": (0, 1), "C": (3, 2), "D": (4, 4), "E": (2, 9), "F": (6, -1), "G": (3, -4)},
        frame=["A", "E", "G"], crank=("A", "B"),
        links=[["B", "C"], ["C", "D", "F"], ["D", "E"], ["F", "G"]]),
}

INPUTS = [0.0, 0.5, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0]


def solve(mech, inputs):
    joints = {k: np.array(v, float) for k, v in mech["joints"].items()}
    pivot, pin = mech["crank"]
    fixed = set(mech["frame"]) | {pin}
    free = [k for k in joints if k not in fixed]
    pairs = []
    for link in mech["links"]:
        for i in range(len(link)):
            for j in range(i + 1, len(link)):
                a, b = link[i], link[j]
                pairs.append((a, b, np.linalg.norm(joints[a] - joints[b])))
    x = np.concatenate([joints[k] for k in free])
    theta0 = math.atan2(*(joints[pin] - joints[pivot])[::-1])
    radius = np.linalg.norm(joints[pin] - joints[pivot])
    results = {}
    targets = sorted(inputs)
    value = 0.0
    step = math.radians(1.0)
    for target in targets:
        while True:
            value = min(value + step, target) if value < target else target
            pos = dict(joints)
            pos[pin] = joints[pivot] + radius * np.array([math.cos(theta0 + value), math.sin(theta0 + value)])
            for _ in range(50):
                for n, k in enumerate(free):
                    pos[k] = x[2 * n:2 * n + 2]
                r = np.array([np.dot(pos[a] - pos[b], pos[a] - pos[b]) - l * l for a, b, l in pairs])
                J = np.zeros((len(pairs), len(x)))
                for row, (a, b, l) in enumerate(pairs):
                    g = 2 * (pos[a] - pos[b])
                    if a in free:
                        J[row, 2 * free.index(a):2 * free.index(a) + 2] += g
                    if b in free:
                        J[row, 2 * free.index(b):2 * free.index(b) + 2] -= g
                dx = np.linalg.lstsq(J, -r, rcond=None)[0]
                x = x + dx
                if np.max(np.abs(dx)) < 1e-15:
                    break
            for n, k in enumerate(free):
                pos[k] = x[2 * n:2 * n + 2]
            assert max(abs(np.linalg.norm(pos[a] - pos[b]) - l) for a, b, l in pairs) < 1e-12
            if value == target:
                results[target] = {k: tuple(pos[k]) for k in sorted(joints)}
                break
    return results


if __name__ == "__main__":
    for name, mech in MECHANISMS.items():
        print(f"// {name}")
        res = solve(mech, INPUTS)
        for value in INPUTS:
            pts = ", ".join(f'{{"{k}", {{{p[0]:.15g}, {p[1]:.15g}}}}}' for k, p in res[value].items())
            print(f"{{{value!r}, {{{pts}}}}},")
