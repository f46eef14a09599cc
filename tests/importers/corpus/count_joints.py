#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""An independent count for the corpus (no kinestat code): for each model file, the bodies,
the freedoms of its joints, its closed loops and Gruebler's sum FN - CN = sum(f) - 6 * loops,
read with Python's own XML parser (and a few lines for SPACAR). For a tree (no loop) FN is the
sum of the freedoms and CN is 0; README.md derives the models with loops by hand from these
numbers. With --check, compares every row of expected.tsv whose model is a tree (loops 0) with
this count and exits 1 on a difference.

Usage: count_joints.py FILE...   |   count_joints.py --check
"""
import os
import sys
import xml.etree.ElementTree as ET

URDF_FREEDOMS = {"revolute": 1, "continuous": 1, "prismatic": 1, "fixed": 0, "floating": 6, "planar": 3,
                 "ball": 3, "spherical": 3, "universal": 2, "screw": 1}
SDF_FREEDOMS = {"revolute": 1, "continuous": 1, "prismatic": 1, "fixed": 0, "universal": 2, "revolute2": 2,
                "ball": 3, "screw": 1}
MJCF_FREEDOMS = {"hinge": 1, "slide": 1, "ball": 3, "free": 6}


def urdf(path):
    robot = ET.parse(path).getroot()
    links = {l.get("name") for l in robot.findall("link")}
    joints = [(j.get("type"), j.find("parent").get("link"), j.find("child").get("link"))
              for j in list(robot.findall("joint")) + list(robot.findall("{http://drake.mit.edu}joint"))]
    if any(p == "world" for _, p, _ in joints):
        links.add("world")
    freedoms = sum(URDF_FREEDOMS[t] for t, _, _ in joints)
    return len(links), len(joints), freedoms


def sdf(path):
    root = ET.parse(path).getroot()
    links, joints, freedoms = 0, 0, 0
    ground = False
    for model in root.iter("model"):
        links += len(model.findall("link"))
        for j in model.findall("joint"):
            joints += 1
            freedoms += SDF_FREEDOMS[j.get("type")]
            ground = ground or j.findtext("parent", "").strip() == "world"
    return links + (1 if ground else 0), joints, freedoms


def mjcf(path):
    root = ET.parse(path).getroot()
    classes = {}  # class -> (parent class, joint type)

    def defaults(element, parent):
        name = element.get("class", "main")
        joint = element.find("joint")
        classes[name] = (parent, joint.get("type") if joint is not None else None)
        for child in element.findall("default"):
            defaults(child, name)

    for d in root.findall("default"):
        defaults(d, None)

    def joint_type(joint, childclass):
        if joint.get("type"):
            return joint.get("type")
        c = joint.get("class", childclass or "main")
        while c is not None and c in classes:
            if classes[c][1]:
                return classes[c][1]
            c = classes[c][0]
        return "hinge"

    bodies, couplings, freedoms = 1, 0, 0  # the world

    def walk(element, childclass):
        nonlocal bodies, couplings, freedoms
        for child in element:
            cc = child.get("childclass", childclass)
            if child.tag == "body":
                bodies += 1
                joints = [j for j in child if j.tag in ("joint", "freejoint")]
                for f in child.iter("frame"):  # MuJoCo 3 frames hold joints of their body
                    joints += [j for j in f if j.tag == "joint"]
                couplings += max(1, len(joints))  # a body without joints is welded (one coupling)
                bodies += max(0, len(joints) - 1)  # joints in series: intermediate bodies
                for j in joints:
                    freedoms += 6 if j.tag == "freejoint" else MJCF_FREEDOMS[joint_type(j, cc)]
                walk(child, cc)
            elif child.tag == "frame":
                walk(child, cc)

    for w in root.findall("worldbody"):
        walk(w, None)
    # An equality is a coupling of 6 - c freedoms: a connect (or a weld with torquescale 0)
    # constrains c = 3, a weld c = 6.
    for eq in root.findall("equality"):
        for e in eq:
            if e.tag == "connect" or (e.tag == "weld" and float(e.get("torquescale", "1")) == 0.0):
                couplings += 1
                freedoms += 3
            elif e.tag == "weld":
                couplings += 1
    return bodies, couplings, freedoms


def count(path):
    if path.endswith(".urdf"):
        return urdf(path)
    if path.endswith(".sdf"):
        return sdf(path)
    return mjcf(path)


def gruebler(path):
    bodies, couplings, total = count(path)
    loops = couplings - (bodies - 1)
    if loops < 0:  # groups joined to nothing (these files have no loop): each floats, 6 freedoms
        total += 6 * -loops
        couplings -= loops
        loops = 0
    return bodies, couplings, loops, total, total - 6 * loops


def main(argv):
    if argv[1:] == ["--check"]:
        here = os.path.dirname(os.path.abspath(__file__))
        bad = 0
        for line in open(os.path.join(here, "expected.tsv"), encoding="utf-8"):
            if line.startswith("#") or not line.strip():
                continue
            path, fn, cn, base = line.rstrip("\n").split("\t")[:4]
            if path.endswith(".dat") or base != "-":
                continue
            _, _, loops, total, difference = gruebler(os.path.join(here, path))
            if loops == 0 and (int(fn), int(cn)) != (total, 0):
                print(f"{path}: tree with {total} freedoms, expected.tsv says {fn}/{cn}")
                bad = 1
            if loops > 0 and int(fn) - int(cn) != difference:
                print(f"{path}: FN - CN = {difference} by Gruebler, expected.tsv says {fn} - {cn}")
                bad = 1
        return bad
    for path in argv[1:]:
        bodies, couplings, loops, total, difference = gruebler(path)
        print(f"{path}: bodies {bodies} (ground included), couplings {couplings}, loops {loops}, "
              f"sum of freedoms {total}, FN - CN = {difference}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
