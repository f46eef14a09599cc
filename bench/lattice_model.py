#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes the lattices of tests/support/lattice_generator.cpp as framework model files
(same nodes, bars and supports, same order), for whole-command runs of `kinestat analyze`, and
builds their D(c) for numpy (rows: bars, columns: x, y[, z] of the free nodes, entries the
direction cosines, the same matrix as kinestat's up to the diagonal length scaling).

    lattice_model.py triangulated N FILE   # N x N planar grid, one diagonal per cell
    lattice_model.py square N FILE
    lattice_model.py spatial N FILE        # N^3 cubic lattice, diagonals in horizontal faces

A FILE ending in .bars is written as a bar table (docs/formats.md, "Bar tables"): the planar
lattices streamed line by line, so that 10^7 bars (triangulated 1826: 9,995,525 bars, about
190 MB) are written without holding the lattice in memory.
"""
import sys


def lattice(kind, n):
    nodes, bars = [], []
    if kind in ("triangulated", "square"):
        for j in range(n):
            for i in range(n):
                nodes.append(((i, j), j == 0))
        node = lambda i, j: j * n + i
        for j in range(n):
            for i in range(n):
                if i + 1 < n:
                    bars.append((node(i, j), node(i + 1, j)))
                if j + 1 < n:
                    bars.append((node(i, j), node(i, j + 1)))
                if kind == "triangulated" and i + 1 < n and j + 1 < n:
                    bars.append((node(i, j), node(i + 1, j + 1)))
        return 2, nodes, bars
    node = lambda i, j, k: (k * n + j) * n + i
    for k in range(n):
        for j in range(n):
            for i in range(n):
                nodes.append(((i, j, k), k == 0))
    for k in range(n):
        for j in range(n):
            for i in range(n):
                if i + 1 < n:
                    bars.append((node(i, j, k), node(i + 1, j, k)))
                if j + 1 < n:
                    bars.append((node(i, j, k), node(i, j + 1, k)))
                if k + 1 < n:
                    bars.append((node(i, j, k), node(i, j, k + 1)))
                if i + 1 < n and j + 1 < n:
                    bars.append((node(i, j, k), node(i + 1, j + 1, k)))
    return 3, nodes, bars


def write_model(kind, n, path):
    dimension, nodes, bars = lattice(kind, n)
    with open(path, "w") as out:
        out.write(f"kinestat: 1\nkind: framework\nname: {kind} lattice {n}\ndimension: {'planar' if dimension == 2 else 'spatial'}\nnodes:\n")
        for index, (position, _) in enumerate(nodes):
            out.write(f"  n{index}: [{', '.join(str(c) for c in position)}]\n")
        out.write("supports:\n")
        for index, (_, pinned) in enumerate(nodes):
            if pinned:
                out.write(f"  n{index}: fixed\n")
        out.write("elements:\n")
        for p, q in bars:
            out.write(f"  - {{type: truss, nodes: [n{p}, n{q}]}}\n")


def write_planar_bar_table(kind, n, path):
    """The planar lattice as a bar table, streamed: nodes j * n + i at (i, j), row j = 0 held."""
    count = 2 * n * (n - 1) + ((n - 1) * (n - 1) if kind == "triangulated" else 0)
    with open(path, "w", buffering=1 << 20) as out:
        out.write(f"kinestat bars 1\n# {kind} lattice {n}\ndimension 2\nnodes {n * n}\n")
        for j in range(n):
            out.write("".join(f"{i} {j}\n" for i in range(n)))
        out.write(f"bars {count}\n")
        for j in range(n):
            lines = []
            for i in range(n):
                p = j * n + i
                if i + 1 < n:
                    lines.append(f"{p} {p + 1}\n")
                if j + 1 < n:
                    lines.append(f"{p} {p + n}\n")
                if kind == "triangulated" and i + 1 < n and j + 1 < n:
                    lines.append(f"{p} {p + n + 1}\n")
            out.write("".join(lines))
        out.write(f"supports {n}\n")
        out.write("".join(f"{i} xy\n" for i in range(n)))


def jacobian(kind, n):
    import numpy
    dimension, nodes, bars = lattice(kind, n)
    column = {}
    for index, (_, pinned) in enumerate(nodes):
        if not pinned:
            column[index] = len(column) * dimension
    d = numpy.zeros((len(bars), len(column) * dimension))
    for row, (p, q) in enumerate(bars):
        u = numpy.subtract(nodes[q][0], nodes[p][0]).astype(float)
        u /= numpy.linalg.norm(u)
        if q in column:
            d[row, column[q]:column[q] + dimension] = u
        if p in column:
            d[row, column[p]:column[p] + dimension] = -u
    return d


if __name__ == "__main__":
    if sys.argv[3].endswith(".bars") and sys.argv[1] in ("triangulated", "square"):
        write_planar_bar_table(sys.argv[1], int(sys.argv[2]), sys.argv[3])
    else:
        write_model(sys.argv[1], int(sys.argv[2]), sys.argv[3])
