#!/usr/bin/env python3
"""eomgen against its peers, in one run: derivation time (SymPy's
LagrangesMethod and KanesMethod), generated-code size (SymPy's cse), and
right-hand-side speed (MuJoCo's mj_forward, a hand-written Eigen version, the
SymPy lambdify right-hand side), plus jacobian_state against central
differences. Writes DIR/peers.md and DIR/peers.png and prints the table.

Models (written here): the planar n-link pendulum (point masses, absolute
angles from the downward vertical) for n = 1, 2, 4, 8, 12, 16, 24, 30, 60, 100
(from 60 on without the other rhs form, the mass-matrix one, whose O(n^3) code
takes minutes to compile), each also generated with the forward dynamics that
eomgen did not choose (`generate --forward-dynamics`), whose rhs is timed in the
same process and compared (and both against the rhs in long double); and a
three-dimensional chain of n rigid rods, each link oriented by its own Cardan
angles rot_x(a_i)*rot_y(b_i) (two rotational degrees of freedom per link, like a
universal joint without twist) for n = 1, 2, 4, 8.

Operations are counted in the generated C++ as binary + - * /, unary minus
and function calls (sin, cos, sqrt, ...), so x*x is one operation like SymPy's
x**2 in count_ops; SymPy's count over M and f is compared with ours over the
same M and f (the mass_matrix and forcing functions; not for the articulated
form, whose M is a loop over the pairs of coordinates); the rhs adds the
unrolled LDL^T solve, counted separately. The header's size and the time g++ -O2
takes to compile its rhs and jacobian_state (one translation unit with both
instantiated for double) are recorded for every planar n, and drawn against n
beside the derivation time, the rhs time and the MuJoCo ratio. For the larger
chains, a program file calling rhs and jacobian_state is rebuilt (g++ -O2)
including the header, and including NAME_split.hpp with the units of
`eomgen generate --split` compiled once beforehand.

Usage: peer_benchmark.py EOMGEN [--quick] [--out DIR]   (exit 77 without SymPy)
"""
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from chain_models import planar_chain  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
LIMIT = 120.0


def spatial_model(n):
    # R_i (0, 0, -s) for R_i = rot_x(a_i) rot_y(b_i): (-s sin b, s sin a cos b, -s cos a cos b)
    def end(i, s):
        return (f"-{s}*sin(b{i})", f"{s}*sin(a{i})*cos(b{i})", f"-{s}*cos(a{i})*cos(b{i})")
    lines = ['[model]', f'name = "spatial{n}"', f'title = "Spatial {n}-link chain of rods"', '[parameters]',
             "m = 1.0", "l = 0.5", "g = 9.81", "[coordinates]"]
    lines += [f"a{i} = 0.1\nb{i} = 0.2" for i in range(1, n + 1)]
    for i in range(1, n + 1):
        parts = [end(k, "l") for k in range(1, i)] + [end(i, "l/2")]
        center = [" + ".join(p[c] for p in parts) for c in range(3)]
        lines.append(f'[[rigid_bodies]]\nname = "link{i}"\nmass = "m"\ncenter = ["{center[0]}", "{center[1]}", "{center[2]}"]\n'
                     f'rotation = "rot_x(a{i})*rot_y(b{i})"\ninertia = ["m*l^2/12", "m*l^2/12", "m*l^2/1200"]')
    lines.append('[gravity]\nacceleration = ["0", "0", "-g"]')
    return "\n".join(lines) + "\n"


def mjcf(kind, n):
    body = ""
    for i in range(n, 0, -1):
        if kind == "planar":
            inner = (f'<joint type="hinge" axis="0 1 0"/><geom type="sphere" size="0.005" pos="0 0 -0.5" mass="1"/>')
        else:
            inner = ('<joint type="hinge" axis="1 0 0"/><joint type="hinge" axis="0 1 0"/>'
                     '<geom type="capsule" fromto="0 0 0 0 0 -0.5" size="0.01" mass="1"/>')
        pos = "0 0 0" if i == 1 else "0 0 -0.5"
        body = f'<body pos="{pos}">{inner}{body}</body>'
    return ('<mujoco><option gravity="0 0 -9.81"><flag contact="disable"/></option>'
            f'<worldbody>{body}</worldbody></mujoco>')


