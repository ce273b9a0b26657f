#!/usr/bin/env python3
"""Rigid-body trees against MuJoCo, in one process per robot: the generated rhs and
jacobian_state against mj_forward on the same robot as MJCF (tests/crosscheck/mjcf/,
where tests/crosscheck/mujoco_oracle_test.cpp checks that both give the same qacc to
1e-12), and against Featherstone's articulated-body algorithm written by hand over Eigen
(articulated_body.hpp, checked against MuJoCo in tests/crosscheck/articulated_body_test.cpp);
jacobian_state against central differences of the rhs and against MuJoCo's mjd_transitionFD.
Interleaved repetitions and medians (rhs_benchmark.cpp); jacobian_state / rhs also from each
one's fastest batch, which a shared machine's other programs disturb the least (on a noisy
machine the medians' ratio moves between runs by a factor of two). Also the header's size, the time
`eomgen generate` takes, and g++ -O2 of a translation unit that calls rhs and jacobian_state.

Robots (written here): models/measured_arm.toml (3 hinges, the Panda's first links'
layout, measured inertias, turned by rot_z(q): the frame recursion), models/oblique_tree.toml
(5 joints, branched, oblique axes through offset anchors, a slide, a fixed frame), and
tests/crosscheck/models/ (robot_models.py): seven_joint_arm (a Panda's layout) and
branched_tree (21 oblique hinges in a humanoid's branching; with its jacobian_state it
takes about 9 s to compile) and quadruped (a free torso, four legs of three hinges: 19
coordinates, 18 velocities). Prints a Markdown table.

Usage: tree_benchmark.py EOMGEN [--quick] [--chart FILE.svg] [--flags "FLAGS"] [ROBOT ...]
(exit 77 without a C++ compiler or MuJoCo). --chart also draws the times as bars, each robot's
rhs beside mj_forward and the articulated-body algorithm by hand, labelled with their ratios to
it (the README's chart). --flags compiles the timing program (the generated header and the
algorithm by hand) with FLAGS instead of -O2, e.g. "-O3 -march=native" as Pinocchio is built;
MuJoCo stays Debian's build, and the last column stays g++ -O2.
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


def measure(eomgen, name, work, flags):
    start = time.perf_counter()
    run([eomgen, "generate", model_file(name), "-o", work])
    generate = time.perf_counter() - start
    # g++ -O2 of the header's rhs and jacobian_state alone, as a user's translation unit compiles them
    unit = os.path.join(work, f"unit_{name}.cpp")
    with open(unit, "w") as f:
        f.write(f'#include "{name}.hpp"\n'
                f"namespace robot = eomgen::models::{name};\n"
                "void rhs(const double* x, const double* u, const double* p, double* xdot) { robot::rhs(0.0, x, u, p, xdot); }\n"
                "void jacobian(const double* x, const double* u, const double* p, double* J) "
                "{ robot::jacobian_state(0.0, x, u, p, J); }\n")
    start = time.perf_counter()
    run(["c++", "-O2", "-std=c++17", "-c", "-I", work, unit, "-o", unit + ".o"])
    build = time.perf_counter() - start
    binary = os.path.join(work, f"tree_{name}")
    run(["c++", *flags, "-std=c++17", f"-DMODEL={name}", "-DPLANAR=0", f"-DJACOBIAN={0 if name in WITHOUT_JACOBIAN else 1}", "-DTREE_PEERS=1",
         "-I", work, "-I", HERE, "-I", "/usr/include/eigen3",
         os.path.join(HERE, "rhs_benchmark.cpp"), "-o", binary, "-lmujoco"])
    result = json.loads(run([binary, os.path.join(ROOT, "tests", "crosscheck", "mjcf", f"{name}.xml")]).stdout)
    result.update(generate=generate, build=build, header_kb=os.path.getsize(os.path.join(work, f"{name}.hpp")) / 1000)
    return result


def svg_chart(rows):
    """Horizontal bars: per robot, eomgen's rhs, MuJoCo's mj_forward and the articulated-body
    algorithm by hand in µs, on one linear axis."""
    width, left, bar, gap, top = 760, 170, 14, 16, 40
    peers = (("eomgen rhs", "eomgen_ns", "#1f77b4"), ("MuJoCo mj_forward", "mujoco_ns", "#bbbbbb"),
             ("articulated-body algorithm by hand (Eigen)", "featherstone_ns", "#e0a060"))
    longest = max(r[key] for _, r in rows for _, key, _ in peers) / 1000
    scale = (width - left - 90) / longest
    height = top + len(rows) * (len(peers) * bar + gap) + 30
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" font-family="sans-serif" font-size="12">',
           f'<rect width="{width}" height="{height}" fill="white"/>',
           f'<text x="{left}" y="18" font-size="13">Time per call of the right-hand side [µs] (lower is faster)</text>']
    x = left
    for label, _, colour in peers:
        out.append(f'<rect x="{x}" y="24" width="10" height="10" fill="{colour}"/><text x="{x + 14}" y="33">{label}</text>')
        x += 24 + 7 * len(label)
    y = top
    for name, r in rows:
        ours = r["eomgen_ns"] / 1000
        out.append(f'<text x="{left - 8}" y="{y + bar + 4}" text-anchor="end">{name}</text>')
        for k, (_, key, colour) in enumerate(peers):
            t = r[key] / 1000
            label = f"{t:.2f}" if k == 0 else f"{t:.2f} ({t / ours:.1f}x)"
            out.append(f'<rect x="{left}" y="{y + k * bar}" width="{t * scale:.1f}" height="{bar}" fill="{colour}"/>')
            out.append(f'<text x="{left + t * scale + 4:.1f}" y="{y + (k + 1) * bar - 3}">{label}</text>')
        y += len(peers) * bar + gap
    out.append(f'<line x1="{left}" y1="{top - 4}" x2="{left}" y2="{y}" stroke="black"/>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def main():
    if len(sys.argv) >= 2 and sys.argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0
    if len(sys.argv) < 2 or not os.access(sys.argv[1], os.X_OK):
        print(__doc__)
        if len(sys.argv) >= 2:
            print(f"{sys.argv[1]}: not an eomgen executable (the first argument is the eomgen to measure)")
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
    flags = ["-O2"]
    if "--flags" in arguments:
        at = arguments.index("--flags")
        if at + 1 >= len(arguments) or not arguments[at + 1].strip():
            print('--flags needs the compiler options in one argument, e.g. --flags "-O3 -march=native"')
            return 2
        flags = arguments[at + 1].split()
        del arguments[at:at + 2]
    named = [a for a in arguments if not a.startswith("--")]
    unknown = [a for a in named if a not in ROBOTS]
    if unknown:
        print(f"unknown robot {unknown[0]}: choose from {', '.join(ROBOTS)}")
        return 2
    robots = ROBOTS[:1] if "--quick" in sys.argv else (named or ROBOTS)
    print(f"Timing program compiled with c++ {' '.join(flags)}; MuJoCo as Debian builds it.\n")
    print("| robot | eomgen rhs | MuJoCo mj_forward | MuJoCo / eomgen | ABA by hand (Eigen) | ABA / eomgen "
          "| jacobian_state | jacobian_state / rhs | the same, fastest batches | central differences / jacobian_state "
          "| mjd_transitionFD / jacobian_state | header | generate | g++ -O2 of rhs and jacobian_state |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for name in robots:
            r = measure(sys.argv[1], name, work, flags)
            rows.append((name, r))
            ours, theirs, jac, fd = r["eomgen_ns"], r["mujoco_ns"], r["jacobian_ns"], r["finite_difference_ns"]
            aba, transition = r["featherstone_ns"], r["transition_fd_ns"]
            if r["featherstone_differs"] > 1e-10:
                raise RuntimeError(f"{name}: the articulated-body peer's qacc differs from MuJoCo's by "
                                   f"{r['featherstone_differs']:.2g} of its size")
            fastest = r["jacobian_fastest_ns"] / r["eomgen_fastest_ns"] if jac else None
            jacobian = (f"{jac / 1000:.2f} µs | {jac / ours:.1f} | {fastest:.1f} | {fd / jac:.1f}x | {transition / jac:.1f}x"
                        if jac else "– | – | – | – | –")
            print(f"| {name} | {ours / 1000:.2f} µs | {theirs / 1000:.2f} µs | {theirs / ours:.2f}x "
                  f"| {aba / 1000:.2f} µs | {aba / ours:.2f}x | {jacobian} "
                  f"| {r['header_kb']:.0f} KB | {r['generate']:.2f} s | {r['build']:.1f} s |", flush=True)
    if chart:
        with open(chart, "w") as f:
            f.write(svg_chart(rows))
        print(f"chart: {chart}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
