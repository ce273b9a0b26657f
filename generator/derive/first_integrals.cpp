/// @file First integrals (Hiller §3.6, §3.8.3). With L = T − V and
///     d/dt ∂L/∂q̇ − ∂L/∂q = Q − ∂R/∂q̇ + Cᵀλ,
/// the generalized energy h = q̇ᵀ∂L/∂q̇ − L has dh/dt = −∂L/∂t + q̇ᵀ(Q − ∂R/∂q̇ + Cᵀλ):
/// it is conserved when L is free of t, no applied force or dissipation acts, and the
/// constraints are scleronomic (C q̇ = 0, so the constraint forces do no work). With
/// T = T2 + T1 + T0 (by degree in q̇), h = T2 − T0 + V, which is T + V only when T1 = T0 = 0.
/// The momentum p_k = ∂L/∂q̇_k of a coordinate that L does not contain is conserved when
/// nothing else acts on q_k: d/dt p_k = ∂L/∂q_k + (Q − ∂R/∂q̇ + Cᵀλ)_k.
#include "derive/first_integrals.hpp"

#include <cmath>
#include <optional>
#include <utility>

#include "derive/constraints.hpp"
#include "derive/state_values.hpp"
#include "symbolic/trig_rational.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

bool vanishes(const ex& e, const MotionSymbols& motion) { return tidy(e, motion).is_zero(); }

// whether x has more than `limit` nodes (counting stops there)
bool larger_than(const ex& x, std::size_t limit) {
  std::size_t nodes = 0;
  for (auto it = x.preorder_begin(); it != x.preorder_end(); ++it)
    if (++nodes > limit) return true;
  return false;
}

// the size up to which a first integral in pseudo-velocities is brought to its simplest form
constexpr std::size_t simplified_up_to = 2000;

// ∂x/∂v through the intermediates of recursive kinematics, which x may contain (chain rule, each
// intermediate's derivative once, in their order); the intermediates stay in the result
ex derivative_through(const ex& x, const GiNaC::symbol& v, const std::vector<Intermediate>& intermediates) {
  ex d = x.diff(v);
  GiNaC::exset in_x;  // x.diff(s) of a symbol s that x does not hold walks all of x to find zero
  for (auto it = x.preorder_begin(); it != x.preorder_end(); ++it)
    if (GiNaC::is_a<GiNaC::symbol>(*it)) in_x.insert(*it);
  GiNaC::exmap of;
  for (const Intermediate& i : intermediates) {
    // most of a tree's quantities (poses, axes, inertias) hold neither v nor one that does: their
    // diff would rebuild each sum only to find zero (TIAGo dual's three momenta took 3 s so)
    bool direct = false;
    GiNaC::exset inside;
    for (auto it = i.definition.preorder_begin(); it != i.definition.preorder_end(); ++it) {
      if (!GiNaC::is_a<GiNaC::symbol>(*it)) continue;
      if (it->is_equal(v)) direct = true;
      else if (of.count(*it)) inside.insert(*it);
    }
    if (!direct && inside.empty()) continue;
    ex di = direct ? i.definition.diff(v) : ex(0);
    for (const ex& k : inside) di += i.definition.diff(GiNaC::ex_to<GiNaC::symbol>(k)) * of[k];
    if (di.is_zero()) continue;
    of[i.symbol] = di;
    if (in_x.count(i.symbol)) d += x.diff(i.symbol) * di;
  }
  return d;
}

// what the model's applied forces are at zero inputs
std::vector<ex> forces_without_inputs(const Mechanics& mech, const Symbols& s) {
  GiNaC::exmap no_inputs;
  for (const auto& u : s.inputs) no_inputs[u] = 0;
  std::vector<ex> Q;
  for (const ex& q : mech.generalized_force) Q.push_back(q.subs(no_inputs));
  return Q;
}

struct Lagrangian {
  ex T, V;
  std::vector<GiNaC::realsymbol> q, qdot;
  GiNaC::realsymbol t;
};

// the text that says when a first integral holds only at zero inputs
std::string at_zero_inputs(const Mechanics& mech, const Symbols& s) {
  for (const ex& q : mech.generalized_force)
    for (const auto& u : s.inputs)
      if (q.has(u)) return " (with the inputs at zero)";
  return "";
}

