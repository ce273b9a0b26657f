/// @file Hamilton's canonical equations (Hiller §3.8): the generalized momenta
/// p = ∂T/∂q̇ = M(q,t) q̇ + b(q,t), the Hamiltonian H(q,p,t) = pᵀq̇ − L with
/// q̇ = M⁻¹(p − b) eliminated, and
///     q̇ = ∂H/∂p,   ṗ = −∂H/∂q + Q − ∂R/∂q̇,
/// with the nonconservative generalized forces Q and Rayleigh's dissipation R
/// taken at q̇(q, p). The state is x = [q; p]: the equations take the form of
/// Appell's (kinematic equations q̇ = r(q,p,t), M = I, f = ṗ), so the header,
/// the simulation and the stability analysis serve both. H is written in closed
/// form, with M⁻¹ formed symbolically, for up to three coordinates and a small M
/// (150 nodes: a free body's, not a three-joint arm's) or a diagonal M; beyond
/// that M⁻¹ swells, and the generated code solves M q̇ = p − b instead.
#include "derive/methods.hpp"

#include <algorithm>
#include <iterator>

#include "symbolic/trig_rational.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

ex compact(const ex& e, const MotionSymbols& motion) { return simplify_trig_rational(tidy(e, motion), motion); }

// q̇ = M⁻¹(p − b) eliminated symbolically: H(q, p, t) = pᵀq̇ − T + V, ṗ = −∂H/∂q + Q − ∂R/∂q̇
void write_closed_form(Equations& e, const Equations& lagrange, const Mechanics& mech,
                       const std::vector<GiNaC::realsymbol>& momenta, const std::vector<ex>& bias,
                       const MotionSymbols& motion) {
  const Symbols& s = lagrange.symbols;
  std::size_t n = momenta.size();
  GiNaC::matrix shifted(n, 1);
  for (unsigned j = 0; j < n; ++j) shifted(j, 0) = momenta[j] - bias[j];
  GiNaC::matrix rates = lagrange.mass_matrix.inverse().mul(shifted);
  GiNaC::exmap velocity_of;
  for (unsigned j = 0; j < n; ++j) {
    e.coordinate_rates.push_back(compact(rates(j, 0), motion));
    velocity_of[s.velocities[j]] = e.coordinate_rates.back();
  }
  const ex& T = lagrange.kinetic_energy;
  ex H = mech.potential_energy - T.subs(velocity_of);
  for (unsigned j = 0; j < n; ++j) H += momenta[j] * e.coordinate_rates[j];
  e.hamiltonian = compact(H.normal(), motion);
  for (unsigned j = 0; j < n; ++j) {
    ex applied = (mech.generalized_force[j] - mech.dissipation.diff(s.velocities[j])).subs(velocity_of);
    e.forcing[j] = compact(-e.hamiltonian.diff(s.coordinates[j]) + applied, motion);
  }
  e.kinetic_energy = compact(T.subs(velocity_of), motion);
  e.dissipation = compact(mech.dissipation.subs(velocity_of), motion);
  for (NamedSymbolic& o : e.outputs) o.expression = compact(o.expression.subs(velocity_of), motion);
}

// v = q̇ is left to the generated code, which solves M v = p − b; with ∂H/∂q|_p = −∂L/∂q|_{q̇=v},
// ṗ = ∂T/∂q − ∂V/∂q + Q − ∂R/∂q̇, and H = vᵀ∂T/∂v − T + V, all in q and v
void write_mass_matrix_form(Equations& e, const Equations& lagrange, const Mechanics& mech, const std::vector<ex>& bias) {
  const Symbols& s = lagrange.symbols;
  const ex& T = lagrange.kinetic_energy;
  std::size_t n = bias.size();
  e.dynamics = MomentumSolve{lagrange.mass_matrix, bias};
  ex H = mech.potential_energy - T;
  for (unsigned j = 0; j < n; ++j) {
    e.coordinate_rates.push_back(s.velocities[j]);
    H += s.velocities[j] * T.diff(s.velocities[j]);
    e.forcing[j] = tidy(T.diff(s.coordinates[j]) - mech.potential_energy.diff(s.coordinates[j]) +
                            mech.generalized_force[j] - mech.dissipation.diff(s.velocities[j]), mech.motion);
  }
  e.hamiltonian = tidy(H, mech.motion);
}

}  // namespace