def count_operations(header, function):
    """Operations in one generated function's body (see the module comment)."""
    body = header.split(f"void {function}(")[-1].split("\n}\n")[0]  # the definition, after any declaration
    count = 0
    for line in body.splitlines():
        line = line.strip()
        if not line or line.startswith(("//", "(void)", "using", "T ", "detail::")) or "= x[" in line or "= p[" in line or "= u[" in line:
            if not line.startswith("const T c"):
                continue
        expr = line.split("=", 1)[1] if "=" in line else ""
        count += 1 if re.match(r"\s*trig_(sin|cos)\[", expr) else 0  # a sine or cosine from detail::sin_cos
        expr = re.sub(r"T\([0-9.e+-]+L?\)", "1", expr)          # literals are not operations
        expr = re.sub(r"\b[A-Za-z_]\w*\[\d+\]", "v", expr)       # array accesses
        count += len(re.findall(r"\b(sin|cos|tan|asin|acos|atan2?|sinh|cosh|tanh|exp|log|sqrt|abs|pow)\(", expr))
        count += len(re.findall(r"(?<=[\w)\]])\s*[-+*/]\s*(?=[\w(])", expr))  # binary operators
        count += len(re.findall(r"(?:^|[=(,*/+-])\s*-\s*(?=[\w(])", expr))    # unary minus
    return count


def run(command, timeout=None, env=None):
    return subprocess.run(command, capture_output=True, text=True, timeout=timeout, env=env)


def timed_generate(eomgen, model, out, repeats):
    samples = []
    for _ in range(repeats):
        start = time.perf_counter()
        r = run([eomgen, "generate", model, "-o", out])
        samples.append(time.perf_counter() - start)
        if r.returncode != 0:
            raise RuntimeError(r.stderr)
    return statistics.median(samples)


def sympy_run(n, method, extra=()):
    try:
        r = run([sys.executable, os.path.join(HERE, "sympy_chain.py"), str(n), method, *extra], timeout=LIMIT)
        return json.loads(r.stdout) if r.returncode == 0 else None
    except subprocess.TimeoutExpired:
        return "timeout"


def compile_seconds(header_dir, name, work):
    """g++ -O2 of one translation unit that instantiates the header's rhs and jacobian_state."""
    source = os.path.join(work, f"compile_{name}.cpp")
    with open(source, "w") as f:
        f.write(f'#include "{name}.hpp"\nnamespace m = eomgen::models::{name};\n'
                "template void m::rhs<double>(double, const double*, const double*, const double*, double*);\n"
                "template void m::jacobian_state<double>(double, const double*, const double*, const double*, double*);\n")
    start = time.perf_counter()
    r = run(["c++", "-O2", "-std=c++17", "-c", "-I", header_dir, source, "-o", os.devnull])
    if r.returncode != 0:
        raise RuntimeError(r.stderr[-3000:])
    return time.perf_counter() - start


SPLIT_SIZES = {"planar": (30, 60, 100), "spatial": (4, 8)}


def timed_jobs(commands, jobs=2):
    """Wall time of running the commands at most `jobs` at a time (a make -j2 of them)."""
    start, running = time.perf_counter(), []
    for command in commands:
        if len(running) == jobs:
            running.pop(0).wait()
        running.append(subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE))
    failed = [p for p in running if p.wait() != 0]
    if failed:
        raise RuntimeError(failed[0].stderr.read().decode()[-3000:])
    return time.perf_counter() - start