// T is a quadratic form in the velocities (T1 = T0 = 0), so that h = T + V by Euler's theorem on
// homogeneous functions: the bodies' b and T0 vanish (mechanics.hpp), and the [energy] kinetic,
// checked alone, is homogeneous of degree 2. Deciding it so spares forming h from the whole T,
// which for a 30-link chain took a third of the derivation.
bool quadratic_in_velocities(const Mechanics& mech, const Lagrangian& L) {
  for (const ex& b : mech.kinetic_linear)
    if (!vanishes(b, mech.motion)) return false;
  if (!vanishes(mech.kinetic_at_rest, mech.motion)) return false;
  return quadratic_form_in(mech.extra_kinetic_energy, L.qdot, mech.motion);
}

std::optional<FirstIntegral> generalized_energy(const Equations& e, const Mechanics& mech, const Lagrangian& L) {
  const MotionSymbols& motion = mech.motion;
  if (L.T.has(L.t) || L.V.has(L.t) || !mech.dissipation.is_zero()) return std::nullopt;
  for (const ex& Q : forces_without_inputs(mech, e.symbols))
    if (!vanishes(Q, motion)) return std::nullopt;
  if (!constraints_scleronomic(e.constraints, e.symbols)) return std::nullopt;
  std::string inputs = at_zero_inputs(mech, e.symbols);
  bool quadratic = quadratic_in_velocities(mech, L);
  ex h = L.V - L.T;
  if (!quadratic) {
    for (std::size_t j = 0; j < L.q.size(); ++j) h += L.qdot[j] * L.T.diff(L.qdot[j]);
    h = tidy(h, motion);
  }
  if (quadratic || vanishes(h - L.T - L.V, motion))
    return FirstIntegral{"energy", L.T + L.V,
                         "L = T - V does not depend on t, no applied force or dissipation acts" + inputs +
                             (e.constraints.size() ? " and the constraints do not move" : "") +
                             "; T is quadratic in the velocities, so the generalized energy is T + V (Hiller §3.6)"};
  return FirstIntegral{"jacobi_integral", h,
                       "L does not depend on t and no applied force or dissipation acts" + inputs +
                           ", so h = der(q)·∂L/∂der(q) - L is conserved; T + V is not: T has terms linear in or "
                           "free of the velocities (a prescribed motion), whose drive does work (Hiller §3.6)"};
}

// the momenta of the cyclic coordinates, each with the index of its coordinate
std::vector<std::pair<std::size_t, FirstIntegral>> cyclic_momenta(const Equations& e, const Mechanics& mech,
                                                                  const Lagrangian& L) {
  std::vector<std::pair<std::size_t, FirstIntegral>> out;
  std::vector<ex> Q = forces_without_inputs(mech, e.symbols);
  const ConstraintSet& c = e.constraints;
  SymbolDependence dependence(mech.intermediates);
  GiNaC::exset in_L;
  dependence.add(L.T, in_L);
  dependence.add(L.V, in_L);
  for (std::size_t k = 0; k < L.q.size(); ++k) {
    const auto& q = L.q[k];
    if (in_L.count(q) || !vanishes(Q[k], mech.motion) ||
        !vanishes(mech.dissipation.diff(L.qdot[k]), mech.motion))
      continue;
    bool constrained = false;
    for (unsigned i = 0; i < c.size(); ++i) constrained = constrained || !c.jacobian(i, k).is_zero();
    if (constrained) continue;
    std::string name = e.symbols.coordinate_names[k];
    out.push_back({k, {"p_" + name, derivative_through(L.T, L.qdot[k], mech.intermediates),
                       name + " is cyclic: L does not contain it, and no applied force" + at_zero_inputs(mech, e.symbols) +
                           ", dissipation or constraint acts on it, so its momentum ∂L/∂der(" + name +
                           ") is conserved (Hiller §3.8.3)"}});
  }
  return out;
}

// the row j of M whose product with the velocities is the momentum of coordinate k, at two states
// to 1e-12 of the largest term, when q'_k is the velocity j itself and the momentum is long (a
// short one, such as (m_c + m) x' + m l cos θ θ', stays as it is: cheaper than forming M); −1
// otherwise. (The quadruped's horizontal momenta have 1,907 nodes in the tree's quantities, and
// were 55 KB of its header written out.)
int mass_matrix_row(const Equations& e, std::size_t k, const ex& momentum) {
  if (!larger_than(momentum, 500)) return -1;
  const Symbols& s = e.symbols;
  std::size_t n = s.velocities.size();
  if (e.mass_matrix.rows() != n || e.has_multipliers) return -1;
  int j = -1;
  for (std::size_t m = 0; m < n; ++m)
    if (e.uses_pseudo_velocities() ? (e.coordinate_rates[k] - s.velocities[m]).is_zero() : m == k) j = int(m);
  if (j < 0) return -1;
  for (int seed = 0; seed < 2; ++seed) {
    StateValues at = StateValues::spread(e.symbols, e.intermediates, seed);
    double p = at(momentum), row = 0, largest = std::abs(p);
    for (std::size_t m = 0; m < n; ++m) {
      double term = at(e.mass_matrix(unsigned(j), unsigned(m))) * at(s.velocities[m]);
      row += term, largest = std::max(largest, std::abs(term));
    }
    if (!(std::abs(p - row) <= 1e-12 * largest)) return -1;
  }
  return j;
}

