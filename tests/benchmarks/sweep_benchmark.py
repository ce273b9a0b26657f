#!/usr/bin/env python3
"""Stability-map throughput: `eomgen sweep` against a NumPy/SymPy sweep of the
same equations, measured in the same run.

The peer is what an engineer would write in Python: M and f from
`eomgen derive --format json` lambdified with SymPy to NumPy, the state matrix
of the reduced system by central differences of x' = [q'; M^-1 f] at the
equilibrium, and numpy.linalg.eigvals for the largest real part. It runs on one
core, so it is compared with `eomgen sweep --threads 1`; the two-thread rate
is printed beside it. The peer's values are checked against eomgen's map.

Models: the Watt governor (3 reduced states, a steady motion) on b x J, and a
six-link planar pendulum (12 states) on m1 x l1.

Usage: sweep_benchmark.py EOMGEN [--quick]   (exit 77 without NumPy and SymPy)
"""
import csv
import json
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from chain_models import planar_chain  # noqa: E402

try:
    import numpy as np
    import sympy as sp
    from sympy.parsing.sympy_parser import parse_expr, standard_transformations, convert_xor
except ImportError:
    print("NumPy or SymPy is not importable; skipping the sweep benchmark")
    sys.exit(77)

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def run(eomgen, *args):
    out = subprocess.run([eomgen, *args], capture_output=True, text=True, check=True,
                         env=dict(os.environ, EOMGEN_CACHE_DIR=os.environ.get("EOMGEN_CACHE_DIR", tempfile.gettempdir() + "/eomgen-bench-cache")))
    return out.stdout


def eomgen_sweep(eomgen, model, x, y, threads, csv_path):
    out = json.loads(run(eomgen, "sweep", model, "--param", x, "--param", y, "--threads", str(threads),
                         "--format", "json", "-o", csv_path))
    return out["points_per_second"], out["seconds"]


class PeerSweep:
    """The NumPy/SymPy sweep."""

    def __init__(self, eomgen, model):
        data = json.loads(run(eomgen, "derive", model, "--format", "json"))
        self.coords = data["coordinates"]
        self.params = list(data["parameters"])
        self.defaults = [data["parameters"][p] for p in self.params]
        q = [sp.Symbol("q_" + c) for c in self.coords]
        v = [sp.Symbol("v_" + c) for c in self.coords]
        p = [sp.Symbol("p_" + c) for c in self.params]
        local = {c: s for c, s in zip(self.coords, q)}
        local.update({name: s for name, s in zip(self.params, p)})
        local.update({"t": sp.Symbol("t")})
        for name in data["inputs"]:
            local[name] = sp.Integer(0)

        def read(text):
            for c, s in zip(self.coords, v):
                text = text.replace(f"der({c})", f"v_{c}")
            return parse_expr(text, local_dict={**local, **{f"v_{c}": s for c, s in zip(self.coords, v)}},
                              transformations=standard_transformations + (convert_xor,))
        M = sp.Matrix([[read(e) for e in row] for row in data["mass_matrix"]])
        f = sp.Matrix([read(e) for e in data["forcing"]])
        self.cyclic = [i for i, s in enumerate(q) if not (M.has(s) or f.has(s))]
        self.M = sp.lambdify([q, v, p], M, "numpy")
        self.f = sp.lambdify([q, v, p], f, "numpy")
        stability = json.loads(run(eomgen, "stability", model, "--format", "json"))
        self.state = np.array([stability["equilibrium"][name] for name in self.coords] +
                              [stability["equilibrium"][f"der({c})"] for c in self.coords])

    def rhs(self, x, p):
        n = len(self.coords)
        a = np.linalg.solve(np.array(self.M(x[:n], x[n:], p), dtype=float), np.array(self.f(x[:n], x[n:], p), dtype=float).ravel())
        return np.concatenate([x[n:], a])

    def degree(self, p):
        x, N = self.state, len(self.state)
        A = np.empty((N, N))
        for j in range(N):
            h = 1e-6 * max(1.0, abs(x[j]))
            e = np.zeros(N)
            e[j] = h
            A[:, j] = (self.rhs(x + e, p) - self.rhs(x - e, p)) / (2 * h)
        keep = [i for i in range(N) if i not in self.cyclic]
        return max(np.linalg.eigvals(A[np.ix_(keep, keep)]).real)

    def sweep(self, x_axis, y_axis, stride):
        """Every `stride`-th point of the grid eomgen swept, so the two can be compared."""
        (xn, x0, x1, xc), (yn, y0, y1, yc) = x_axis, y_axis
        xi, yi = self.params.index(xn), self.params.index(yn)
        values, start = {}, time.perf_counter()
        for j in range(0, yc, stride):
            for i in range(0, xc, stride):
                p = list(self.defaults)
                p[xi] = x0 + (x1 - x0) * i / (xc - 1)
                p[yi] = y0 + (y1 - y0) * j / (yc - 1)
                values[(round(p[xi], 12), round(p[yi], 12))] = self.degree(p)
        return len(values) / (time.perf_counter() - start), values


def axis(text):
    name, rest = text.split("=")
    lo, hi, count = rest.split(":")
    return name, float(lo), float(hi), int(count)


def main():
    eomgen, quick = sys.argv[1], "--quick" in sys.argv
    work = tempfile.mkdtemp()
    chain = os.path.join(work, "chain6.toml")
    with open(chain, "w") as f:
        f.write(planar_chain(6, name="chain6"))
    size = 4 if quick else 200
    stride = 2 if quick else 13
    cases = [("watt_governor", os.path.join(ROOT, "models", "watt_governor.toml"), "b=0.05:1.2:{}", "J=0.05:3:{}"),
             ("six-link pendulum", chain, "m1=0.5:2:{}", "l1=0.3:1:{}")]
    print("| model | states | grid | eomgen, 2 threads [points/s] | eomgen, 1 thread [points/s] | NumPy/SymPy, 1 thread [points/s] | ratio (1 thread) | largest difference |")
    print("|---|---|---|---|---|---|---|---|")
    governor_seconds = None
    for name, model, x, y in cases:
        csv_path = os.path.join(work, name.replace(" ", "_") + ".csv")
        rate1, _ = eomgen_sweep(eomgen, model, x.format(size), y.format(size), 1, csv_path)
        rate2, seconds = eomgen_sweep(eomgen, model, x.format(size), y.format(size), 2, csv_path)
        if name == "watt_governor":
            governor_seconds = seconds
        peer = PeerSweep(eomgen, model)
        peer_rate, peer_values = peer.sweep(axis(x.format(size)), axis(y.format(size)), stride)
        ours = {}
        with open(csv_path) as f:
            reader = csv.reader(f)
            next(reader)
            for row in reader:
                ours[(round(float(row[0]), 12), round(float(row[1]), 12))] = float(row[2])
        common = [k for k in peer_values if k in ours]
        difference = max((abs(peer_values[k] - ours[k]) for k in common), default=float("nan"))
        states = len(peer.state) - len(peer.cyclic)
        print(f"| {name} | {states} | {size}x{size} | {rate2:,.0f} | {rate1:,.0f} | {peer_rate:,.0f} | "
              f"{rate1 / peer_rate:,.0f}x | {difference:.1e} over {len(common)} shared points |")
    print(f"\nwatt_governor {size}x{size} map: {governor_seconds:.3f} s on 2 threads (target: under 2 s for 200x200)")


if __name__ == "__main__":
    main()