def split_build(eomgen, model, name, work):
    """g++ -O2 of a program file that calls rhs and jacobian_state, as one rebuilds it after each edit:
    including NAME.hpp (every rebuild compiles the model's functions), against including NAME_split.hpp
    (they are in the units of `eomgen generate --split`, compiled once, two at a time, and linked);
    (units, rebuild whole s, rebuild split s, units s), or None when nothing is split."""
    folder = os.path.join(work, f"split_{name}")
    os.makedirs(folder, exist_ok=True)
    r = run([eomgen, "generate", model, "-o", folder, "--split"])
    if r.returncode != 0:
        raise RuntimeError(r.stderr)
    units = sorted(f for f in os.listdir(folder) if f.startswith(name + "_") and f.endswith(".cpp"))
    if not units:
        return None
    unit_objects = [os.path.join(folder, u[:-4] + ".o") for u in units]
    units_s = timed_jobs([["c++", "-O2", "-std=c++17", "-c", os.path.join(folder, u), "-o", o] for u, o in zip(units, unit_objects)])
    rebuild = {}
    for variant, include in (("whole", f"{name}.hpp"), ("split", f"{name}_split.hpp")):
        source, program = os.path.join(folder, f"{variant}.cpp"), os.path.join(folder, variant)
        with open(source, "w") as f:
            f.write(f'#include "{include}"\nnamespace m = eomgen::models::{name};\n'
                    "void step(const double* x, const double* p, double* xdot, double* J) {\n"
                    "  m::rhs(0.0, x, nullptr, p, xdot);\n  m::jacobian_state(0.0, x, nullptr, p, J);\n}\n"
                    "int main() { return 0; }\n")
        objects = unit_objects if variant == "split" else []
        rebuild[variant] = timed_jobs([["c++", "-O2", "-std=c++17", "-c", source, "-o", program + ".o"]]) + \
            timed_jobs([["c++", program + ".o", *objects, "-o", program]])
    return len(units), rebuild["whole"], rebuild["split"], units_s


def rhs_speed(header_dir, name, planar, work, other=None, jacobian=True):
    source = os.path.join(HERE, "rhs_benchmark.cpp")
    binary = os.path.join(work, f"bench_{name}")
    build = run(["c++", "-O2", "-std=c++17", f"-DMODEL={name}", f"-DPLANAR={1 if planar else 0}", "-I", header_dir,
                 *([f"-DOTHER={other}"] if other else []), f"-DJACOBIAN={1 if jacobian else 0}",
                 "-I", "/usr/include/eigen3", source, "-lmujoco", "-o", binary])
    if build.returncode != 0:
        raise RuntimeError(build.stderr[-3000:])
    xml = os.path.join(work, f"{name}.xml")
    with open(xml, "w") as f:
        f.write(mjcf("planar" if planar else "spatial", int(re.sub(r"\D", "", name))))
    return json.loads(run([binary, xml]).stdout)


def fmt(x, digits=3):
    if x is None:
        return "–"
    if x == "timeout":
        return f"> {LIMIT:.0f}"
    return f"{x:.{digits}g}"


def ratio(peer, ours):
    if peer in (None, "timeout") or not ours:
        return "> " + f"{LIMIT / ours:.0f}x" if peer == "timeout" else "–"
    return f"{peer / ours:.1f}x"


