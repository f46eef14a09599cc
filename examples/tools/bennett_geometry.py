#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Exact geometry of the Bennett linkage in examples/bennett.yaml (and its perturbed twin).

Bennett (1903): a 4R loop with link lengths a, b, a, b and twists alpha, beta, alpha, beta
is mobile when a / sin(alpha) = b / sin(beta); its joint angles satisfy
tan(theta1/2) tan(theta2/2) = sin((beta+alpha)/2) / sin((beta-alpha)/2)
                            = (tan(beta/2) + tan(alpha/2)) / (tan(beta/2) - tan(alpha/2)),
theta3 = -theta1, theta4 = -theta2 (Denavit-Hartenberg, d_i = 0).

With tan(alpha/2) = 1/3 (sin 3/5, cos 4/5), tan(beta/2) = 1/2 (sin 4/5, cos 3/5), a = 3,
b = 4 (a/sin alpha = b/sin beta = 5) the right-hand side is 5, and every angle has a rational
half-angle tangent, so all axes and points are exact rationals. This script checks the
closure T1 T2 T3 T4 = I exactly (fractions), checks that the loop closes for other theta1
too (a one-parameter family: it moves), prints the joint axes, and computes the rank of the
four joint twists (w; p x w) exactly: 3 for Bennett (FN = 4 - 3 = 1, CN = 6 - 3 = 3),
4 for the perturbed loop (FN = 0, CN = 2). Run: python3 examples/tools/bennett_geometry.py
"""
import math
from fractions import Fraction as Fr


def sin_cos(t):  # from the tangent of the half angle
    return 2 * t / (1 + t * t), (1 - t * t) / (1 + t * t)


def dh(theta, a, alpha):
    st, ct = theta
    sa, ca = alpha
    return [[ct, -st * ca, st * sa, a * ct], [st, ct * ca, -ct * sa, a * st], [0, sa, ca, 0], [0, 0, 0, 1]]


def mul(A, B):
    return [[sum(A[i][k] * B[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


IDENTITY = [[Fr(int(i == j)) for j in range(4)] for i in range(4)]
TA, TB, A, B = Fr(1, 3), Fr(1, 2), Fr(3), Fr(4)
RATIO = (TB + TA) / (TB - TA)  # = 5


def frames(t1):
    t2 = RATIO / t1
    out, T = [IDENTITY], IDENTITY
    for t, length, twist in [(t1, A, TA), (t2, B, TB), (-t1, A, TA), (-t2, B, TB)]:
        T = mul(T, dh(sin_cos(t), length, sin_cos(twist)))
        out.append(T)
    return out


def cross(p, w):
    return [p[1] * w[2] - p[2] * w[1], p[2] * w[0] - p[0] * w[2], p[0] * w[1] - p[1] * w[0]]


def rank(rows):
    m = [list(r) for r in rows]
    r = 0
    for c in range(len(m[0])):
        pivot = next((i for i in range(r, len(m)) if m[i][c] != 0), None)
        if pivot is None:
            continue
        m[r], m[pivot] = m[pivot], m[r]
        for i in range(len(m)):
            if i != r and m[i][c] != 0:
                f = m[i][c] / m[r][c]
                m[i] = [x - f * y for x, y in zip(m[i], m[r])]
        r += 1
    return r


def twist_rank(joints):
    return rank([w + cross(p, w) for p, w in joints])


def main():
    for t1 in [Fr(2), Fr(3), Fr(-1, 4)]:
        assert frames(t1)[4] == IDENTITY, f"loop does not close for tan(theta1/2) = {t1}"
    f = frames(Fr(2))
    joints = [([f[i][r][3] for r in range(3)], [f[i][r][2] for r in range(3)]) for i in range(4)]
    for i, (p, w) in enumerate(joints):
        print(f"joint {i + 1}: point {[str(x) for x in p]} axis {[str(x) for x in w]}")
    # The model file takes decimals: lengths times 145 (= 5 * 29) are integers, and axes
    # need only their direction, so each is scaled to integers too.
    for i, (p, w) in enumerate(joints):
        axis_scale = 1
        for x in w:
            axis_scale = axis_scale * x.denominator // math.gcd(axis_scale, x.denominator)
        print(f"  file, joint {i + 1}: point {[str(145 * x) for x in p]} axis {[str(axis_scale * x) for x in w]}")
    assert twist_rank([([145 * x for x in p], w) for p, w in joints]) == 3
    print("rank of the joint twists (Bennett):", twist_rank(joints))
    p3, w3 = joints[2]
    tilted = joints[:2] + [(p3, [w3[0], w3[1] + Fr(1, 100), w3[2]])] + joints[3:]
    print("perturbed joint 3 axis:", [str(x) for x in tilted[2][1]])
    print("rank of the joint twists (perturbed):", twist_rank(tilted))


if __name__ == "__main__":
    main()
