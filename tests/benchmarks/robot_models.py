#!/usr/bin/env python3
"""Writes the robots of the tree benchmark and of the MuJoCo oracle test, each as an eomgen
model (tests/crosscheck/models/NAME.toml) and as MJCF (tests/crosscheck/mjcf/NAME.xml), from one
description (their headers are generated when the tests are built, not kept in generated/: the
tree's is 3.7 MB):

- seven_joint_arm: the kinematic layout of a 7-joint arm (the Franka Panda's link offsets:
  0.333, 0.316, 0.0825, 0.384, 0.088 m; links turned by +-90 degrees about x, hinges about z),
  with link masses, centres and full inertia tensors invented here (positive definite, the
  triangle inequality held), armature, damping and a motor on every joint;
- branched_tree: 21 hinges in a humanoid's branching (a spine of 3, two arms of 3, two legs of
  6) about oblique axes through offset anchors, with the same kinds of bodies;
- quadruped: a floating torso with four legs of three hinges;
- hinge_chain: a hanging chain of 20 hinges about x and y in turn through offset anchors, each
  link below the last (mean depth 10.5: eomgen's rhs takes the articulated-body algorithm);
- floating_snake: a head on a free joint and 16 hinges about z and y in turn behind it (the
  algorithm again, with a free joint's six columns at the root).
- floating_humanoid: the branched tree's layout, new bodies, below a torso on a free joint (M and f
  by the loops over the links below a root joint);
- humanoid_beside_a_free_body: two trees in one model, a body on a free joint and, beside it on the
  ground, the branched tree's layout with new bodies.

The numbers are drawn from a fixed seed and written with 10 significant digits (all they have). MJCF takes each
inertia tensor in its principal axes (quat and diaginertia, from numpy's eigh in double
precision, to about 1e-16 of the tensor): MuJoCo 2.2.2 diagonalizes a fullinertia only to about
1e-7. Usage: robot_models.py REPOSITORY_ROOT (needs numpy)
"""
import os
import random
import sys

import numpy as np


def number(x):
    return f"{x:.10g}"


def quat_of(R):
    t = np.trace(R)
    if t > 0:
        s = np.sqrt(t + 1) * 2
        return [s / 4, (R[2, 1] - R[1, 2]) / s, (R[0, 2] - R[2, 0]) / s, (R[1, 0] - R[0, 1]) / s]
    i = int(np.argmax(np.diag(R)))
    j, k = (i + 1) % 3, (i + 2) % 3
    s = np.sqrt(1 + R[i, i] - R[j, j] - R[k, k]) * 2
    q = [0.0, 0.0, 0.0]
    q[i], q[j], q[k] = s / 4, (R[j, i] + R[i, j]) / s, (R[k, i] + R[i, k]) / s
    return [(R[k, j] - R[j, k]) / s] + q


def body(rng, scale):
    """mass, centre, and a full inertia tensor about the centre (rounded, then checked)."""
    mass = round(rng.uniform(0.5, 4.0) * scale, 4)
    center = [round(rng.uniform(-0.05, 0.05), 4) for _ in range(3)]
    while True:
        principal = sorted(rng.uniform(0.002, 0.03) * scale for _ in range(3))
        if principal[0] + principal[1] < principal[2]:
            continue
        axis = np.array([rng.uniform(-1, 1) for _ in range(3)])
        axis /= np.linalg.norm(axis)
        angle = rng.uniform(0, np.pi)
        K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
        R = np.eye(3) + np.sin(angle) * K + (1 - np.cos(angle)) * K @ K
        inertia = np.round(R @ np.diag(principal) @ R.T, 7)
        w = np.linalg.eigvalsh(inertia)
        if w[0] > 0 and w[0] + w[1] >= w[2]:
            return mass, center, inertia


def principal_axes(inertia):
    w, V = np.linalg.eigh(inertia)
    if np.linalg.det(V) < 0:
        V[:, 0] = -V[:, 0]
    return quat_of(V), w


QUARTER = {"+x": ("rot_x(Pi/2)", "0.7071067811865476 0.7071067811865476 0 0"),
           "-x": ("rot_x(-Pi/2)", "0.7071067811865476 -0.7071067811865476 0 0"), "": (None, None)}


FREE_COORDINATES = ["x", "y", "z", "qw", "qx", "qy", "qz"]