def main():
    if "--help" in sys.argv or len(sys.argv) < 2:
        print(__doc__)
        return
    try:
        import sympy  # noqa: F401
    except ImportError:
        print("SymPy is not importable; skipping the peer benchmark")
        sys.exit(77)
    eomgen, quick = sys.argv[1], "--quick" in sys.argv
    out = sys.argv[sys.argv.index("--out") + 1] if "--out" in sys.argv else os.path.join(os.getcwd(), "benchmarks")
    os.makedirs(out, exist_ok=True)
    work = tempfile.mkdtemp()
    # --quick (CTest's smoke run): one chain of each form, the mass-matrix one and the articulated one
    planar = [1, 8] if quick else [1, 2, 4, 8, 12, 16, 24, 30, 60, 100]
    spatial = [1] if quick else [1, 2, 4, 8]
    rows, points = [], []
    lagrange_gave_up = kane_gave_up = False
    for kind, sizes in (("planar", planar), ("spatial", spatial)):
        for n in sizes:
            name = f"chain{n}" if kind == "planar" else f"spatial{n}"
            model = os.path.join(work, name + ".toml")
            with open(model, "w") as f:
                f.write(planar_chain(n) if kind == "planar" else spatial_model(n))
            print(f"peer benchmark: {name} ...", file=sys.stderr, flush=True)
            derive = timed_generate(eomgen, model, work, 3 if n <= 16 else 1)
            with open(os.path.join(work, name + ".hpp")) as f:
                header = f.read()
            long_chain = n > 30
            ops_mf = count_operations(header, "mass_matrix") + count_operations(header, "forcing")
            ops_rhs = count_operations(header, "rhs")
            form = "articulated" if "articulated-body recursion" in header.split("void rhs(")[0] else "mass_matrix"
            other = None
            if kind == "planar" and not long_chain:
                # the same chain in the form eomgen did not choose, timed alongside
                other = f"{name}_other"
                with open(os.path.join(work, other + ".toml"), "w") as f:
                    f.write(planar_chain(n, name=other))
                run([eomgen, "generate", "--forward-dynamics", "mass_matrix" if form == "articulated" else "articulated",
                     os.path.join(work, other + ".toml"), "-o", work])
            # the articulated form's jacobian_state is O(n) code, the mass-matrix form's O(n^3)
            jacobian = not long_chain or form == "articulated"
            speed = rhs_speed(work, name, kind == "planar", work, other, jacobian=jacobian)
            compile_s = compile_seconds(work, name, work) if kind == "planar" and jacobian else None
            split = split_build(eomgen, model, name, work) if n in SPLIT_SIZES[kind] and not quick else None
            lagrange = kane = lam = None
            if kind == "planar":
                if not lagrange_gave_up:
                    lagrange = sympy_run(n, "lagrange")
                    lagrange_gave_up = lagrange == "timeout"
                else:
                    lagrange = "timeout"
                if not kane_gave_up:
                    kane = sympy_run(n, "kane", ("--cse", "--lambdify"))
                    kane_gave_up = kane == "timeout"
                else:
                    kane = "timeout"
            row = {"model": kind, "n": n, "states": 2 * n * (1 if kind == "planar" else 2), "derive_s": derive, "form": form,
                   "header_kb": len(header.encode()) / 1024, "compile_s": compile_s,
                   "ops_m_f": ops_mf, "ops_rhs": ops_rhs, "split": split, **speed,
                   "lagrange_s": lagrange["seconds"] if isinstance(lagrange, dict) else lagrange,
                   "kane_s": kane["seconds"] if isinstance(kane, dict) else kane,
                   "sympy_cse_ops": kane.get("cse_ops") if isinstance(kane, dict) else None,
                   "lambdify_ns": kane.get("lambdify_ns") if isinstance(kane, dict) else None}
            rows.append(row)
    write_report(rows, out, quick)


def ops_m_f(r):
    """The operations of mass_matrix and forcing, counted in the text: an articulated model's M is a
    loop over the pairs of coordinates, whose text says nothing of the operations it runs."""
    return "– (loop)" if r["form"] == "articulated" else r["ops_m_f"]


def per(a, b, digits=1):
    """a / b as a ratio, or – when either is missing."""
    if not isinstance(a, (int, float)) or not isinstance(b, (int, float)) or not b:
        return "–"
    return f"{a / b:.{digits}f}x"


