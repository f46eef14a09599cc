#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes a planar framework model: a triangular lattice of bars (for scale measurements).

usage: generate-triangular-lattice.py BARS [FILE]    (FILE defaults to standard output)

The lattice is a k x k grid of nodes sheared into equilateral triangles; each node is joined
to its right, upper and upper-right neighbour, so it has 3 (k-1)^2 + 2 (k-1) bars (k chosen so that
the count is at least BARS). Node (0, 0) is fixed and node (1, 0) held in y.
"""
import math
import sys


def main():
    bars = int(sys.argv[1])
    k = 2
    while 3 * (k - 1) ** 2 + 2 * (k - 1) < bars:
        k += 1
    out = open(sys.argv[2], "w") if len(sys.argv) > 2 else sys.stdout
    w = out.write
    w("kinestat: 1\nkind: framework\nname: triangular lattice %dx%d\ndimension: planar\nnodes:\n" % (k, k))
    for j in range(k):
        for i in range(k):
            w("  n%d: [%.6f, %.6f]\n" % (j * k + i, i + 0.5 * j, j * math.sqrt(3) / 2))
    w("supports: {n0: fixed, n1: [y]}\nelements:\n")
    for j in range(k):
        for i in range(k):
            a = j * k + i
            if i + 1 < k:
                w("  - {type: truss, nodes: [n%d, n%d]}\n" % (a, a + 1))
            if j + 1 < k:
                w("  - {type: truss, nodes: [n%d, n%d]}\n" % (a, a + k))
                if i + 1 < k:
                    w("  - {type: truss, nodes: [n%d, n%d]}\n" % (a, a + k + 1))
    out.close()


if __name__ == "__main__":
    main()