// In pseudo-velocities s = Y q' (no term free of q') with T quadratic in q', T = ½ sᵀ M s; where
// q'_k enters s_j alone, with weight 1, ∂T/∂q'_k = Σ_m (∂T/∂s_m) ∂s_m/∂q'_k = (M s)_j exactly:
// the row j, found without writing ∂T/∂q'_k in the state's variables (a floating base's horizontal
// momenta: TIAGo's, 54 velocities, took 22 s each so, and 9 s more to match M's row); −1 otherwise
int pseudo_velocity_row(const Equations& e, const Mechanics& mech, const Lagrangian& L, std::size_t k) {
  std::size_t n = e.symbols.velocities.size();
  if (!e.uses_pseudo_velocities() || e.has_multipliers || e.mass_matrix.rows() != n ||
      e.pseudo_velocity_definitions.size() != n || !quadratic_in_velocities(mech, L))
    return -1;
  GiNaC::exmap at_rest;
  for (const auto& v : L.qdot) at_rest[v] = 0;
  int j = -1;
  for (std::size_t m = 0; m < n; ++m) {
    const ex& s = e.pseudo_velocity_definitions[m].expression;
    if (!s.subs(at_rest).is_zero()) return -1;
    ex weight = s.diff(L.qdot[k]);
    if ((weight - 1).is_zero() && j < 0) j = int(m);
    else if (!weight.is_zero()) return -1;
  }
  return j;
}

}  // namespace

std::vector<FirstIntegral> find_first_integrals(const Equations& e, const Mechanics& mech) {
  // Lagrange II and I (whose M is that of the unconstrained system) have T already, formed from
  // M and simplified; Appell's and Hamilton's equations hold it in other variables
  ex T = e.method == "lagrange2" || e.method == "lagrange1" ? e.kinetic_energy : kinetic_energy_of(mech);
  Lagrangian L{T, mech.potential_energy, e.symbols.coordinates,
               e.uses_pseudo_velocities() ? e.coordinate_velocities : e.symbols.velocities, e.symbols.time};
  bool hamilton = e.method == "hamilton";
  MotionSymbols motion = motion_symbols(e.symbols);
  GiNaC::exmap rates;  // q' = coordinate_rates(q, s, t) writes them in the state's variables
  for (std::size_t j = 0; e.uses_pseudo_velocities() && j < L.qdot.size(); ++j) rates[L.qdot[j]] = e.coordinate_rates[j];
  // a long expression is left as the rates make it: brought to one fraction, a floating humanoid's
  // (Talos, 38 velocities) momenta took over three minutes, and the header writes a long momentum
  // as a row of M anyway (mass_matrix_row)
  auto in_state = [&](const ex& x) {
    if (rates.empty()) return x;
    ex written = x.subs(rates);
    return larger_than(written, simplified_up_to) ? written : simplify_trig_rational(tidy(written, motion), motion);
  };
  std::vector<FirstIntegral> found;
  if (auto h = generalized_energy(e, mech, L)) {
    h->expression = hamilton ? e.hamiltonian : in_state(h->expression);  // h = H in canonical variables
    found.push_back(*h);
  }
  for (auto& [k, p] : cyclic_momenta(e, mech, L)) {
    // a long momentum is written as M's row (mass_matrix_row), a short one stays as it is
    if (int j = hamilton || !larger_than(p.expression, 500) ? -1 : pseudo_velocity_row(e, mech, L, k); j >= 0) {
      p.expression = 0;
      for (std::size_t m = 0; m < e.symbols.velocities.size(); ++m)
        p.expression += e.mass_matrix(unsigned(j), unsigned(m)) * e.symbols.velocities[m];
      p.mass_matrix_row = j;
    } else {
      p.expression = hamilton ? ex(e.symbols.velocities[k]) : in_state(p.expression);
      if (!hamilton) p.mass_matrix_row = mass_matrix_row(e, k, p.expression);
    }
    found.push_back(p);
  }
  return found;
}

}  // namespace eomgen