def write(root, name, title, comment, links, gravity=9.81, base=None):
    """links: dicts with name, parent, origin, turn ('+x', '-x' or ''), axis, anchor, body; base:
    a floating base (name, height, body) on a free joint, the links' root, or None."""
    method = "appell" if base else "lagrange2"
    toml = [f"# {line}".rstrip() for line in comment] + [
        "", "[model]", f'name       = "{name}"', f'title      = "{title}"', f'method     = "{method}"', "", "[parameters]", f"g = {gravity}", "", "[inputs]"]
    toml += [f"u{i + 1} = 0.0" for i in range(len(links))] + ["", "[coordinates]"]
    if base:
        toml += ["x  = 0", "y  = 0", f"z  = {number(base['height'])}", "qw = 1", "qx = 0", "qy = 0", "qz = 0"]
    toml += [f"q{i + 1} = {{ initial = {number(0.1 * ((i % 5) - 2))}, rate = 0.0 }}" for i in range(len(links))]
    if base:
        mass, center, inertia = base["body"]
        toml += ["", "[[frames]]", f'name   = "{base["name"]}"',
                 'joint  = { type = "free", position = ["x", "y", "z"], quaternion = ["qw", "qx", "qy", "qz"], '
                 'angular_velocity = ["wx", "wy", "wz"] }',
                 "", "[[rigid_bodies]]", f'name    = "{base["name"]}_body"', f'mass    = "{number(mass)}"',
                 f'frame   = "{base["name"]}"', "center  = [" + ", ".join(f'"{number(x)}"' for x in center) + "]",
                 "inertia = [" + ", ".join("[" + ", ".join(f'"{number(x)}"' for x in row) + "]" for row in inertia) + "]"]
    kinetic, dissipation, forces = [], [], []
    for i, link in enumerate(links):
        q = f"q{i + 1}"
        toml += ["", "[[frames]]", f'name   = "{link["name"]}"']
        if link["parent"]:
            toml.append(f'parent = "{link["parent"]}"')
        toml.append("origin = [" + ", ".join(f'"{number(x)}"' for x in link["origin"]) + "]")
        if QUARTER[link["turn"]][0]:
            toml.append(f'rotation = "{QUARTER[link["turn"]][0]}"')
        anchor = "" if not any(link["anchor"]) else ", anchor = [" + ", ".join(f'"{number(x)}"' for x in link["anchor"]) + "]"
        toml.append('joint  = { type = "revolute", axis = [' + ", ".join(f'"{number(x)}"' for x in link["axis"]) + "]"
                    + anchor + f', coordinate = "{q}" }}')
        if link["armature"]:
            kinetic.append(f"{number(link['armature'])}*der({q})^2")
        dissipation.append(f"{number(link['damping'])}*der({q})^2")
        forces.append(f'{q} = "u{i + 1}"')
    for link in links:
        mass, center, inertia = link["body"]
        toml += ["", "[[rigid_bodies]]", f'name    = "{link["name"]}_body"', f'mass    = "{number(mass)}"',
                 f'frame   = "{link["name"]}"', "center  = [" + ", ".join(f'"{number(x)}"' for x in center) + "]",
                 "inertia = [" + ", ".join("[" + ", ".join(f'"{number(x)}"' for x in row) + "]" for row in inertia) + "]"]
    toml += ["", "[gravity]", 'acceleration = ["0", "0", "-g"]', "", "[energy]"]
    toml += ['kinetic     = "(' + " + ".join(kinetic) + ')/2"'] if kinetic else []
    toml += ['dissipation = "(' + " + ".join(dissipation) + ')/2"', "", "[[forces]]",
             "generalized = { " + ", ".join(forces) + " }", ""]
    with open(os.path.join(root, "tests", "crosscheck", "models", f"{name}.toml"), "w") as f:
        f.write("\n".join(toml))

    xml = [f"<!-- tests/crosscheck/models/{name}.toml for MuJoCo, written by tests/benchmarks/robot_models.py. -->",
           f'<mujoco model="{name}">', f'  <option gravity="0 0 -{gravity}">', '    <flag contact="disable"/>',
           "  </option>", "  <worldbody>"]
    children = {}
    for i, link in enumerate(links):
        children.setdefault(link["parent"], []).append(i)

    def inertial(pad, body):
        mass, center, inertia = body
        quat_i, diag = principal_axes(inertia)
        xml.append(f'{pad}  <inertial pos="{" ".join(number(x) for x in center)}" mass="{number(mass)}" '
                   f'quat="{" ".join(repr(float(x)) for x in quat_i)}" diaginertia="{" ".join(repr(float(x)) for x in diag)}"/>')

    def emit(i, depth):
        link = links[i]
        pad = "  " * depth
        quat = QUARTER[link["turn"]][1]
        head = f'{pad}<body name="{link["name"]}" pos="{" ".join(number(x) for x in link["origin"])}"'
        xml.append(head + (f' quat="{quat}">' if quat else ">"))
        xml.append(f'{pad}  <joint name="q{i + 1}" type="hinge" axis="{" ".join(number(x) for x in link["axis"])}" '
                   f'pos="{" ".join(number(x) for x in link["anchor"])}" armature="{number(link["armature"])}" '
                   f'damping="{number(link["damping"])}"/>')
        inertial(pad, link["body"])
        for c in children.get(link["name"], []):
            emit(c, depth + 1)
        xml.append(f"{pad}</body>")

    if base:
        xml += [f'    <body name="{base["name"]}" pos="0 0 {number(base["height"])}">', '      <freejoint name="root"/>']
        inertial("    ", base["body"])
        for i in children.get(base["name"], []):
            emit(i, 3)
        xml.append("    </body>")
    for i in children.get("", []):
        emit(i, 2)
    xml += ["  </worldbody>", "  <actuator>"]
    xml += [f'    <motor name="u{i + 1}" joint="q{i + 1}" gear="1" ctrllimited="false"/>' for i in range(len(links))]
    xml += ["  </actuator>", "</mujoco>", ""]
    with open(os.path.join(root, "tests", "crosscheck", "mjcf", f"{name}.xml"), "w") as f:
        f.write("\n".join(xml))


