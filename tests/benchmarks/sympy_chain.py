#!/usr/bin/env python3
"""The planar n-link pendulum (point masses, absolute angles from the downward
vertical, gravity) derived by SymPy's LagrangesMethod or KanesMethod: the peer
of eomgen's derivation in peer_benchmark.py. Run in a fresh process per size.

Usage: sympy_chain.py N lagrange|kane [--cse] [--lambdify]
Prints one JSON object: seconds to form M and f; with --cse the operations of
sympy.cse over M and f by count_ops; with --lambdify ns per call of the NumPy
right-hand side solve(M, f).
"""
import json
import sys
import time

import sympy as sp
from sympy.physics import mechanics as me


def derive(n, method):
    q = me.dynamicsymbols(f"q1:{n + 1}")
    u = me.dynamicsymbols(f"u1:{n + 1}")
    m = sp.symbols(f"m1:{n + 1}")
    l = sp.symbols(f"l1:{n + 1}")
    g = sp.Symbol("g")
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    particles, loads, point = [], [], O
    speeds = u if method == "kane" else [qi.diff() for qi in q]
    for i in range(n):
        point = point.locatenew(f"P{i + 1}", l[i] * sp.sin(q[i]) * N.x - l[i] * sp.cos(q[i]) * N.y)
        point.set_vel(N, point.pos_from(O).dt(N).subs({qi.diff(): s for qi, s in zip(q, speeds)}))
        particle = me.Particle(f"p{i + 1}", point, m[i])
        particles.append(particle)
        loads.append((point, -m[i] * g * N.y))
        if method == "lagrange":
            particle.potential_energy = m[i] * g * point.pos_from(O).dot(N.y)
    if method == "lagrange":
        lm = me.LagrangesMethod(me.Lagrangian(N, *particles), q, frame=N)
        lm.form_lagranges_equations()
        return lm.mass_matrix, lm.forcing, q, [qi.diff() for qi in q], list(m) + list(l) + [g]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=[qi.diff() - ui for qi, ui in zip(q, u)])
    kane.kanes_equations(particles, loads)
    return kane.mass_matrix, kane.forcing, q, u, list(m) + list(l) + [g]


def main():
    n, method = int(sys.argv[1]), sys.argv[2]
    start = time.perf_counter()
    M, f, q, v, params = derive(n, method)
    result = {"n": n, "method": method, "seconds": time.perf_counter() - start}
    if "--cse" in sys.argv:
        replacements, reduced = sp.cse(list(M) + list(f))
        result["cse_ops"] = int(sum(sp.count_ops(e) for _, e in replacements) + sum(sp.count_ops(e) for e in reduced))
    if "--lambdify" in sys.argv:
        import numpy as np
        qs = sp.symbols(f"q1:{n + 1}")
        vs = sp.symbols(f"v1:{n + 1}")
        plain = {**dict(zip(q, qs)), **dict(zip(v, vs))}
        Mf = sp.lambdify([qs, vs, params], M.subs(plain), "numpy")
        ff = sp.lambdify([qs, vs, params], f.subs(plain), "numpy")
        rng = np.random.default_rng(1)
        x = rng.uniform(-0.5, 0.5, 2 * n)
        p = [1.0] * n + [0.5] * n + [9.81]

        def rhs():
            return np.linalg.solve(np.array(Mf(x[:n], x[n:], p), dtype=float), np.array(ff(x[:n], x[n:], p), dtype=float).ravel())
        calls, samples = max(20, 20000 // (n * n)), []
        for _ in range(7):
            t0 = time.perf_counter()
            for _ in range(calls):
                rhs()
            samples.append((time.perf_counter() - t0) / calls * 1e9)
        result["lambdify_ns"] = sorted(samples)[len(samples) // 2]
    print(json.dumps(result))


if __name__ == "__main__":
    main()
