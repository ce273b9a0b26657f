#!/usr/bin/env python3
"""Robot files nobody here wrote, against MuJoCo: each URDF or MJCF file given (or found in a
folder given) is imported (`eomgen import`), generated and compiled with robot_sweep.cpp, which
compares the header's qacc with MuJoCo's reading the same file at 20 random states and its
jacobian_state with central differences of its rhs, and times the rhs against mj_forward and
jacobian_state against the rhs in one process. Prints a Markdown
table, one row per robot, and the reason for each robot that did not get that far.

MuJoCo reads a URDF as the import does: its fixed links kept (fusestatic off), a link without
an <inertial> massless as URDF has it (inertiafromgeom off, where MuJoCo would weigh its shapes), each link with
the inertia tensor the file states (tests/support/urdf_inertias.hpp; with balanceinertia on so
that MuJoCo reads a tensor it would refuse, which the stated one then replaces), and, when
MuJoCo cannot read the file's meshes, without its mesh geoms. A URDF with a <mimic> has fewer
coordinates in eomgen than in MuJoCo, which ignores it, and MuJoCo's equality constraints (a
closed loop) are soft and broken by a random state: such robots are timed only. MuJoCo's side
has no constraints (contacts, limits, dry friction) and no medium (`density`, `viscosity`), which
the import warns it does not carry.

Usage: robot_sweep.py EOMGEN FILE_OR_FOLDER ... [--free-base] [--flags "FLAGS"] [--check TOL]
       [--check-jacobian TOL]
--free-base imports every URDF on a floating base (and gives MuJoCo the same floating joint: a new
one at the root link, or the fixed joint that mounts the robot on a link named world, floating);
--flags compiles with FLAGS instead of -O2; --check exits 1 when a robot's qacc differs from
MuJoCo's by more than TOL (relative to the larger of 1 and MuJoCo's largest |qacc|) or a robot fails,
--check-jacobian when jacobian_state differs from the central differences by more than TOL
(relative to the larger of 1 and its largest entry; the differences' own error is about 1e-9). Exit 77 without a C++
compiler or MuJoCo. Not run on any robot of another project by the tests: they sweep
tests/crosscheck/urdf/.
"""
import glob
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
TESTS = os.path.dirname(HERE)


def mesh_free(urdf):
    """The URDF without the <visual> and <collision> elements whose geometry is a mesh."""
    for tag in ("visual", "collision"):
        urdf = re.sub(r"<%s\b(?:(?!</%s>).)*?<mesh\b.*?</%s>" % (tag, tag, tag), "", urdf, flags=re.S)
    return urdf


def as_mujoco_reads_it(urdf, folder, free_base, bounded=False):
    """The URDF text with fixed links kept, no mass from shapes and inertias read as stated, its meshes looked for in
    `folder` (the file's own), and on a floating base; `bounded` raises every mass and moment to
    2e-15, so that MuJoCo reads a massless link that a joint moves (as the import does,
    generator/import/massless_bodies.hpp)."""
    bounds = ' boundmass="2e-15" boundinertia="2e-15"' if bounded else ""
    settings = '<mujoco><compiler fusestatic="false" balanceinertia="true" inertiafromgeom="false" meshdir="%s/"%s/></mujoco>' % (folder, bounds)
    if free_base:
        links = re.findall(r'<link\s+name="([^"]+)"', urdf)
        children = set(re.findall(r'<child\s+link="([^"]+)"', urdf))
        roots = [link for link in links if link not in children]
        if roots == ["world"]:
            # mounted on the world by one fixed joint: that joint floats, as `eomgen import --free-base` does
            def set_free(joint):
                block = joint.group(0)
                if not re.search(r'<parent\s+link="world"', block):
                    return block
                return re.sub(r'\btype="fixed"', 'type="floating"', block, count=1)
            urdf = re.sub(r"<joint\b.*?</joint>", set_free, urdf, flags=re.S)
        elif roots:
            settings += ('<link name="world"/><joint name="root" type="floating"><parent link="world"/>'
                         '<child link="%s"/></joint>' % roots[0])
    return re.sub(r"(<robot\b[^>]*>)", lambda m: m.group(1) + settings, urdf, count=1)


def mujoco_readings(path, name, work, free_base):
    """The URDF as MuJoCo is to read it, written into `work`, in the order to try: as it is, without
    its mesh geoms (when MuJoCo cannot read the meshes), and both again with the mass bounds."""
    folder = os.path.dirname(os.path.abspath(path))
    text, bounded = (as_mujoco_reads_it(open(path).read(), folder, free_base, b) for b in (False, True))
    readings = []
    for label, content in (("", text), ("_without_meshes", mesh_free(text)), ("_bounded", bounded),
                           ("_bounded_without_meshes", mesh_free(bounded))):
        readings.append(os.path.join(work, f"{name}{label}.urdf"))
        open(readings[-1], "w").write(content)
    return readings


def run(command, **kwargs):
    return subprocess.run(command, capture_output=True, text=True, **kwargs)


def first_line(text):
    """The first line that says what went wrong (a compiler's first error), else the first."""
    lines = [line for line in text.strip().splitlines() if line.strip()]
    errors = [line for line in lines if "error" in line]
    return (errors or lines or ["no message"])[0][:200]