def write_report(rows, out, quick):
    lines = [f"Measured {time.strftime('%Y-%m-%d')} on {os.cpu_count()} cores ({platform_line()}); "
             f"SymPy runs in a fresh process each, stopped after {LIMIT:.0f} s.", "",
             "Derivation and code:", "",
             "| model | n | states | eomgen generate [s] | SymPy Lagrange [s] | ratio | SymPy Kane [s] | ratio | ops M,f (eomgen) | ops M,f (SymPy cse of Kane) | ops rhs (eomgen) | header [KB] | g++ -O2 rhs + jacobian_state [s] |",
             "|" + "---|" * 13]
    for r in rows:
        lines.append(
            f"| {r['model']} | {r['n']} | {r['states']} | {fmt(r['derive_s'])} | {fmt(r['lagrange_s'])} | {ratio(r['lagrange_s'], r['derive_s'])} | "
            f"{fmt(r['kane_s'])} | {ratio(r['kane_s'], r['derive_s'])} | {ops_m_f(r)} | {fmt(r['sympy_cse_ops'], 6)} | {r['ops_rhs']} | "
            f"{r['header_kb']:.0f} | {fmt(r['compile_s'])} |")
    lines += ["", "Right-hand side and Jacobian (ns per call; the form is what eomgen chose; "
              "difference: largest |x'_auto − x'_other| / max(1, |x'|) over 100 random states; error: the same against "
              "the rhs in long double):", "",
              "| model | n | form | eomgen rhs [ns] | other form [ns] | other/eomgen | difference | error (eomgen, other) | MuJoCo mj_forward [ns] | MuJoCo/eomgen | Eigen by hand [ns] | Eigen/eomgen | SymPy lambdify [ns] | jacobian_state [ns] | jacobian/rhs | central differences [ns] | FD/jacobian |",
             "|" + "---|" * 17]
    for r in rows:
        errors = "–" if r.get("other_form_ns") is None else f"{r['error']:.1g}, {r['other_form_error']:.1g}"
        difference = "–" if r.get("other_form_ns") is None else f"{r['forms_differ']:.1g}"
        lines.append(
            f"| {r['model']} | {r['n']} | {r['form']} | {r['eomgen_ns']:.0f} | {fmt(r.get('other_form_ns'), 4)} | "
            f"{per(r.get('other_form_ns'), r['eomgen_ns'])} | {difference} | {errors} | "
            f"{fmt(r['mujoco_ns'], 4)} | {per(r['mujoco_ns'], r['eomgen_ns'])} | {fmt(r['eigen_ns'], 4)} | {per(r['eigen_ns'], r['eomgen_ns'])} | "
            f"{fmt(r['lambdify_ns'], 4)} | {fmt(r['jacobian_ns'], 4)} | {per(r['jacobian_ns'], r['eomgen_ns'])} | "
            f"{fmt(r['finite_difference_ns'], 4)} | {per(r['finite_difference_ns'], r['jacobian_ns'])} |")
    split_rows = [r for r in rows if r.get("split")]
    if split_rows:
        lines += ["", "Split builds (`eomgen generate --split`): rebuilding a program file that calls rhs and jacobian_state "
                  "(g++ -O2, compile and link) when it includes NAME.hpp, against including NAME_split.hpp and linking the "
                  "units, which compile once (all of them, two at a time):", "",
                  "| model | n | header [KB] | units | rebuild, NAME.hpp [s] | rebuild, NAME_split.hpp [s] | ratio | units, once [s] |",
                  "|" + "---|" * 8]
        for r in split_rows:
            units, whole, split, once = r["split"]
            lines.append(f"| {r['model']} | {r['n']} | {r['header_kb']:.0f} | {units} | {fmt(whole)} | {fmt(split)} | "
                         f"{per(whole, split)} | {fmt(once)} |")
    lines += ["", "Targets (planar chain, issue 17):"]
    by_n = {r["n"]: r for r in rows if r["model"] == "planar"}
    for n in (12, 30):
        if n in by_n:
            r = by_n[n]
            lines.append(f"- generate at n = {n}: {r['derive_s']:.3f} s, {ratio(r['kane_s'], r['derive_s'])} faster than KanesMethod "
                         f"(target 30x{', and under 0.3 s' if n == 30 else ''})")
    for n, target in ((8, 10), (30, 5)):
        if n in by_n:
            lines.append(f"- rhs vs MuJoCo at n = {n}: {per(by_n[n]['mujoco_ns'], by_n[n]['eomgen_ns'])} (target {target}x)")
    lines.append("- rhs vs MuJoCo at every n: " + ", ".join(f"{r['n']}: {per(r['mujoco_ns'], r['eomgen_ns'])}" for r in by_n.values()))
    slower = [r["n"] for r in by_n.values() if isinstance(r["eigen_ns"], (int, float)) and r["eomgen_ns"] > r["eigen_ns"]]
    lines.append(f"- rhs vs hand-written Eigen: slower at n = {slower}" if slower else "- rhs vs hand-written Eigen: not slower at any n")
    differ = [r["forms_differ"] for r in by_n.values() if r.get("other_form_ns") is not None]
    if differ:
        lines.append(f"- the two forms of the rhs differ by at most {max(differ):.1g} (target 1e-12)")
    if 30 in by_n:
        r = by_n[30]
        lines.append(f"- n = 30: header {r['header_kb']:.0f} KB (target under 200 KB), rhs + jacobian_state compile in "
                     f"{fmt(r['compile_s'])} s (target 3 s), jacobian_state {per(r['jacobian_ns'], r['eomgen_ns'])} the rhs (target 5x)")
    text = "\n".join(lines) + "\n"
    with open(os.path.join(out, "peers.md"), "w") as f:
        f.write(text)
    print(text)
    draw_chart(rows, out)


