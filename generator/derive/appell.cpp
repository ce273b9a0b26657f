/// @file Appell's equations (Hiller §4.3): with pseudo-velocities s and the kinematic
/// equations q' = W s + w, the acceleration energy
///   S = Σ ½ m a·a + ½ α·I α + α·(ω × I ω)
/// (a, α the accelerations of the bodies, linear in s') gives ∂S/∂s' = Π, where Π are
/// the generalized forces along the pseudo-velocities, Π = Wᵀ (Q − ∂V/∂q − ∂R/∂q').
/// The equations are M_s(q,t)·s' = f_s with M_s = ∂²S/∂s'² and f_s = Π − ∂S/∂s'|s'=0.
#include <stdexcept>

#include "derive/constraints.hpp"
#include "derive/methods.hpp"
#include "symbolic/trig_rational.hpp"
#include "derive/pseudo_velocities.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

struct AppellKinematics {
  GiNaC::exmap rates;              // q' → W s + w
  GiNaC::matrix W;                 // n × k
  std::vector<ex> rate_bias;       // q'' − W s' = d/dt(W s + w) at constant s
  std::vector<GiNaC::realsymbol> accelerations;  // s'
  std::vector<ex> coordinate_accelerations;      // q'' = W s' + rate_bias
};

AppellKinematics appell_kinematics(const Symbols& s, const PseudoVelocities& p) {
  std::size_t n = s.coordinates.size(), k = p.symbols.size();
  AppellKinematics a;
  a.W = GiNaC::matrix(n, k);
  for (unsigned j = 0; j < n; ++j) a.rates[s.velocities[j]] = p.coordinate_rates[j];
  for (unsigned j = 0; j < n; ++j) {
    for (unsigned c = 0; c < k; ++c) a.W(j, c) = p.coordinate_rates[j].diff(p.symbols[c]);
    ex bias = p.coordinate_rates[j].diff(s.time);
    for (unsigned i = 0; i < n; ++i) bias += p.coordinate_rates[j].diff(s.coordinates[i]) * p.coordinate_rates[i];
    a.rate_bias.push_back(bias);
  }
  for (const auto& x : p.symbols) a.accelerations.emplace_back("der(" + x.get_name() + ")");
  for (unsigned j = 0; j < n; ++j) {
    ex qdd = a.rate_bias[j];
    for (unsigned c = 0; c < k; ++c) qdd += a.W(j, c) * a.accelerations[c];
    a.coordinate_accelerations.push_back(qdd);
  }
  return a;
}

// a = J q'' + a_b with q'' = W s' + rate_bias and q' = W s + w
Vector3 body_acceleration(const GiNaC::matrix& J, const Vector3& bias, const AppellKinematics& a) {
  Vector3 out;
  for (unsigned r = 0; r < 3; ++r) {
    ex value = bias[r].subs(a.rates);
    for (unsigned j = 0; j < J.cols(); ++j)
      if (!J(r, j).is_zero()) value += J(r, j).subs(a.rates) * a.coordinate_accelerations[j];
    out[r] = value;
  }
  return out;
}

ex acceleration_energy(const Mechanics& mech, const AppellKinematics& a) {
  ex S = 0;
  for (const BodyKinematics& b : mech.bodies) {
    Vector3 acc = body_acceleration(b.velocity_jacobian, b.bias_acceleration, a);
    S += b.mass * (acc[0] * acc[0] + acc[1] * acc[1] + acc[2] * acc[2]) / 2;
    if (!b.rotates) continue;
    Vector3 alpha = body_acceleration(b.angular_velocity_jacobian, b.bias_angular_acceleration, a), w, Iw{0, 0, 0},
            Ia{0, 0, 0};
    for (unsigned r = 0; r < 3; ++r) w[r] = b.angular_velocity[r].subs(a.rates);
    for (unsigned r = 0; r < 3; ++r)
      for (unsigned c = 0; c < 3; ++c) {
        Iw[r] += b.inertia(r, c) * w[c];
        Ia[r] += b.inertia(r, c) * alpha[c];
      }
    Vector3 gyroscopic{w[1] * Iw[2] - w[2] * Iw[1], w[2] * Iw[0] - w[0] * Iw[2], w[0] * Iw[1] - w[1] * Iw[0]};
    for (unsigned r = 0; r < 3; ++r) S += alpha[r] * Ia[r] / 2 + alpha[r] * gyroscopic[r];
  }
  return S;
}

ex kinetic_energy(const Mechanics& mech, const AppellKinematics& a) {
  ex T = mech.extra_kinetic_energy.subs(a.rates);
  for (const BodyKinematics& b : mech.bodies) {
    for (unsigned r = 0; r < 3; ++r) T += b.mass * GiNaC::pow(b.velocity[r].subs(a.rates), 2) / 2;
    if (!b.rotates) continue;
    for (unsigned r = 0; r < 3; ++r)
      for (unsigned c = 0; c < 3; ++c)
        if (!b.inertia(r, c).is_zero())
          T += b.angular_velocity[r].subs(a.rates) * b.inertia(r, c) * b.angular_velocity[c].subs(a.rates) / 2;
  }
  return T;
}

