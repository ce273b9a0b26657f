#!/usr/bin/env python3
"""The two forms of a joint tree's rhs against each other, in one process per model
(forward_dynamics_forms.cpp): M = L D L^T of the composite-rigid-body M and the Newton-Euler
f, against the articulated-body algorithm (`eomgen generate --forward-dynamics mass_matrix` and
`articulated`). Models: chains of rods on universal joints (two hinges a rod, the chain of
frames_benchmark.py; a first rod of one hinge for an odd count) from 4 to 30 hinges, and the
robots of tests/crosscheck/models/: seven_joint_arm, branched_tree (21 oblique hinges, branched)
hinge_chain (20 hinges about x and y in turn), quadruped (a free torso, four legs of three
hinges), ball_hung_chain (nine hinges below a ball joint) and floating_snake (a free head and 16
hinges), and a chain of 12 oblique hinges. Prints a
Markdown table: the mean depth of the joints (from 4.5 on eomgen weighs the algorithm,
spatial/joint_tree_forward_dynamics.cpp, and takes the form of fewer operations,
emit/cpp_joint_tree.hpp), both times, their ratio, the form eomgen takes and the largest
difference between the two forms' q'' (of its size); says so and exits 1 when that reaches 1e-9.

Usage: forward_dynamics_forms.py EOMGEN [--quick]   (exit 77 without a C++ compiler)
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
from frames_benchmark import chain_model  # noqa: E402


def rod_chain(hinges):
    """chain_model's rods, the first on a single hinge (about x) when the count is odd"""
    text = chain_model((hinges + 1) // 2).replace(f'name = "frames{(hinges + 1) // 2}"', f'name = "chain{hinges}"')
    if hinges % 2:
        text = text.replace('rotation = "rot_z(a1)*rot_x(b1)"', 'rotation = "rot_x(b1)"').replace("a1 = 0.1\n", "")
    return text


def oblique_chain(n):
    """n links hung one below the other on hinges about two oblique axes in turn through offset
    anchors, with armature (tests/generator/spatial/joint_tree_forward_dynamics_test.cpp's)"""
    lines = ['[model]', f'name = "oblique{n}"', '[parameters]', 'g = 9.81', '[coordinates]']
    lines += [f"q{i} = 0.1" for i in range(1, n + 1)]
    axes = ('["0.3", "0.5", "0.8"]', '["-0.6", "0.7", "0.2"]')
    for i in range(1, n + 1):
        lines.append(f'[[frames]]\nname = "link{i}"')
        if i > 1:
            lines.append(f'parent = "link{i - 1}"\norigin = ["0.02", "0.01", "-0.3"]')
        lines.append(f'joint = {{ type = "revolute", axis = {axes[i % 2]}, anchor = ["0.01", "0", "0.02"], '
                     f'coordinate = "q{i}" }}')
        lines.append(f'[[rigid_bodies]]\nname = "rod{i}"\nmass = "1.5"\nframe = "link{i}"\n'
                     'center = ["0.01", "0", "-0.15"]\n'
                     'inertia = [["0.02", "0.001", "0"], ["0.001", "0.025", "0.002"], ["0", "0.002", "0.015"]]')
    kinetic = " + ".join(f"0.01*der(q{i})^2/2" for i in range(1, n + 1))
    lines += ['[gravity]', 'acceleration = ["0", "0", "-g"]', '[energy]', f'kinetic = "{kinetic}"']
    return "\n".join(lines) + "\n"


def run(command):
    r = subprocess.run(command, capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError(f"{' '.join(command)}:\n{r.stderr[-3000:]}")
    return r.stdout


def chosen_form(eomgen, path, work):
    run([eomgen, "generate", path, "-o", os.path.join(work, "chosen")])
    with open(os.path.join(work, "chosen", os.path.basename(path)[:-5] + ".hpp")) as f:
        head = f.read(2000)
    return "articulated" if "articulated-body algorithm" in head else "M = L D L^T"


def measure(eomgen, name, path, work):
    for form in ("mass_matrix", "articulated"):
        run([eomgen, "generate", path, "--forward-dynamics", form, "-o", os.path.join(work, form)])
    binary = os.path.join(work, f"forms_{name}")
    run(["c++", "-std=c++17", "-O2", f"-DMODEL={name}", f"-DFACTORED={work}/mass_matrix/{name}.hpp",
         f"-DARTICULATED={work}/articulated/{name}.hpp", "-I", HERE,
         os.path.join(HERE, "forward_dynamics_forms.cpp"), "-o", binary])
    result = json.loads(run([binary]))
    result["chosen"] = chosen_form(eomgen, path, work)
    return result


def mean_depth(path):
    """the joints' mean depth, from the frames' parents (one joint a frame, or two for rot_z*rot_x)"""
    import re
    text = open(path).read()
    parent, joints = {}, {}
    for block in text.split("[[frames]]")[1:]:
        name = re.search(r'name\s*=\s*"([^"]+)"', block).group(1)
        above = re.search(r'parent\s*=\s*"([^"]+)"', block)
        parent[name] = above.group(1) if above else None
        rotation = re.search(r'rotation\s*=\s*"([^"]+)"', block)
        kind = re.search(r'type\s*=\s*"([a-z]+)"', block)
        velocities = {"free": 6, "ball": 3, "fixed": 0}.get(kind.group(1), 1) if kind else 1
        joints[name] = rotation.group(1).count("rot_") if rotation else velocities
    def above(name):
        return 0 if name is None else joints[name] + above(parent[name])
    depths = []
    for name in parent:
        base = above(parent[name])
        depths += [base + k + 1 for k in range(joints[name])]
    return sum(depths) / len(depths)


def main():
    if len(sys.argv) >= 2 and sys.argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0
    if len(sys.argv) < 2 or not os.access(sys.argv[1], os.X_OK):
        print(__doc__)
        if len(sys.argv) >= 2:
            print(f"{sys.argv[1]}: not an eomgen executable (the first argument is the eomgen to measure)")
        return 2
    if not shutil.which("c++"):
        print("no C++ compiler: skipped")
        return 77
    eomgen = sys.argv[1]
    quick = "--quick" in sys.argv
    print("| model | hinges | mean depth | M = L D L^T (ns) | articulated (ns) | ratio | eomgen takes | difference |")
    print("| --- | ---: | ---: | ---: | ---: | ---: | --- | ---: |")
    with tempfile.TemporaryDirectory() as work:
        cases = []
        for hinges in ((4, 10) if quick else (4, 8, 9, 10, 16, 30)):
            path = os.path.join(work, f"chain{hinges}.toml")
            with open(path, "w") as f:
                f.write(rod_chain(hinges))
            cases.append((f"chain{hinges}", path, hinges))
        robots = ("hinge_chain",) if quick else ("seven_joint_arm", "branched_tree", "hinge_chain", "quadruped",
                                                  "ball_hung_chain", "floating_snake")
        for robot in robots:
            path = os.path.join(ROOT, "tests", "crosscheck", "models", f"{robot}.toml")
            cases.append((robot, path, None))
        if not quick:
            path = os.path.join(work, "oblique12.toml")
            with open(path, "w") as f:
                f.write(oblique_chain(12))
            cases.append(("oblique12", path, 12))
        worst = 0.0
        for name, path, hinges in cases:
            r = measure(eomgen, name, path, work)
            depth = mean_depth(path)
            count = hinges if hinges else open(path).read().count('type = "revolute"')  # the hinges alone
            worst = max(worst, r["difference"])
            print(f"| {name} | {count} | {depth:.1f} | {r['ldlt_ns']:.0f} | {r['articulated_ns']:.0f} | "
                  f"{r['ldlt_ns'] / r['articulated_ns']:.2f}x | {r['chosen']} | {r['difference']:.1e} |", flush=True)
    print(f"\nratio: M = L D L^T time over the articulated-body algorithm's (above 1: the algorithm is faster)")
    if worst >= 1e-9:
        print(f"the two forms disagree: {worst:.1e} of the size of q''")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