def platform_line():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "unknown CPU"


def draw_chart(rows, out):
    data = os.path.join(out, "peers.dat")
    planar = [r for r in rows if r["model"] == "planar"]
    with open(data, "w") as f:
        for r in planar:
            vals = [r["n"], r["derive_s"], r["lagrange_s"], r["kane_s"], r["eomgen_ns"], r["mujoco_ns"], r["eigen_ns"],
                    r.get("other_form_ns"), r["mujoco_ns"] / r["eomgen_ns"] if r["mujoco_ns"] else None, r["header_kb"], r["compile_s"]]
            f.write(" ".join("NaN" if not isinstance(v, (int, float)) else repr(v) for v in vals) + "\n")
    script = f"""set terminal pngcairo size 1300,1000 noenhanced
set output '{os.path.join(out, "peers.png")}'
set multiplot layout 2,2
set logscale xy
set grid
set key top left
set xlabel 'n (links of the planar chain)'
set ylabel 'derivation time [s]'
set title 'Derivation: model file to equations (and C++ for eomgen)'
plot '{data}' using 1:2 with linespoints lw 2 title 'eomgen generate (parse, derive, CSE, header)', '' using 1:3 with linespoints lw 2 title 'SymPy LagrangesMethod', '' using 1:4 with linespoints lw 2 title 'SymPy KanesMethod'
set ylabel 'time per call [ns]'
set title 'Right-hand side'
plot '{data}' using 1:5 with linespoints lw 2 title 'eomgen rhs (the form eomgen chose)', '' using 1:8 with linespoints lw 2 title 'eomgen rhs, the other form', '' using 1:6 with linespoints lw 2 title 'MuJoCo mj_forward', '' using 1:7 with linespoints lw 2 title 'Eigen by hand (LDLT)'
unset logscale y
set yrange [0:*]
set ylabel 'MuJoCo time / eomgen time'
set title 'rhs: MuJoCo mj_forward / eomgen'
plot '{data}' using 1:9 with linespoints lw 2 title 'ratio'
set logscale y
set yrange [*:*]
set ylabel 'header [KB], compile [s]'
set title 'Generated code: header size and g++ -O2 of rhs + jacobian_state'
plot '{data}' using 1:10 with linespoints lw 2 title 'header [KB]', '' using 1:11 with linespoints lw 2 title 'compile [s]'
unset multiplot
"""
    subprocess.run(["gnuplot"], input=script, text=True)


if __name__ == "__main__":
    main()