def write_urdf(root, name, links):
    """The same robot as URDF (tests/crosscheck/urdf/NAME.urdf): each link's joint placed by its origin
    and rpy, its axis in the link's frame, inertials as full tensors about the centre, damping; URDF
    has no armature and no actuators, so neither has the URDF robot (nor its import)."""
    rpy = {"+x": "1.5707963267948966 0 0", "-x": "-1.5707963267948966 0 0", "": "0 0 0"}
    xml = ['<?xml version="1.0"?>',
           f"<!-- tests/crosscheck/models/{name}.toml as URDF, without armature and motors; written by",
           "     tests/benchmarks/robot_models.py. MuJoCo's compiler reads it for the MuJoCo oracle test. -->",
           f'<robot name="{name}">', '  <link name="base"/>']
    for link in links:
        mass, center, inertia = link["body"]
        I = inertia
        xml += [f'  <link name="{link["name"]}">', "    <inertial>",
                f'      <origin xyz="{" ".join(number(x) for x in center)}" rpy="0 0 0"/>', f'      <mass value="{number(mass)}"/>',
                f'      <inertia ixx="{number(I[0][0])}" ixy="{number(I[0][1])}" ixz="{number(I[0][2])}" '
                f'iyy="{number(I[1][1])}" iyz="{number(I[1][2])}" izz="{number(I[2][2])}"/>', "    </inertial>", "  </link>"]
    for i, link in enumerate(links):
        xml += [f'  <joint name="q{i + 1}" type="continuous">', f'    <parent link="{link["parent"] or "base"}"/>',
                f'    <child link="{link["name"]}"/>',
                f'    <origin xyz="{" ".join(number(x) for x in link["origin"])}" rpy="{rpy[link["turn"]]}"/>',
                f'    <axis xyz="{" ".join(number(x) for x in link["axis"])}"/>',
                f'    <dynamics damping="{number(link["damping"])}"/>', "  </joint>"]
    xml += ["</robot>", ""]
    with open(os.path.join(root, "tests", "crosscheck", "urdf", f"{name}.urdf"), "w") as f:
        f.write("\n".join(xml))


def seven_joint_arm(rng):
    layout = [((0, 0, 0.333), ""), ((0, 0, 0), "-x"), ((0, -0.316, 0), "+x"), ((0.0825, 0, 0), "+x"),
              ((-0.0825, 0.384, 0), "-x"), ((0, 0, 0), "+x"), ((0.088, 0, 0), "+x")]
    links = []
    for i, (origin, turn) in enumerate(layout):
        links.append(dict(name=f"link{i + 1}", parent=f"link{i}" if i else "", origin=origin, turn=turn,
                          axis=(0, 0, 1), anchor=(0, 0, 0), body=body(rng, 1.0 if i < 4 else 0.4),
                          armature=0.1, damping=1.0))
    return links


