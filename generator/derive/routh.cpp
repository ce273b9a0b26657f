/// @file Routh's reduction (Hiller §3.8.4). For cyclic coordinates q_c with conserved
/// momenta β_c = ∂L/∂q̇_c, the Routhian
///     R(q_r, q̇_r, t; β) = L − Σ_c β_c q̇_c,   q̇_c solved from β_c = ∂L/∂q̇_c,
/// is a Lagrangian of the remaining coordinates: d/dt ∂R/∂q̇_r − ∂R/∂q_r = Q_r − ∂D/∂q̇_r.
/// Its second-order form M = ∂²R/∂q̇_r², f = ∂R/∂q_r − (∂²R/∂q̇_r∂q_r) q̇_r − ∂²R/∂q̇_r∂t + Q_r
/// − ∂D/∂q̇_r turns a steady motion (q_r constant, q̇_c constant) into an equilibrium.
#include "derive/routh.hpp"

#include "derive/constraints.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "derive/first_integrals.hpp"
#include "symbolic/trig_rational.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

// why q_k cannot be eliminated, or empty: L, the forces on every coordinate and the
// dissipation must not contain it, and nothing but inertia may act on it
std::string not_reducible(const Mechanics& mech, const ex& T, std::size_t k, const Symbols& s) {
  const auto& q = s.coordinates[k];
  const std::string& name = s.coordinate_names[k];
  if (T.has(q) || mech.potential_energy.has(q))
    return fmt::format("L depends on {}, so {} is not cyclic and p_{} is not conserved", name, name, name);
  if (!tidy(mech.generalized_force[k], mech.motion).is_zero() ||
      !tidy(mech.dissipation.diff(s.velocities[k]), mech.motion).is_zero())
    return fmt::format("an applied force or dissipation acts on {}, so p_{} is not conserved", name, name);
  for (const ex& Q : mech.generalized_force)
    if (Q.has(q)) return fmt::format("an applied force depends on {}", name);
  if (mech.dissipation.has(q)) return fmt::format("the dissipation depends on {}", name);
  return "";
}

Symbols reduced_symbols(const Symbols& s, const std::vector<std::size_t>& eliminated,
                        const std::vector<GiNaC::realsymbol>& momenta, const std::vector<double>& momentum_values) {
  Symbols r = s;
  r.coordinate_names.clear(), r.coordinates.clear(), r.velocities.clear();
  r.initial_coordinates.clear(), r.initial_velocities.clear();
  r.initial_coordinate_expressions.clear(), r.initial_rate_expressions.clear();
  for (std::size_t k = 0; k < s.coordinates.size(); ++k) {
    if (std::find(eliminated.begin(), eliminated.end(), k) != eliminated.end()) continue;
    r.coordinate_names.push_back(s.coordinate_names[k]);
    r.coordinates.push_back(s.coordinates[k]);
    r.velocities.push_back(s.velocities[k]);
    r.initial_coordinates.push_back(s.initial_coordinates[k]);
    r.initial_velocities.push_back(s.initial_velocities[k]);
    r.initial_coordinate_expressions.push_back(s.initial_coordinate_expressions[k]);
    r.initial_rate_expressions.push_back(s.initial_rate_expressions[k]);
  }
  r.by_name.clear();
  for (std::size_t i = 0; i < momenta.size(); ++i) {
    r.parameter_names.push_back(momenta[i].get_name());
    r.parameters.push_back(momenta[i]);
    r.parameter_defaults.push_back(momentum_values[i]);
  }
  for (std::size_t i = 0; i < r.parameters.size(); ++i) r.by_name[r.parameter_names[i]] = {SymbolKind::parameter, i};
  for (std::size_t i = 0; i < r.coordinates.size(); ++i) r.by_name[r.coordinate_names[i]] = {SymbolKind::coordinate, i};
  for (std::size_t i = 0; i < r.inputs.size(); ++i) r.by_name[r.input_names[i]] = {SymbolKind::input, i};
  return r;
}


}  // namespace