namespace {

// The nodes of M's entries: how much M⁻¹ and H have to be simplified
std::size_t tree_size(const GiNaC::matrix& M) {
  std::size_t nodes = 0;
  for (unsigned i = 0; i < M.rows(); ++i)
    for (unsigned j = 0; j < M.cols(); ++j) nodes += std::size_t(std::distance(M(i, j).preorder_begin(), M(i, j).preorder_end()));
  return nodes;
}

// M⁻¹ in closed form swells beyond a few coordinates unless M is diagonal, and beyond a small M of
// a few: a three-joint arm's M of 277 nodes (measured_arm) had not been simplified after 300 s,
// where the free body's of 77 takes 0.2 s
bool closed_form_fits(const GiNaC::matrix& M) {
  if (M.rows() <= 3 && tree_size(M) <= 150) return true;
  for (unsigned i = 0; i < M.rows(); ++i)
    for (unsigned j = 0; j < M.cols(); ++j)
      if (i != j && !M(i, j).is_zero()) return false;
  return true;
}

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

  // p = M q̇ + b, with b = ∂T/∂q̇ at q̇ = 0
  GiNaC::exmap at_rest;
  for (const auto& v : s.velocities) at_rest[v] = 0;
  std::vector<ex> bias;
  std::vector<NamedSymbolic> definitions;
  for (unsigned j = 0; j < n; ++j) {
    ex p_j = T.diff(s.velocities[j]);
    definitions.push_back({momenta[j].get_name(), tidy(p_j, mech.motion)});
    bias.push_back(tidy(p_j.subs(at_rest), mech.motion));
  }
  Equations e = lagrange;
  e.method = "hamilton";
  e.symbols.velocities = momenta;
  e.coordinate_velocities = s.velocities;
  e.pseudo_velocity_definitions = definitions;
  e.mass_matrix = GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(n));
  e.forcing.assign(n, 0);
  e.acceleration_energy = 0;
  if (closed_form_fits(lagrange.mass_matrix)) {
    // M = I and f = p' as written: Lagrange's recursion, in its velocities, is no form of these
    e.dynamics = std::monostate{};
    write_closed_form(e, lagrange, mech, momenta, bias, motion);
  } else {
    write_mass_matrix_form(e, lagrange, mech, bias);
  }
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
  // In the mass-matrix form the rates are the velocities v of M(q) v = p − b: separable only where
  // M and b are made of parameters and inputs alone and the forces ṗ(q, v) of those and q (any
  // other symbol, such as a tree's quantity, is taken to vary)
  if (const auto* solve = std::get_if<MomentumSolve>(&e.dynamics)) {
    const Symbols& s = e.symbols;
    auto made_of = [&](const ex& x, bool with_coordinates) {
      for (auto it = x.preorder_begin(); it != x.preorder_end(); ++it) {
        if (!GiNaC::is_a<GiNaC::symbol>(*it)) continue;
        auto among = [&](const std::vector<GiNaC::realsymbol>& set) {
          return std::any_of(set.begin(), set.end(), [&](const GiNaC::realsymbol& y) { return it->is_equal(y); });
        };
        if (!among(s.parameters) && !among(s.inputs) && !(with_coordinates && among(s.coordinates))) return false;
      }
      return true;
    };
    for (unsigned i = 0; i < solve->mass_matrix.rows(); ++i)
      for (unsigned j = 0; j < solve->mass_matrix.cols(); ++j)
        if (!made_of(solve->mass_matrix(i, j), false)) return false;
    return std::all_of(solve->bias.begin(), solve->bias.end(), [&](const ex& b) { return made_of(b, false); }) &&
           std::all_of(e.forcing.begin(), e.forcing.end(), [&](const ex& f) { return made_of(f, true); });
  }
  for (const ex& rate : e.coordinate_rates)
    for (const auto& q : e.symbols.coordinates)
      if (rate.has(q) || rate.has(e.symbols.time)) return false;
  for (const ex& force : e.forcing)
    for (const auto& p : e.symbols.velocities)
      if (force.has(p)) return false;
  return true;
}

}  // namespace eomgen