def branched_tree(rng, base="", spine=(0, 0, 1.0)):
    """base: the link the spine hangs from ("" the ground), spine: where"""
    links, names = [], []

    def chain(prefix, parent, count, offset):
        for k in range(count):
            axis = [round(rng.uniform(-1, 1), 3) for _ in range(3)]
            anchor = [round(rng.uniform(-0.03, 0.03), 3) for _ in range(3)]
            origin = offset if k == 0 else (0, 0, round(-rng.uniform(0.1, 0.3), 3))
            name = f"{prefix}{k + 1}"
            links.append(dict(name=name, parent=parent, origin=origin, turn="", axis=axis, anchor=anchor,
                              body=body(rng, 0.6), armature=0.02, damping=0.2))
            names.append(name)
            parent = name

    chain("spine", base, 3, spine)
    chain("left_arm", "spine3", 3, (0, 0.2, 0.1))
    chain("right_arm", "spine3", 3, (0, -0.2, 0.1))
    chain("left_leg", "spine1", 6, (0, 0.1, -0.1))
    chain("right_leg", "spine1", 6, (0, -0.1, -0.1))
    return links


def quadruped(rng):
    """a floating torso with four legs of three hinges: hip abduction about x through an offset
    anchor, hip flexion about y, and a knee about an axis tilted from y."""
    links = []
    for leg, (sx, sy) in {"front_left": (1, 1), "front_right": (1, -1), "rear_left": (-1, 1), "rear_right": (-1, -1)}.items():
        hip, thigh = f"{leg}_hip", f"{leg}_thigh"
        links.append(dict(name=hip, parent="torso", origin=(0.19 * sx, 0.05 * sy, 0), turn="", axis=(1, 0, 0),
                          anchor=(0, 0.01 * sy, 0), body=body(rng, 0.3), armature=0.01, damping=0.1))
        links.append(dict(name=thigh, parent=hip, origin=(0, 0.08 * sy, 0), turn="", axis=(0, 1, 0),
                          anchor=(0, 0, 0), body=body(rng, 0.4), armature=0.01, damping=0.1))
        links.append(dict(name=f"{leg}_calf", parent=thigh, origin=(0, 0, -0.21), turn="",
                          axis=(round(rng.uniform(-0.1, 0.1), 3), 1, round(rng.uniform(-0.1, 0.1), 3)),
                          anchor=(0, 0, 0.01), body=body(rng, 0.2), armature=0.02, damping=0.1))
    return links


def hinge_chain(rng):
    """20 links hung one below the other, each on a hinge through an offset anchor, about x and y in turn
    (a snake robot's pitch and yaw)."""
    links = []
    for k in range(20):
        axis = (1, 0, 0) if k % 2 == 0 else (0, 1, 0)
        anchor = [round(rng.uniform(-0.02, 0.02), 3) for _ in range(3)]
        origin = (0, 0, 2.0) if k == 0 else (round(rng.uniform(-0.02, 0.02), 3), 0, round(-rng.uniform(0.1, 0.2), 3))
        links.append(dict(name=f"link{k + 1}", parent=f"link{k}" if k else "", origin=origin, turn="", axis=axis,
                          anchor=anchor, body=body(rng, 0.3), armature=0.01, damping=0.05))
    return links