Equations derive_routh(const Model& model, const Mechanics& mech, const std::vector<std::string>& cyclic) {
  const Symbols& s = model.symbols;
  if (!model.constraints.empty())
    throw std::invalid_argument("Routh's reduction needs independent coordinates; the model has constraints");
  ex T = kinetic_energy_of(mech);
  std::vector<std::size_t> eliminated;
  std::vector<GiNaC::realsymbol> momenta;
  for (const std::string& name : cyclic) {
    auto it = std::find(s.coordinate_names.begin(), s.coordinate_names.end(), name);
    if (it == s.coordinate_names.end()) throw std::invalid_argument(fmt::format("{} is not a coordinate of the model", name));
    std::size_t k = static_cast<std::size_t>(it - s.coordinate_names.begin());
    if (std::string why = not_reducible(mech, T, k, s); !why.empty()) throw std::invalid_argument(why);
    if (s.by_name.count("p_" + name)) throw std::invalid_argument(fmt::format("the model already has a symbol p_{}", name));
    eliminated.push_back(k);
    momenta.emplace_back("p_" + name);
  }
  if (eliminated.size() == s.coordinates.size()) throw std::invalid_argument("Routh's reduction would leave no coordinate");
  // β_c = ∂T/∂q̇_c is linear in q̇_c: A q̇_c = β − (∂T/∂q̇_c at q̇_c = 0)
  std::size_t c = eliminated.size();
  GiNaC::exmap cyclic_at_rest;
  for (std::size_t k : eliminated) cyclic_at_rest[s.velocities[k]] = 0;
  GiNaC::matrix A(c, c), rhs(c, 1);
  std::vector<double> momentum_values;
  for (unsigned i = 0; i < c; ++i) {
    ex p = T.diff(s.velocities[eliminated[i]]);
    momentum_values.push_back(initial_value(p, s));
    for (unsigned j = 0; j < c; ++j) A(i, j) = p.diff(s.velocities[eliminated[j]]);
    rhs(i, 0) = momenta[i] - p.subs(cyclic_at_rest);
  }
  GiNaC::matrix rates = A.inverse().mul(rhs);
  Symbols r = reduced_symbols(s, eliminated, momenta, momentum_values);
  MotionSymbols motion = motion_symbols(r);
  GiNaC::exmap cyclic_rates;
  for (unsigned i = 0; i < c; ++i) cyclic_rates[s.velocities[eliminated[i]]] = simplify_trig_rational(tidy(rates(i, 0), motion), motion);
  ex routhian = T - mech.potential_energy;
  for (unsigned i = 0; i < c; ++i) routhian -= momenta[i] * s.velocities[eliminated[i]];
  routhian = simplify_trig_rational(tidy(routhian.subs(cyclic_rates).normal(), motion), motion);

  std::size_t n = r.coordinates.size();
  Equations e;
  e.model_name = model.name + "_routh";
  e.title = model.title + " (Routh-reduced)";
  e.method = "routh";
  e.source = model.source;
  e.symbols = r;
  e.degrees_of_freedom = n;
  e.mass_matrix = GiNaC::matrix(n, n);
  e.forcing.assign(n, 0);
  std::size_t row = 0;
  for (std::size_t k = 0; k < s.coordinates.size(); ++k) {
    if (std::find(eliminated.begin(), eliminated.end(), k) != eliminated.end()) continue;
    ex p = routhian.diff(r.velocities[row]);
    for (unsigned j = 0; j < n; ++j) e.mass_matrix(row, j) = simplify_trig_rational(tidy(p.diff(r.velocities[j]), motion), motion);
    ex f = routhian.diff(r.coordinates[row]) - p.diff(r.time) + mech.generalized_force[k].subs(cyclic_rates) -
           mech.dissipation.diff(s.velocities[k]).subs(cyclic_rates);
    for (unsigned j = 0; j < n; ++j) f -= p.diff(r.coordinates[j]) * r.velocities[j];
    e.forcing[row++] = simplify_trig_rational(tidy(f, motion), motion);
  }
  // R = R2 + R1 + R0 by degree in q̇: R2 acts as the kinetic energy, −R0 as the amended potential
  // (V plus the centrifugal terms of the held momenta), and R2 − R0 is the original energy
  GiNaC::exmap at_rest;
  for (const auto& v : r.velocities) at_rest[v] = 0;
  ex quadratic = 0;
  for (unsigned i = 0; i < n; ++i)
    for (unsigned j = 0; j < n; ++j) quadratic += e.mass_matrix(i, j) * r.velocities[i] * r.velocities[j] / 2;
  e.kinetic_energy = tidy(quadratic, motion);
  e.potential_energy = simplify_trig_rational(tidy(-routhian.subs(at_rest), motion), motion);
  e.dissipation = tidy(mech.dissipation.subs(cyclic_rates), motion);
  for (const NamedSymbolic& o : model.outputs) {
    bool uses_eliminated = false;
    for (std::size_t k : eliminated) uses_eliminated = uses_eliminated || o.expression.has(s.coordinates[k]);
    if (!uses_eliminated) e.outputs.push_back({o.name, tidy(o.expression.subs(cyclic_rates), motion)});
  }
  e.conserves_energy_without_inputs = conserves_energy_without_inputs(mech, s);
  // the model's first integrals in the reduced state; the eliminated momenta are parameters now
  Equations full;
  full.symbols = s;
  for (FirstIntegral f : find_first_integrals(full, mech)) {
    bool eliminated_momentum = std::find_if(momenta.begin(), momenta.end(), [&](const GiNaC::realsymbol& p) {
                                 return p.get_name() == f.name;
                               }) != momenta.end();
    if (eliminated_momentum) continue;
    f.expression = simplify_trig_rational(tidy(f.expression.subs(cyclic_rates), motion), motion);
    e.first_integrals.push_back(f);
  }
  e.routhian = routhian;
  for (unsigned i = 0; i < c; ++i) e.eliminated_coordinates.push_back({s.coordinate_names[eliminated[i]], cyclic_rates[s.velocities[eliminated[i]]]});
  return e;
}

}  // namespace eomgen
