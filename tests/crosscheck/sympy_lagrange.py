#!/usr/bin/env python3
"""Cross-check of eomgen's Lagrange II against SymPy's LagrangesMethod.

For the pendulum, the double pendulum and the cart pendulum, the systems are
set up again here in sympy.physics.mechanics from their physical description
(not from eomgen's output), and the mass matrix and forcing that SymPy derives
are compared with those in `eomgen derive --format json` at 20 random points
to 1e-12 relative. The JSON expressions are read with SymPy's own parser, which
also checks that they are valid input for it.

Usage: sympy_lagrange.py EOMGEN MODELS_DIR. Exit 77 (skipped) without SymPy.
"""
import json
import random
import subprocess
import sys

try:
    import sympy as sp
    from sympy.physics import mechanics as me
    from sympy.parsing.sympy_parser import parse_expr, standard_transformations, convert_xor
except ImportError:
    print("SymPy is not importable; skipping the cross-check")
    sys.exit(77)

t = me.dynamicsymbols._t


def pendulum():
    m, l, g, d = sp.symbols("m l g d")
    phi = me.dynamicsymbols("phi")
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", (phi, N.z))
    O = me.Point("O")
    O.set_vel(N, 0)
    P = O.locatenew("P", l * sp.sin(phi) * N.x - l * sp.cos(phi) * N.y)
    P.set_vel(N, P.pos_from(O).dt(N))
    bob = me.Particle("bob", P, m)
    bob.potential_energy = m * g * P.pos_from(O).dot(N.y)
    L = me.Lagrangian(N, bob)
    forces = [(A, -d * phi.diff(t) * N.z)]
    return [phi], {"m": m, "l": l, "g": g, "d": d}, me.LagrangesMethod(L, [phi], forcelist=forces, frame=N)


def double_pendulum():
    m1, m2, l1, l2, g, tau = sp.symbols("m1 m2 l1 l2 g tau")
    phi1, phi2 = me.dynamicsymbols("phi1 phi2")
    N = me.ReferenceFrame("N")
    A1 = N.orientnew("A1", "Axis", (phi1, N.z))
    O = me.Point("O")
    O.set_vel(N, 0)
    P1 = O.locatenew("P1", l1 * sp.sin(phi1) * N.x - l1 * sp.cos(phi1) * N.y)
    P2 = P1.locatenew("P2", l2 * sp.sin(phi2) * N.x - l2 * sp.cos(phi2) * N.y)
    for P in (P1, P2):
        P.set_vel(N, P.pos_from(O).dt(N))
    b1, b2 = me.Particle("b1", P1, m1), me.Particle("b2", P2, m2)
    b1.potential_energy = m1 * g * P1.pos_from(O).dot(N.y)
    b2.potential_energy = m2 * g * P2.pos_from(O).dot(N.y)
    L = me.Lagrangian(N, b1, b2)
    forces = [(A1, tau * N.z)]  # a torque on the first link is the generalized force tau on phi1
    names = {"m1": m1, "m2": m2, "l1": l1, "l2": l2, "g": g, "tau": tau}
    return [phi1, phi2], names, me.LagrangesMethod(L, [phi1, phi2], forcelist=forces, frame=N)


def cart_pendulum():
    mc, m, l, g, F = sp.symbols("mc m l g F")
    x, theta = me.dynamicsymbols("x theta")
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    C = O.locatenew("C", x * N.x)
    B = C.locatenew("B", l * sp.sin(theta) * N.x - l * sp.cos(theta) * N.y)
    for P in (C, B):
        P.set_vel(N, P.pos_from(O).dt(N))
    cart, bob = me.Particle("cart", C, mc), me.Particle("bob", B, m)
    bob.potential_energy = m * g * B.pos_from(O).dot(N.y)
    L = me.Lagrangian(N, cart, bob)
    names = {"mc": mc, "m": m, "l": l, "g": g, "F": F}
    return [x, theta], names, me.LagrangesMethod(L, [x, theta], forcelist=[(C, F * N.x)], frame=N)


def read_eomgen(eomgen, models, name):
    out = subprocess.run([eomgen, "derive", f"{models}/{name}.toml", "--format", "json"],
                         capture_output=True, text=True, check=True)
    return json.loads(out.stdout)


def compare(name, eomgen, models, build):
    q, names, lm = build()
    lm.form_lagranges_equations()
    data = read_eomgen(eomgen, models, name)
    coordinate_symbols = {c: sp.Symbol(c) for c in data["coordinates"]}
    velocity_symbols = {c: sp.Symbol("d_" + c) for c in data["coordinates"]}
    local = dict(names)
    local.update(coordinate_symbols)
    local.update({"d_" + c: v for c, v in velocity_symbols.items()})
    transformations = standard_transformations + (convert_xor,)

    def read(text):
        for c in data["coordinates"]:
            text = text.replace(f"der({c})", f"d_{c}")
        return parse_expr(text, local_dict=local, transformations=transformations)

    # SymPy's q(t), q'(t) → plain symbols
    to_plain = {}
    for qi in q:
        c = qi.func.__name__
        to_plain[qi.diff(t)] = velocity_symbols[c]
    for qi in q:
        to_plain[qi] = coordinate_symbols[qi.func.__name__]
    M_sympy = lm.mass_matrix.subs(to_plain)
    f_sympy = lm.forcing.subs(to_plain)
    M_ours = [[read(e) for e in row] for row in data["mass_matrix"]]
    f_ours = [read(e) for e in data["forcing"]]

    rng = random.Random(2024)
    free = list(names.values()) + list(coordinate_symbols.values()) + list(velocity_symbols.values())
    failures = 0
    n = len(q)
    for _ in range(20):
        point = {s: sp.Float(rng.uniform(0.5, 2.0), 30) for s in free}
        pairs = [(M_ours[j][k], M_sympy[j, k], f"M[{j}][{k}]") for j in range(n) for k in range(n)]
        pairs += [(f_ours[j], f_sympy[j], f"f[{j}]") for j in range(n)]
        for ours, theirs, what in pairs:
            a = float(sp.N(ours.subs(point), 30))
            b = float(sp.N(theirs.subs(point), 30))
            if abs(a - b) > 1e-12 * max(1.0, abs(a), abs(b)):
                print(f"{name} {what}: eomgen {a!r} vs SymPy {b!r}")
                failures += 1
    print(f"{name}: {'agrees' if failures == 0 else 'DIFFERS'} with SymPy LagrangesMethod at 20 random points")
    return failures == 0


def main():
    eomgen, models = sys.argv[1], sys.argv[2]
    cases = [("pendulum", pendulum), ("double_pendulum", double_pendulum), ("cart_pendulum", cart_pendulum)]
    results = [compare(name, eomgen, models, build) for name, build in cases]
    passed = sum(results)
    print(f"{passed} passed, {len(results) - passed} failed")
    sys.exit(0 if all(results) else 1)


if __name__ == "__main__":
    main()