def floating_snake(rng):
    """a free head and 16 links behind it, each on a hinge through an offset anchor, about z and y in
    turn (a snake robot's yaw and pitch), falling free (no contacts)"""
    links = []
    for k in range(16):
        axis = (0, 0, 1) if k % 2 == 0 else (0, 1, 0)
        anchor = [round(rng.uniform(-0.01, 0.01), 3) for _ in range(3)]
        origin = (round(-rng.uniform(0.08, 0.12), 3), 0, round(rng.uniform(-0.01, 0.01), 3))
        links.append(dict(name=f"segment{k + 1}", parent=f"segment{k}" if k else "head", origin=origin, turn="",
                          axis=axis, anchor=anchor, body=body(rng, 0.2), armature=0.005, damping=0.02))
    return links


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
    rng = random.Random(38)
    arm = seven_joint_arm(rng)
    write_urdf(root, "seven_joint_arm", arm)
    write(root, "seven_joint_arm", "Seven-joint arm: a Panda's link offsets, invented inertias",
          ["A 7-joint arm for the tree benchmark and the MuJoCo oracle test: the link offsets of the",
           "Franka Panda (0.333, 0.316, 0.0825, 0.384, 0.088 m), links turned by +-90 degrees about x,",
           "hinges about z, with masses, centres and full inertia tensors invented here; armature,",
           "damping and a motor on each joint. Written by tests/benchmarks/robot_models.py with",
           "tests/crosscheck/mjcf/seven_joint_arm.xml, the same robot for MuJoCo."], arm)
    write(root, "branched_tree", "Humanoid-like tree of 21 hinges about oblique axes through offset anchors",
          ["21 hinges in a humanoid's branching (a spine of 3, two arms of 3, two legs of 6) about",
           "oblique axes through offset anchors, bodies with full inertia tensors, armature, damping",
           "and a motor on each joint: the 20+ joint tree of the tree benchmark and the MuJoCo oracle",
           "test. Written by tests/benchmarks/robot_models.py with tests/crosscheck/mjcf/branched_tree.xml."],
          branched_tree(rng))
    write(root, "quadruped", "Quadruped on a floating base: a free torso and four legs of three hinges",
          ["A quadruped on a floating base for the MuJoCo oracle test: a torso on a free joint (position,",
           "unit quaternion, angular velocity in the torso's axes: MuJoCo's qpos and qvel layout) and",
           "four legs of three hinges (hip abduction about x through an offset anchor, hip flexion about",
           "y, a knee about a tilted axis), bodies with full inertia tensors, armature, damping and a",
           "motor on each hinge. Written by tests/benchmarks/robot_models.py with tests/crosscheck/mjcf/quadruped.xml."],
          quadruped(rng), base=dict(name="torso", height=0.45, body=body(rng, 6.0)))
    write(root, "hinge_chain", "Hanging chain of 20 hinges about x and y in turn through offset anchors",
          ["20 links hung one below the other, each on a hinge about x or y in turn (a snake robot's pitch",
           "and yaw) through an offset anchor, bodies with full inertia tensors, armature, damping and a",
           "motor on each joint: a long serial chain, whose rhs eomgen solves by the articulated-body",
           "algorithm, for the MuJoCo oracle test. Written by tests/benchmarks/robot_models.py with",
           "tests/crosscheck/mjcf/hinge_chain.xml."],
          hinge_chain(rng))
    write(root, "floating_snake", "Snake robot floating free: a head on a free joint and 16 hinges behind it",
          ["A snake robot floating free for the MuJoCo oracle test: a head on a free joint (MuJoCo's qpos",
           "and qvel layout) and 16 segments behind it, each on a hinge about z or y in turn (yaw and",
           "pitch) through an offset anchor, bodies with full inertia tensors, armature, damping and a",
           "motor on each hinge: a floating base below which eomgen's rhs takes the articulated-body",
           "algorithm. Written by tests/benchmarks/robot_models.py with tests/crosscheck/mjcf/floating_snake.xml."],
          floating_snake(rng), base=dict(name="head", height=1.0, body=body(rng, 0.5)))
    write(root, "floating_humanoid", "Humanoid-like tree of 21 oblique hinges on a free torso",
          ["The branched tree's layout (a spine of 3, two arms of 3, two legs of 6, hinges about oblique",
           "axes through offset anchors) with new bodies, below a torso on a free joint (MuJoCo's qpos and",
           "qvel layout): a floating humanoid for the MuJoCo oracle test. Written by",
           "tests/benchmarks/robot_models.py with tests/crosscheck/mjcf/floating_humanoid.xml."],
          branched_tree(rng, "torso", (0, 0, 0.1)), base=dict(name="torso", height=1.2, body=body(rng, 8.0)))
    write(root, "humanoid_beside_a_free_body", "A free body beside a humanoid-like tree of 21 oblique hinges",
          ["Two trees in one model: a body on a free joint (MuJoCo's qpos and qvel layout) and, beside it",
           "on the ground, the branched tree's layout of 21 hinges about oblique axes through offset",
           "anchors with new bodies, for the MuJoCo oracle test. Written by tests/benchmarks/robot_models.py",
           "with tests/crosscheck/mjcf/humanoid_beside_a_free_body.xml."],
          branched_tree(rng), base=dict(name="box", height=0.5, body=body(rng, 2.0)))


if __name__ == "__main__":
    main()