def sweep_one(eomgen, path, work, flags, free_base):
    """Imports, generates, compiles and runs one robot: its name, its row (or None) and why not."""
    name = re.sub(r"\W", "_", os.path.splitext(os.path.basename(path))[0])
    urdf = path.lower().endswith(".urdf")
    toml = os.path.join(work, name + ".toml")
    command = [eomgen, "import", path, "-o", toml] + (["--free-base"] if free_base and urdf else [])
    imported = run(command)
    if imported.returncode != 0:
        return name, None, "import: " + first_line(imported.stderr)
    model = re.search(r'^name\s*=\s*"([^"]+)"', open(toml).read(), re.M).group(1)
    start = time.perf_counter()
    generated = run([eomgen, "generate", toml, "-o", work])
    generate = time.perf_counter() - start
    if generated.returncode != 0:
        return name, None, "generate: " + first_line(generated.stderr)
    binary = os.path.join(work, name + "_sweep")
    start = time.perf_counter()
    built = run(["c++", *flags, "-std=c++17", f"-DMODEL={model}", f'-DHEADER="{os.path.join(work, model + ".hpp")}"',
                 "-I", HERE, "-I", TESTS, "-I", "/usr/include/eigen3", os.path.join(HERE, "robot_sweep.cpp"),
                 "-o", binary, "-lmujoco"])
    build = time.perf_counter() - start
    if built.returncode != 0:
        return name, None, "compile: " + first_line(built.stderr)
    readings = mujoco_readings(path, name, work, free_base) if urdf else [path]
    result = None
    for reading in readings:
        flags = ["urdf", "bounded" if "_bounded" in os.path.basename(reading) else "exact"] if urdf else []
        result = run([binary, reading] + flags, timeout=600)
        if result.returncode != 2:
            break
    if result.returncode not in (0, 3):
        return name, None, "MuJoCo: " + first_line(result.stderr)
    row = json.loads(result.stdout)
    row.update(generate=generate, build=build, header_kb=os.path.getsize(os.path.join(work, model + ".hpp")) / 1000)
    return name, row, None


def robot_files(arguments):
    files = []
    for argument in arguments:
        if os.path.isdir(argument):
            for pattern in ("*.urdf", "*.xml"):
                files += sorted(glob.glob(os.path.join(argument, "**", pattern), recursive=True))
        else:
            files.append(argument)
    return [f for f in files if not os.path.basename(f).startswith(".")]


def main():
    args = sys.argv[1:]
    options = {"--flags": "-O2", "--check": None, "--check-jacobian": None}
    for key in options:
        if key in args:
            k = args.index(key)
            options[key] = args[k + 1]
            del args[k:k + 2]
    free_base = "--free-base" in args
    args = [a for a in args if a != "--free-base"]
    if len(args) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    if not shutil.which("c++") or not os.path.exists("/usr/include/mujoco/mujoco.h"):
        print("robot_sweep: needs a C++ compiler and MuJoCo (apt-get install libmujoco-dev)", file=sys.stderr)
        return 77
    eomgen, files = args[0], robot_files(args[1:])
    tolerance = float(options["--check"]) if options["--check"] else None
    jacobian_tolerance = float(options["--check-jacobian"]) if options["--check-jacobian"] else None
    rows, failures, too_far = [], [], []
    with tempfile.TemporaryDirectory() as work:
        for count, path in enumerate(files, 1):
            print(f"[{count}/{len(files)}] {path}", file=sys.stderr)
            name, row, why = sweep_one(eomgen, path, work, options["--flags"].split(), free_base)
            if row is None:
                failures.append((name, why))
                continue
            rows.append((name, row))
            if tolerance is not None and row["qacc_difference"] is not None and row["qacc_difference"] > tolerance:
                too_far.append(name)
            if jacobian_tolerance is not None and not row["jacobian_difference"] <= jacobian_tolerance:
                too_far.append(name + " (jacobian_state)")
    print("| robot | velocities | qacc against MuJoCo | jacobian_state against differences | rhs | mj_forward | "
          "mj_forward / rhs | jacobian_state | header | generate | g++ of this program |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for name, r in rows:
        qacc = f"({r['why_not_compared']}: timed only)" if r["qacc_difference"] is None else f"{r['qacc_difference']:.1e}"
        print(f"| {name} | {r['velocities']} | {qacc} | {r['jacobian_difference']:.1e} | {r['rhs_ns'] / 1000:.2f} µs | "
              f"{r['mujoco_ns'] / 1000:.2f} µs | "
              f"{r['mujoco_ns'] / r['rhs_ns']:.2f}x | {r['jacobian_ns'] / r['rhs_ns']:.1f} rhs | {r['header_kb']:.0f} KB | "
              f"{r['generate']:.2f} s | {r['build']:.1f} s |")
    for name, why in failures:
        print(f"\n{name}: {why}")
    if (tolerance is not None or jacobian_tolerance is not None) and (too_far or failures):
        print(f"\nbeyond the tolerance: {', '.join(too_far) or 'none'}; failed: {len(failures)}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
