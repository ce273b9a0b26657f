#!/usr/bin/env python3
"""Rigid-body trees against MuJoCo, in one process per robot: the generated rhs and
jacobian_state against mj_forward on the same robot as MJCF (tests/crosscheck/mjcf/,
where tests/crosscheck/mujoco_oracle_test.cpp checks that both give the same qacc to
1e-12), with interleaved repetitions and medians (rhs_benchmark.cpp). Also the header's
size, the time `eomgen generate` takes, and g++ -O2 of rhs and jacobian_state.

Robots (written here): models/measured_arm.toml (3 hinges, the Panda's first links'
layout, measured inertias, turned by rot_z(q): the frame recursion), models/oblique_tree.toml
(5 joints, branched, oblique axes through offset anchors, a slide, a fixed frame), and
tests/crosscheck/models/ (robot_models.py): seven_joint_arm (a Panda's layout) and
branched_tree (21 oblique hinges in a humanoid's branching; with its jacobian_state it
takes about 40 s to compile) and quadruped (a free torso, four legs of three hinges: 19
coordinates, 18 velocities). Prints a Markdown table.

Usage: tree_benchmark.py EOMGEN [--quick] [--chart FILE.svg] [ROBOT ...]
(exit 77 without a C++ compiler or MuJoCo). --chart also draws the times as bars, each robot's
rhs beside mj_forward, labelled with their ratio (the README's chart).
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
ROBOTS = ("measured_arm", "oblique_tree", "seven_joint_arm", "branched_tree", "quadruped")
WITHOUT_JACOBIAN = ()


def model_file(name):
    path = os.path.join(ROOT, "models", f"{name}.toml")
    return path if os.path.exists(path) else os.path.join(ROOT, "tests", "crosscheck", "models", f"{name}.toml")


def run(command):
    r = subprocess.run(command, capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError(f"{' '.join(command)}:\n{r.stderr[-3000:]}")
    return r


def measure(eomgen, name, work):
    start = time.perf_counter()
    run([eomgen, "generate", model_file(name), "-o", work])
    generate = time.perf_counter() - start
    binary = os.path.join(work, f"tree_{name}")
    start = time.perf_counter()
    run(["c++", "-O2", "-std=c++17", f"-DMODEL={name}", "-DPLANAR=0", f"-DJACOBIAN={0 if name in WITHOUT_JACOBIAN else 1}",
         "-I", work, "-I", HERE, "-I", "/usr/include/eigen3",
         os.path.join(HERE, "rhs_benchmark.cpp"), "-o", binary, "-lmujoco"])
    build = time.perf_counter() - start
    result = json.loads(run([binary, os.path.join(ROOT, "tests", "crosscheck", "mjcf", f"{name}.xml")]).stdout)
    result.update(generate=generate, build=build, header_kb=os.path.getsize(os.path.join(work, f"{name}.hpp")) / 1000)
    return result


def svg_chart(rows):
    """Horizontal bars: per robot, eomgen's rhs and MuJoCo's mj_forward in µs, on one linear axis."""
    width, left, bar, gap, top = 760, 170, 14, 16, 40
    longest = max(max(r["eomgen_ns"], r["mujoco_ns"]) for _, r in rows) / 1000
    scale = (width - left - 90) / longest
    height = top + len(rows) * (2 * bar + gap) + 30
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" font-family="sans-serif" font-size="12">',
           f'<rect width="{width}" height="{height}" fill="white"/>',
           f'<text x="{left}" y="18" font-size="13">Time per call of the right-hand side [µs] (lower is faster)</text>',
           f'<rect x="{left}" y="24" width="10" height="10" fill="#1f77b4"/><text x="{left + 14}" y="33">eomgen rhs</text>',
           f'<rect x="{left + 100}" y="24" width="10" height="10" fill="#bbbbbb"/><text x="{left + 114}" y="33">MuJoCo mj_forward</text>']
    y = top
    for name, r in rows:
        ours, theirs = r["eomgen_ns"] / 1000, r["mujoco_ns"] / 1000
        out.append(f'<text x="{left - 8}" y="{y + bar + 4}" text-anchor="end">{name}</text>')
        out.append(f'<rect x="{left}" y="{y}" width="{ours * scale:.1f}" height="{bar}" fill="#1f77b4"/>')
        out.append(f'<text x="{left + ours * scale + 4:.1f}" y="{y + bar - 3}">{ours:.2f}</text>')
        out.append(f'<rect x="{left}" y="{y + bar}" width="{theirs * scale:.1f}" height="{bar}" fill="#bbbbbb"/>')
        out.append(f'<text x="{left + theirs * scale + 4:.1f}" y="{y + 2 * bar - 3}">{theirs:.2f} ({theirs / ours:.1f}x)</text>')
        y += 2 * bar + gap
    out.append(f'<line x1="{left}" y1="{top - 4}" x2="{left}" y2="{y}" stroke="black"/>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    if not shutil.which("c++") or not os.path.exists("/usr/include/mujoco/mujoco.h"):
        print("no C++ compiler or no MuJoCo (apt-get install libmujoco-dev): skipped")
        return 77
    arguments = sys.argv[2:]
    chart = None
    if "--chart" in arguments:
        at = arguments.index("--chart")
        if at + 1 >= len(arguments):
            print("--chart needs a file name, e.g. --chart trees.svg")
            return 2
        chart = arguments[at + 1]
        del arguments[at:at + 2]
    named = [a for a in arguments if not a.startswith("--")]
    unknown = [a for a in named if a not in ROBOTS]
    if unknown:
        print(f"unknown robot {unknown[0]}: choose from {', '.join(ROBOTS)}")
        return 2
    robots = ROBOTS[:1] if "--quick" in sys.argv else (named or ROBOTS)
    print("| robot | eomgen rhs | MuJoCo mj_forward | MuJoCo / eomgen | jacobian_state | jacobian_state / rhs "
          "| central differences / jacobian_state | header | generate | g++ -O2 (with the benchmark) |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for name in robots:
            r = measure(sys.argv[1], name, work)
            rows.append((name, r))
            ours, theirs, jac, fd = r["eomgen_ns"], r["mujoco_ns"], r["jacobian_ns"], r["finite_difference_ns"]
            jacobian = f"{jac / 1000:.2f} µs | {jac / ours:.1f} | {fd / jac:.1f}x" if jac else "– | – | –"
            print(f"| {name} | {ours / 1000:.2f} µs | {theirs / 1000:.2f} µs | {theirs / ours:.2f}x | {jacobian} "
                  f"| {r['header_kb']:.0f} KB | {r['generate']:.2f} s | {r['build']:.1f} s |", flush=True)
    if chart:
        with open(chart, "w") as f:
            f.write(svg_chart(rows))
        print(f"chart: {chart}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