// the terms of an expanded sum that contain one of `symbols`
ex terms_with(const ex& expanded, const std::vector<GiNaC::realsymbol>& symbols) {
  auto has_any = [&](const ex& term) {
    for (const auto& x : symbols)
      if (term.has(x)) return true;
    return false;
  };
  if (!GiNaC::is_a<GiNaC::add>(expanded)) return has_any(expanded) ? expanded : ex(0);
  ex out = 0;
  for (std::size_t i = 0; i < expanded.nops(); ++i)
    if (has_any(expanded.op(i))) out += expanded.op(i);
  return out;
}

}  // namespace

Equations derive_appell(const Model& model, const Mechanics& mech) {
  if (mech.tree_velocities) return derive_joint_tree_appell(model, mech);
  const Symbols& s = model.symbols;
  std::size_t n = s.coordinates.size();
  ConstraintSet constraints = constraint_set(model, mech);
  require_independent(constraints, s, mech.intermediates);
  auto chosen = pseudo_velocities(model, constraints, mech.motion);
  if (auto* why = std::get_if<std::string>(&chosen)) throw UndeterminedVelocities(*why);
  const PseudoVelocities& p = std::get<PseudoVelocities>(chosen);
  std::size_t k = p.symbols.size();
  AppellKinematics a = appell_kinematics(s, p);

  Equations e;
  e.model_name = model.name;
  e.title = model.title;
  e.method = "appell";
  e.source = model.source;
  e.symbols = s;
  e.symbols.velocities = p.symbols;
  e.symbols.initial_velocities = p.initial_values;
  e.coordinate_velocities = s.velocities;
  e.coordinate_rates = p.coordinate_rates;
  e.pseudo_velocity_definitions = p.definitions;
  e.pseudo_accelerations = a.accelerations;
  e.constraints = constraints;
  e.degrees_of_freedom = k;
  MotionSymbols motion = motion_symbols(e.symbols);
  for (const auto& x : a.accelerations) motion.symbols.insert(x);

  // [energy] kinetic has no bodies to take accelerations of: its Lagrange terms
  // M_T q'' + g_T enter as S_T = q''ᵀ(½ M_T q'' + g_T), whose ∂/∂s' is Wᵀ(M_T q'' + g_T)
  ex S = acceleration_energy(mech, a);
  if (const ex& T = mech.extra_kinetic_energy; !T.is_zero()) {
    const std::vector<ex>& qdd = a.coordinate_accelerations;
    for (unsigned j = 0; j < n; ++j) {
      ex p_j = T.diff(s.velocities[j]), inertia = 0;
      ex g = p_j.diff(s.time) - T.diff(s.coordinates[j]);
      for (unsigned i = 0; i < n; ++i) {
        inertia += p_j.diff(s.velocities[i]) * qdd[i];
        g += p_j.diff(s.coordinates[i]) * s.velocities[i];
      }
      S += qdd[j] * (inertia / 2 + g).subs(a.rates);
    }
  }
  GiNaC::exmap no_acceleration;
  for (const auto& x : a.accelerations) no_acceleration[x] = 0;
  e.mass_matrix = GiNaC::matrix(k, k);
  e.forcing.assign(k, 0);
  // the generalized forces of the coordinates, Q − ∂V/∂q − ∂R/∂q', with q' = W s + w (once each)
  std::vector<ex> applied(n);
  for (unsigned j = 0; j < n; ++j)
    applied[j] = (mech.generalized_force[j] - mech.potential_energy.diff(s.coordinates[j]) -
                  mech.dissipation.diff(s.velocities[j]))
                     .subs(a.rates);
  for (unsigned c = 0; c < k; ++c) {
    ex dS = S.diff(a.accelerations[c]);
    for (unsigned d = c; d < k; ++d) {
      e.mass_matrix(c, d) = simplify_trig_rational(tidy(dS.diff(a.accelerations[d]), motion), motion);
      e.mass_matrix(d, c) = e.mass_matrix(c, d);
    }
    ex force = -dS.subs(no_acceleration);
    for (unsigned j = 0; j < n; ++j)
      if (!a.W(j, c).is_zero()) force += a.W(j, c) * applied[j];
    e.forcing[c] = simplify_trig_rational(tidy(force, motion), motion);
  }
  e.acceleration_energy = terms_with(tidy(S, motion), a.accelerations);
  e.kinetic_energy = tidy(kinetic_energy(mech, a), motion);
  e.potential_energy = mech.potential_energy;
  e.dissipation = tidy(mech.dissipation.subs(a.rates), motion);
  for (const NamedSymbolic& o : model.outputs) e.outputs.push_back({o.name, tidy(o.expression.subs(a.rates), motion)});
  e.conserves_energy_without_inputs = conserves_energy_without_inputs(mech, s) && constraints_scleronomic(constraints, s);
  return e;
}

}  // namespace eomgen
