#!/usr/bin/env python3
"""The 3-D chain of rods with relative joint angles placed through frames: how
eomgen's derivation grows with the chain's length, with the positions and
rotations multiplied out (`eomgen derive --written-out`) and as eomgen derives
it (its frames read as joints: the tree of joints), against SymPy's KanesMethod
of the same chain, in one run. Each link turns about its parent's z axis by a_i, then about its own
x axis by b_i (a universal joint), carries a rod of mass m and length l hanging
along its -z axis, and the next joint sits at the rod's end; gravity along -z
and a horizontal force F at the tip. The chain is that of
tests/generator/model/frames_test.cpp, which checks the derivations agree.

Every size runs in a fresh process, stopped after LIMIT seconds. Printed: the
seconds of `eomgen derive` and `eomgen generate` (derive, CSE and the header)
and of KanesMethod forming M and f, the ratio Kane / tree generate, and
the header's size. Writes DIR/frames.md.

Usage: frames_benchmark.py EOMGEN [--quick] [--out DIR]   (exit 77 without SymPy)
"""
import os
import subprocess
import sys
import tempfile
import time

LIMIT = 120.0


def chain_model(n):
    lines = ['[model]', f'name = "frames{n}"', '[parameters]',
             'm = 1.2', 'l = 0.8', 'g = 9.81', 'F = 0.7', '[gravity]', 'acceleration = ["0", "0", "-g"]',
             '[coordinates]']
    lines += [f"a{i} = {0.1 * i:.1f}\nb{i} = {0.3 - 0.05 * i:.2f}" for i in range(1, n + 1)]
    for i in range(1, n + 1):
        lines.append(f'[[frames]]\nname = "link{i}"\nrotation = "rot_z(a{i})*rot_x(b{i})"')
        if i > 1:
            lines.append(f'parent = "link{i - 1}"\norigin = ["0", "0", "-l"]')
    for i in range(1, n + 1):
        lines.append(f'[[rigid_bodies]]\nname = "rod{i}"\nmass = "m"\nframe = "link{i}"\ncenter = ["0", "0", "-l/2"]\n'
                     'inertia = ["m*l^2/12", "m*l^2/12", "m*l^2/200"]')
    lines.append(f'[[points]]\nname = "tip"\nframe = "link{n}"\nposition = ["0", "0", "-l"]')
    lines.append('[[forces]]\nat = "tip"\nforce = ["F", "0", "0"]')
    return "\n".join(lines) + "\n"


KANE = r'''
import sys, time
import sympy as sp
from sympy.physics import mechanics as me
n = int(sys.argv[1])
start = time.perf_counter()
a, b = me.dynamicsymbols(f"a1:{n + 1}"), me.dynamicsymbols(f"b1:{n + 1}")
ua, ub = me.dynamicsymbols(f"ua1:{n + 1}"), me.dynamicsymbols(f"ub1:{n + 1}")
m, l, g, F = sp.symbols("m l g F")
N = me.ReferenceFrame("N")
joint = me.Point("O")
joint.set_vel(N, 0)
frame, bodies, loads = N, [], []
for i in range(n):
    turned = frame.orientnew(f"Z{i + 1}", "Axis", [a[i], frame.z])
    turned.set_ang_vel(frame, ua[i] * frame.z)
    link = turned.orientnew(f"A{i + 1}", "Axis", [b[i], turned.x])
    link.set_ang_vel(turned, ub[i] * turned.x)
    centre = joint.locatenew(f"C{i + 1}", -l / 2 * link.z)
    centre.v2pt_theory(joint, N, link)
    end = joint.locatenew(f"J{i + 2}", -l * link.z)
    end.v2pt_theory(joint, N, link)
    inertia = me.inertia(link, m * l**2 / 12, m * l**2 / 12, m * l**2 / 200)
    bodies.append(me.RigidBody(f"rod{i + 1}", centre, link, m, (inertia, centre)))
    loads.append((centre, -m * g * N.z))
    joint, frame = end, link
loads.append((joint, F * N.x))
kd = [x.diff() - y for x, y in zip(a + b, ua + ub)]
kane = me.KanesMethod(N, q_ind=a + b, u_ind=ua + ub, kd_eqs=kd)
kane.kanes_equations(bodies, loads)
M, f = kane.mass_matrix, kane.forcing
print(time.perf_counter() - start)
'''


def timed(command, limit=LIMIT):
    start = time.perf_counter()
    try:
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=limit)
    except subprocess.TimeoutExpired:
        return None
    return time.perf_counter() - start


def kane_seconds(n):
    try:
        out = subprocess.run([sys.executable, "-c", KANE, str(n)], check=True, capture_output=True, text=True,
                             timeout=LIMIT)
    except subprocess.TimeoutExpired:
        return None
    return float(out.stdout.strip().splitlines()[-1])


def cell(x, digits=3):
    return f"> {LIMIT:.0f}" if x is None else (f"{x:.{digits}g}" if isinstance(x, float) else str(x))


def main():
    args = sys.argv[1:]
    if args and args[0] in ("-h", "--help"):
        print(__doc__)
        return 0
    if not args or not os.access(args[0], os.X_OK):
        print(__doc__)
        if args:
            print(f"{args[0]}: not an eomgen executable (the first argument is the eomgen to measure)")
        return 2
    try:
        import sympy  # noqa: F401
    except ImportError:
        print("SymPy is not importable; skipping the frames benchmark")
        return 77
    eomgen = args[0]
    out_dir = args[args.index("--out") + 1] if "--out" in args else None
    quick = "--quick" in args
    sizes = [1, 2] if quick else [1, 2, 3, 4, 6, 8, 12, 16]
    header = ("| links | coordinates | written-out derive [s] | tree derive [s] | tree generate [s] | "
              "header [KB] | SymPy Kane [s] | Kane / tree generate |\n|---|---|---|---|---|---|---|---|")
    rows = [header]
    print(header, flush=True)
    expanded_stopped = kane_stopped = False
    with tempfile.TemporaryDirectory() as work:
        for n in sizes:
            path = os.path.join(work, f"frames{n}.toml")
            with open(path, "w") as f:
                f.write(chain_model(n))
            expanded = None if expanded_stopped else timed([eomgen, "derive", "--written-out", path])
            expanded_stopped = expanded is None
            recursive = timed([eomgen, "derive", path])
            header_path = os.path.join(work, f"frames{n}.hpp")
            generate = timed([eomgen, "generate", path, "--header", header_path])
            size = os.path.getsize(header_path) / 1000 if generate is not None else None
            kane = None if kane_stopped else kane_seconds(n)
            kane_stopped = kane is None
            ratio = f"{kane / generate:.1f}x" if kane is not None and generate else "–"
            row = (f"| {n} | {2 * n} | {cell(expanded)} | {cell(recursive)} | {cell(generate)} | "
                   f"{cell(size, 4)} | {cell(kane)} | {ratio} |")
            rows.append(row)
            print(row, flush=True)
    if out_dir:
        os.makedirs(out_dir, exist_ok=True)
        with open(os.path.join(out_dir, "frames.md"), "w") as f:
            f.write("\n".join(rows) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
