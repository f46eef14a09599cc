#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes the four-bar, Stewart-Gough and Delta mechanisms of examples/ as URDF, SDFormat and
MJCF files (examples/robots/), from one description per mechanism in world coordinates, so
that every format states the same joints at the same places. kinestat must give the same FN,
CN, modes and self-stresses for each as for the YAML examples (tests/importers).

Conventions: every link frame is parallel to the world frame and placed at the link's tree
joint, so joint positions are plain differences and axes are world axes.
  URDF: loop closures as a joint whose child already has a parent (file order), or Drake's
        <loop_joint> (the four-bar's last joint); universal joints as two revolutes through a
        cross link; spherical joints as type="ball".
  SDFormat: joints in any order (loops allowed), universal and ball joints as such.
  MJCF: the body tree; a revolute closing a loop is a hinge in a dummy child body welded to
        the other side (<weld>), a spherical closure is a <connect> at the joint centre.
Run from the repository root: /usr/bin/python3 scripts/generate-robot-examples.py
"""
import os

OUT = "examples/robots"


def fmt(v):
    out = []
    for c in v:
        c = 0.0 if abs(c) < 1e-12 else c
        s = repr(round(c, 12))
        out.append(s[:-2] if s.endswith(".0") else s)
    return " ".join(out)


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def add(a, b):
    return [a[i] + b[i] for i in range(3)]


def scale(a, s):
    return [x * s for x in a]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


class Mechanism:
    """Joints (name, type, parent, child, point, axis, axis2) in world coordinates. The first
    joint that names a link as child is its tree joint; later ones close loops."""

    def __init__(self, name, ground):
        self.name, self.ground, self.joints = name, ground, []

    def joint(self, name, kind, parent, child, point, axis=None, axis2=None):
        self.joints.append(dict(name=name, kind=kind, parent=parent, child=child, point=point, axis=axis, axis2=axis2))

    def tree(self):
        origin, tree, loops = {self.ground: [0, 0, 0]}, [], []
        for j in self.joints:
            if j["child"] in origin or j["child"] == self.ground:
                loops.append(j)
            else:
                origin[j["child"]] = j["point"]
                tree.append(j)
        return origin, tree, loops


def urdf(m, loop_joint_for=()):
    origin, tree, loops = m.tree()
    links = [m.ground] + [j["child"] for j in tree]
    lines = [f'<?xml version="1.0"?>', f'<!-- {m.name}: written by scripts/generate-robot-examples.py -->',
             f'<robot name="{m.name}">']
    for link in links:
        lines.append(f'  <link name="{link}"/>')
    # Universal joints become two revolutes through a cross link.
    for j in m.joints:
        if j["kind"] == "universal":
            lines.append(f'  <link name="{j["name"]}_cross"/>')
    for j in tree + loops:
        parent, child = j["parent"], j["child"]
        rel = sub(j["point"], origin[parent])
        if j["name"] in loop_joint_for:
            lines.append(f'  <loop_joint name="{j["name"]}" type="continuous">')
            lines.append(f'    <link1 link="{parent}" xyz="{fmt(rel)}" rpy="0 0 0"/>')
            lines.append(f'    <link2 link="{child}" xyz="{fmt(sub(j["point"], origin[child]))}" rpy="0 0 0"/>')
            lines.append(f'    <axis xyz="{fmt(j["axis"])}"/>')
            lines.append('  </loop_joint>')
            continue
        if j["kind"] == "universal":
            cross_link = j["name"] + "_cross"
            lines.append(f'  <joint name="{j["name"]}a" type="continuous">')
            lines.append(f'    <parent link="{parent}"/><child link="{cross_link}"/>')
            lines.append(f'    <origin xyz="{fmt(rel)}" rpy="0 0 0"/><axis xyz="{fmt(j["axis"])}"/>')
            lines.append('  </joint>')
            lines.append(f'  <joint name="{j["name"]}b" type="continuous">')
            lines.append(f'    <parent link="{cross_link}"/><child link="{child}"/>')
            lines.append(f'    <origin xyz="{fmt(sub(origin[child], j["point"]))}" rpy="0 0 0"/><axis xyz="{fmt(j["axis2"])}"/>')
            lines.append('  </joint>')
            continue
        kind = {"revolute": "continuous", "prismatic": "prismatic", "spherical": "ball", "rigid": "fixed"}[j["kind"]]
        lines.append(f'  <joint name="{j["name"]}" type="{kind}">')
        lines.append(f'    <parent link="{parent}"/><child link="{child}"/>')
        extra = f'<axis xyz="{fmt(j["axis"])}"/>' if j["axis"] else ""
        if kind == "prismatic":
            extra += '<limit lower="-1" upper="1" effort="1" velocity="1"/>'
        lines.append(f'    <origin xyz="{fmt(rel)}" rpy="0 0 0"/>{extra}')
        lines.append('  </joint>')
    lines.append('</robot>')
    return "\n".join(lines) + "\n"


def sdf(m):
    origin, tree, loops = m.tree()
    links = [j["child"] for j in tree]
    lines = ['<?xml version="1.0"?>', f'<!-- {m.name}: written by scripts/generate-robot-examples.py -->',
             '<sdf version="1.8">', f'  <model name="{m.name.replace(" ", "_")}">']
    for link in links:
        lines.append(f'    <link name="{link}"><pose>{fmt(origin[link])} 0 0 0</pose></link>')
    for j in m.joints:
        kind = {"revolute": "revolute", "prismatic": "prismatic", "spherical": "ball", "rigid": "fixed",
                "universal": "universal"}[j["kind"]]
        parent, child = j["parent"], j["child"]
        if child == m.ground:  # SDFormat's world can only be a parent: the joint is turned round
            parent, child = child, parent
        parent = "world" if parent == m.ground else parent
        lines.append(f'    <joint name="{j["name"]}" type="{kind}">')
        lines.append(f'      <parent>{parent}</parent><child>{child}</child>')
        lines.append(f'      <pose relative_to="__model__">{fmt(j["point"])} 0 0 0</pose>')
        limit = '<limit><lower>-1e16</lower><upper>1e16</upper></limit>'
        if j["axis"]:
            lines.append(f'      <axis><xyz>{fmt(j["axis"])}</xyz>{limit}</axis>')
        if j["axis2"]:
            lines.append(f'      <axis2><xyz>{fmt(j["axis2"])}</xyz>{limit}</axis2>')
        lines.append('    </joint>')
    lines.append('  </model>')
    lines.append('</sdf>')
    return "\n".join(lines) + "\n"


def mjcf(m):
    origin, tree, loops = m.tree()
    children = {}
    for j in tree:
        children.setdefault(j["parent"], []).append(j)
    inertial = '<inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>'
    dummies = {}  # loop revolute closures: a dummy body with the hinge, welded to the other side
    equality = []
    for j in loops:
        if j["kind"] == "spherical":
            equality.append(f'    <connect name="{j["name"]}" body1="{j["parent"]}" body2="{j["child"]}" '
                            f'anchor="{fmt(sub(j["point"], origin[j["parent"]]))}"/>')
        elif j["kind"] == "revolute":
            dummy = j["name"] + "_end"
            dummies.setdefault(j["parent"], []).append((dummy, j))
            other = "world" if j["child"] == m.ground else j["child"]
            equality.append(f'    <weld name="{j["name"]}_weld" body1="{dummy}" body2="{other}"/>')
        else:
            raise ValueError(j)

    def joint_xml(j, indent):
        pos = "0 0 0"
        if j["kind"] == "revolute":
            return [f'{indent}<joint name="{j["name"]}" type="hinge" pos="{pos}" axis="{fmt(j["axis"])}"/>']
        if j["kind"] == "prismatic":
            return [f'{indent}<joint name="{j["name"]}" type="slide" pos="{pos}" axis="{fmt(j["axis"])}"/>']
        if j["kind"] == "spherical":
            return [f'{indent}<joint name="{j["name"]}" type="ball" pos="{pos}"/>']
        if j["kind"] == "universal":
            return [f'{indent}<joint name="{j["name"]}a" type="hinge" pos="{pos}" axis="{fmt(j["axis"])}"/>',
                    f'{indent}<joint name="{j["name"]}b" type="hinge" pos="{pos}" axis="{fmt(j["axis2"])}"/>']
        raise ValueError(j)

    def body(link, indent):
        out = []
        for j in children.get(link, []):
            child = j["child"]
            out.append(f'{indent}<body name="{child}" pos="{fmt(sub(origin[child], origin[link]))}">')
            out.append(f'{indent}  {inertial}')
            out += joint_xml(j, indent + "  ")
            out += body(child, indent + "  ")
            out.append(f'{indent}</body>')
        for dummy, j in dummies.get(link, []):
            out.append(f'{indent}<body name="{dummy}" pos="{fmt(sub(j["point"], origin[link]))}">')
            out.append(f'{indent}  {inertial}')
            out += joint_xml(j, indent + "  ")
            out.append(f'{indent}</body>')
        return out

    lines = [f'<!-- {m.name}: written by scripts/generate-robot-examples.py -->', f'<mujoco model="{m.name}">',
             '  <worldbody>']
    lines += body(m.ground, "    ")
    lines += ['  </worldbody>', '  <equality>'] + equality + ['  </equality>', '</mujoco>']
    return "\n".join(lines) + "\n"


def four_bar():
    # examples/four-bar-spatial.yaml: four revolutes with axes along z.
    m = Mechanism("four_bar", "ground")
    z = [0, 0, 1]
    m.joint("A", "revolute", "ground", "crank", [0, 0, 0], z)
    m.joint("B", "revolute", "crank", "coupler", [1, 2, 0], z)
    m.joint("C", "revolute", "coupler", "rocker", [4, 3, 0], z)
    m.joint("D", "revolute", "rocker", "ground", [5, 0, 0], z)
    return m


def stewart():
    # examples/stewart-6ups.yaml: base anchors a, platform anchors b; U first axis z, second
    # axis z x (b - a); P along b - a.
    a = [[10, 0, 0], [6, 8, 0], [-5, 9, 0], [-9, -3, 0], [-2, -10, 0], [7, -6, 0]]
    b = [[4, 1, 5], [1, 5, 6], [-3, 3, 5], [-4, -1, 6], [0, -4, 5], [3, -3, 6]]
    m = Mechanism("stewart_6ups", "base")
    for i in range(6):
        leg = sub(b[i], a[i])
        n = i + 1
        m.joint(f"U{n}", "universal", "base", f"leg{n}_lower", a[i], [0, 0, 1], cross([0, 0, 1], leg))
        # The upper leg's frame sits at the platform anchor (where its spherical joint is).
        m.joint(f"P{n}", "prismatic", f"leg{n}_lower", f"leg{n}_upper", b[i], leg)
        m.joint(f"S{n}", "spherical", f"leg{n}_upper", "platform", b[i])
    return m


def delta():
    # examples/delta-robot.yaml: legs R(u) - R(u) - parallelogram(w) - R(u).
    m = Mechanism("delta", "base")
    # Leg directions with rational cosines (3-4-5 triangles), so every number is a short decimal.
    for i, (c, s) in enumerate([(1, 0), (-0.6, 0.8), (-0.6, -0.8)]):
        n = i + 1
        radial, u = [c, s, 0], [-s, c, 0]
        A, B, C = scale(radial, 2), scale(radial, 3), add(scale(radial, 1), [0, 0, -2])
        w = cross(u, sub(C, B))
        h = scale(u, 0.25)
        m.joint(f"R{n}", "revolute", "base", f"arm{n}", A, u)
        m.joint(f"E{n}", "revolute", f"arm{n}", f"top{n}", B, u)
        m.joint(f"T{n}a", "revolute", f"top{n}", f"rod{n}a", add(B, h), w)
        m.joint(f"T{n}b", "revolute", f"top{n}", f"rod{n}b", sub(B, h), w)
        m.joint(f"L{n}a", "revolute", f"rod{n}a", f"bottom{n}", add(C, h), w)
        m.joint(f"L{n}b", "revolute", f"rod{n}b", f"bottom{n}", sub(C, h), w)
        m.joint(f"W{n}", "revolute", f"bottom{n}", "platform", C, u)
    return m


def yaml(m):
    def v(x):
        return "[" + ", ".join(fmt([c]) for c in x) + "]"
    lines = []
    for j in m.joints:
        geometry = f"point: {v(j['point'])}"
        if j["axis"]:
            geometry += f", axis: {v(j['axis'])}"
        if j["axis2"]:
            geometry += f", axis2: {v(j['axis2'])}"
        lines.append(f"  - {{name: {j['name']}, type: {j['kind']}, between: [{j['parent']}, {j['child']}], {geometry}}}")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    os.makedirs(OUT, exist_ok=True)
    for m, loop_joints in [(four_bar(), ("D",)), (stewart(), ()), (delta(), ())]:
        base = os.path.join(OUT, m.name.replace("_", "-"))
        open(base + ".urdf", "w").write(urdf(m, loop_joints))
        open(base + ".sdf", "w").write(sdf(m))
        open(base + ".xml", "w").write(mjcf(m))
    print(yaml(delta()))
