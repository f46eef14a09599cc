#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes the straight-guidance examples of seed 002, section 4 (Figs. 3-6), to examples/.

The geometry is designed to match the text (the paper gives no coordinates): the moving part is
one node C at the origin whose intended motion is translation along z. A wire flexure
constrains translation along the wire; a folded sheet flexure (two sheets meeting at a fold
node F, the second sheet ending at C) constrains translation along its fold line, which passes
through F perpendicular to both sheets. Lengths in millimetres.
"""
import math
import pathlib

OUT = pathlib.Path(__file__).resolve().parent.parent / "examples"
H, R = 40.0, 30.0          # height of the upper/lower flexure level, radius of the fold lines
SHEET = 20.0               # length of the first sheet of a folded sheet flexure
WIRE = 25.0                # wire length


def fmt(v):
    v = 0.0 if abs(v) < 1e-13 else v
    s = "%.12g" % v
    return "0" if s == "-0" else s


def vec(v):
    return "[" + ", ".join(fmt(x) for x in v) + "]"


def sub(a, b): return [x - y for x, y in zip(a, b)]
def add(a, b): return [x + y for x, y in zip(a, b)]
def mul(s, a): return [s * x for x in a]
def norm(a): return math.sqrt(sum(x * x for x in a))
def unit(a): return mul(1.0 / norm(a), a)
def cross(a, b): return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def tangential(angle_deg, z):
    """Fold line tangent to the circle of radius R at height z: (point, direction)."""
    t = math.radians(angle_deg)
    return [R * math.cos(t), R * math.sin(t), z], [-math.sin(t), math.cos(t), 0.0]


FIG3_LINES = [  # two constraints at the top, three at the bottom (asymmetric, Fig. 3)
    ([0.0, R, H], [1.0, 0.0, 0.0]),
    ([R, 0.0, H], [0.0, 1.0, 0.0]),
    ([0.0, R, -H], [1.0, 0.0, 0.0]),
    ([R, 0.0, -H], [0.0, 1.0, 0.0]),
    ([0.0, -R, -H], [1.0, 0.0, 0.0]),
]
FIG5_LINES = [tangential(a, H) for a in (90, 210, 330)] + [([0.0, R, -H], [1.0, 0.0, 0.0]), ([0.0, -R, -H], [1.0, 0.0, 0.0])]
FIG6_LINES = [tangential(a, H) for a in (90, 210, 330)] + [tangential(a, -H) for a in (90, 210, 330)]


def header(name, comment):
    return "".join("# " + line + "\n" for line in comment.strip().splitlines()) + \
        f"kinestat: 1\nkind: framework\nname: {name}\ndimension: spatial\n"


def folded_sheet_guide(name, lines, comment):
    nodes, elements, supports = ["  C: [0, 0, 0]"], [], []
    for i, (fold, d) in enumerate(lines, start=1):
        s2 = unit(sub([0.0, 0.0, 0.0], fold))
        s1 = unit(cross(d, s2))
        anchor = sub(fold, mul(SHEET, s1))
        nodes += [f"  A{i}: {vec(anchor)}", f"  F{i}: {vec(fold)}"]
        supports.append(f"A{i}: fixed")
        elements.append(f"  - {{name: f{i}.s1, type: beam, nodes: [A{i}, F{i}], orientation: {{z: {vec(d)}}},\n"
                        f"     released: [torsion, bending_xy], independent: [bending_xy_q]}}")
        elements.append(f"  - {{name: f{i}.s2, type: beam, nodes: [F{i}, C], orientation: {{z: {vec(d)}}},\n"
                        f"     released: [torsion, bending_xy]}}")
    text = header(name, comment) + "nodes:\n" + "\n".join(nodes) + "\n"
    text += "supports: {" + ", ".join(supports) + "}\n"
    text += "independent: {C: [z]}\n"
    text += "elements:\n" + "\n".join(elements) + "\n"
    return text


def wire_guide():
    nodes, elements, supports, body = ["  C: [0, 0, 0]"], [], [], ["C"]
    for i, (point, d) in enumerate(FIG3_LINES, start=1):
        nodes += [f"  A{i}: {vec(sub(point, mul(WIRE, d)))}", f"  P{i}: {vec(point)}"]
        supports.append(f"A{i}: fixed")
        body.append(f"P{i}")
        elements.append(f"  - {{name: w{i}, type: beam, nodes: [A{i}, P{i}], released: [torsion, bending]}}")
    elements.append("  - {name: body, type: rigid_body, nodes: [" + ", ".join(body) + "]}")
    comment = """
