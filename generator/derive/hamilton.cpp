/// @file Hamilton's canonical equations (Hiller §3.8): the generalized momenta
/// p = ∂T/∂q̇ = M(q,t) q̇ + b(q,t), the Hamiltonian H(q,p,t) = pᵀq̇ − L with
/// q̇ = M⁻¹(p − b) eliminated, and
///     q̇ = ∂H/∂p,   ṗ = −∂H/∂q + Q − ∂R/∂q̇,
/// with the nonconservative generalized forces Q and Rayleigh's dissipation R
/// taken at q̇(q, p). The state is x = [q; p]: the equations take the form of
/// Appell's (kinematic equations q̇ = r(q,p,t), M = I, f = ṗ), so the header,
/// the simulation and the stability analysis serve both. H is written in closed
/// form, with M⁻¹ formed symbolically (fine for the few coordinates of a
/// textbook system; larger models are better derived with lagrange2).
#include "derive/methods.hpp"

#include "symbolic/trig_rational.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

ex compact(const ex& e, const MotionSymbols& motion) { return simplify_trig_rational(tidy(e, motion), motion); }

}  // namespace

Equations derive_hamilton(const Model& model, const Mechanics& mech) {
  Equations lagrange = derive_lagrange2(model, mech);
  const Symbols& s = model.symbols;
  std::size_t n = s.coordinates.size();
  const ex& T = lagrange.kinetic_energy;
  std::vector<GiNaC::realsymbol> momenta;
  for (const std::string& q : s.coordinate_names) momenta.emplace_back("p_" + q);
  MotionSymbols motion = mech.motion;
  for (const auto& p : momenta) motion.symbols.insert(p);

  // p = M q̇ + b, so q̇ = M⁻¹(p − b), with b = ∂T/∂q̇ at q̇ = 0
  GiNaC::exmap at_rest;
  for (const auto& v : s.velocities) at_rest[v] = 0;
  GiNaC::matrix shifted(n, 1);
  std::vector<NamedSymbolic> definitions;
  for (unsigned j = 0; j < n; ++j) {
    ex p_j = T.diff(s.velocities[j]);
    definitions.push_back({momenta[j].get_name(), tidy(p_j, mech.motion)});
    shifted(j, 0) = momenta[j] - p_j.subs(at_rest);
  }
  GiNaC::matrix rates = lagrange.mass_matrix.inverse().mul(shifted);
  GiNaC::exmap velocity_of;
  std::vector<ex> coordinate_rates;
  for (unsigned j = 0; j < n; ++j) {
    coordinate_rates.push_back(compact(rates(j, 0), motion));
    velocity_of[s.velocities[j]] = coordinate_rates.back();
  }

  // H = pᵀ q̇ − T + V at q̇(q, p)
  ex H = mech.potential_energy - T.subs(velocity_of);
  for (unsigned j = 0; j < n; ++j) H += momenta[j] * coordinate_rates[j];
  H = compact(H.normal(), motion);

  Equations e = lagrange;
  e.method = "hamilton";
  e.symbols.velocities = momenta;
  e.coordinate_velocities = s.velocities;
  e.coordinate_rates = coordinate_rates;
  e.pseudo_velocity_definitions = definitions;
  e.hamiltonian = H;
  e.mass_matrix = GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(n));
  e.forcing.assign(n, 0);
  for (unsigned j = 0; j < n; ++j) {
    ex applied = (mech.generalized_force[j] - mech.dissipation.diff(s.velocities[j])).subs(velocity_of);
    e.forcing[j] = compact(-H.diff(s.coordinates[j]) + applied, motion);
  }
  e.kinetic_energy = compact(T.subs(velocity_of), motion);
  e.dissipation = compact(mech.dissipation.subs(velocity_of), motion);
  for (NamedSymbolic& o : e.outputs) o.expression = compact(o.expression.subs(velocity_of), motion);
  e.acceleration_energy = 0;
  // the initial momenta from the initial state with the default parameters
  GiNaC::exmap at = s.default_parameter_values();
  for (unsigned j = 0; j < n; ++j) at[s.coordinates[j]] = s.initial_coordinates[j], at[s.velocities[j]] = s.initial_velocities[j];
  at[s.time] = 0;
  e.symbols.initial_velocities.clear();
  for (const NamedSymbolic& d : definitions)
    e.symbols.initial_velocities.push_back(GiNaC::ex_to<GiNaC::numeric>(d.expression.subs(at).evalf()).to_double());
  return e;
}

bool separable_hamiltonian(const Equations& e) {
  if (e.method != "hamilton") return false;
  for (const ex& rate : e.coordinate_rates)
    for (const auto& q : e.symbols.coordinates)
      if (rate.has(q) || rate.has(e.symbols.time)) return false;
  for (const ex& force : e.forcing)
    for (const auto& p : e.symbols.velocities)
      if (force.has(p)) return false;
  return true;
}

}  // namespace eomgen