Seed 002, Fig. 3(a): straight guidance with five wire flexures. Each wire keeps only its
elongation rigid (torsion and bending released), so it constrains translation along itself.
The moving part is a rigid body (reference node C, wires attached at P1-P5); its translation
along z is the intended motion, declared independent. Wires are horizontal (not aligned with
the motion): two at z = +40, three at z = -40. Expected: D(c) square (35 x 35) and non-singular;
with C.z dependent instead, one mechanism, the translation along z.
"""
    text = header("wire flexure guide (seed 002, Fig. 3a)", comment) + "nodes:\n" + "\n".join(nodes) + "\n"
    text += "supports: {" + ", ".join(supports) + "}\n"
    text += "independent: {C: [z]}\n"
    text += "elements:\n" + "\n".join(elements) + "\n"
    return text


def single_folded_sheet(clamped):
    name = "folded sheet flexure, double clamped (seed 002, Fig. 4b-c)" if clamped else "folded sheet flexure (seed 002, Fig. 4a)"
    comment = ("""
Seed 002, Fig. 4(b-c): a folded sheet flexure clamped at both ends. Expected: D(c) 6 x 6 of rank
5: one internal mode (rotation of the fold node F about the fold line, z) and one self-stress
(in-plane bending, opposite signs at the two clamped ends).
""" if clamped else """
Seed 002, Fig. 4(a): one folded sheet flexure, clamped at A, free at B. Sheet s1 lies in the
xz-plane, sheet s2 in the yz-plane; the fold line through F is parallel to z. Each sheet keeps
elongation and in-plane bending (bending_xz) rigid and releases torsion and out-of-plane
bending (bending_xy). Expected: D(c) 6 x 12 of rank 6; the flexure constrains one motion of B
(translation along the fold line) and has one internal mode (F rotates about the fold line).
""")
    text = header(name, comment)
    text += "nodes:\n  A: [0, 0, 0]\n  F: [20, 0, 0]\n  B: [20, 20, 0]\n"
    text += "supports: {A: fixed, B: fixed}\n" if clamped else "supports: {A: fixed}\n"
    text += "elements:\n"
    text += "  - {name: s1, type: beam, nodes: [A, F], orientation: {z: [0, 0, 1]}, released: [torsion, bending_xy]}\n"
    text += "  - {name: s2, type: beam, nodes: [F, B], orientation: {z: [0, 0, 1]}, released: [torsion, bending_xy]}\n"
    return text


def main():
    files = {
        "wire-flexure-guide.yaml": wire_guide(),
        "folded-sheet-flexure.yaml": single_folded_sheet(False),
        "folded-sheet-double-clamped.yaml": single_folded_sheet(True),
        "folded-sheet-guide-5.yaml": folded_sheet_guide("five folded sheet flexures (seed 002, Fig. 3b)", FIG3_LINES, """
Seed 002, Fig. 3(b): straight guidance with five folded sheet flexures (two at z = +40, three at
z = -40). Each flexure i: sheet f<i>.s1 from the clamp A<i> to the fold node F<i>, sheet f<i>.s2 from
F<i> to the moving node C; the fold line (local z of both sheets) is horizontal. One out-of-plane
bending per flexure is independent (its internal mode), C.z is the intended motion.
Expected: D(c) 35 x 35, non-singular: exactly constrained.
"""),
        "folded-sheet-guide-5-symmetric.yaml": folded_sheet_guide("five folded sheet flexures, symmetric (seed 002, Fig. 5)", FIG5_LINES, """
Seed 002, Fig. 5: a more symmetric variant with five folded sheet flexures: three fold lines
tangent to a circle at the top, the two lower fold lines parallel (both along x).
Expected: D(c) 35 x 35 of rank 34: one mechanism and one self-stress (in-plane bending).
"""),
        "folded-sheet-guide-6.yaml": folded_sheet_guide("six folded sheet flexures (seed 002, Fig. 6)", FIG6_LINES, """
Seed 002, Fig. 6: symmetric design with six folded sheet flexures, three fold lines tangent to a
circle at the top and three at the bottom. Expected: D(c) 42 x 41 of rank 41: no mechanism and
one self-stress with in-plane bending in all sheets.
"""),
    }
    for name, text in files.items():
        (OUT / name).write_text(text)


if __name__ == "__main__":
    main()
