/// @file Lagrange's equations of the second kind, d/dt ∂T/∂q̇ − ∂T/∂q + ∂V/∂q + ∂R/∂q̇ = Q
/// (Hiller §3.3), in the form M(q,t)·q̈ = f(q,q̇,u,t).
///
/// For the bodies the inertia terms are formed from their Jacobians, which is the
/// same as differentiating their T twice (Lagrange's identity) but keeps each term
/// small: M = Σ m JᵀJ + J_ωᵀ I J_ω and the velocity terms Σ m Jᵀa_b + J_ωᵀ(I α_b + ω×Iω).
/// A kinetic energy given directly in [energy] goes through the general formula
/// M = ∂²T/∂q̇², f = ∂T/∂q − (∂²T/∂q̇∂q)·q̇ − ∂²T/∂q̇∂t.
#include <optional>

#include <fmt/format.h>

#include "common/deadline.hpp"
#include "derive/articulated_inverse_dynamics.hpp"
#include "derive/joint_tree_accelerations.hpp"
#include "derive/methods.hpp"
#include "derive/particle_tree_terms.hpp"
#include "kinematics/vector3.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

// Σ_a x_a · y_a for three-vectors held in columns of matrices or arrays
template <class X, class Y>
ex dot3(const X& x, const Y& y) {
  return x(0) * y(0) + x(1) * y(1) + x(2) * y(2);
}

// adds the body's raw (not yet simplified) terms; every entry is simplified once, at the end
// (`mass`: also its part of M, which recursive kinematics may have formed otherwise)
void add_body(const BodyKinematics& b, GiNaC::matrix& M, std::vector<ex>& f, bool mass) {
  std::size_t n = f.size();
  const GiNaC::matrix& J = b.velocity_jacobian;
  for (unsigned j = 0; j < n; ++j) {
    auto Jj = [&](int a) { return J(a, j); };
    for (unsigned k = j; k < n && mass; ++k) {
      auto Jk = [&](int a) { return J(a, k); };
      ex m = b.mass * dot3(Jj, Jk);
      if (b.rotates) {
        const GiNaC::matrix& W = b.angular_velocity_jacobian;
        for (unsigned a = 0; a < 3; ++a)
          for (unsigned c = 0; c < 3; ++c)
            if (!b.inertia(a, c).is_zero()) m += W(a, j) * b.inertia(a, c) * W(c, k);
      }
      M(j, k) += m;
    }
    auto bias = [&](int a) { return b.bias_acceleration[a]; };
    ex inertia_force = b.mass * dot3(Jj, bias);
    if (b.rotates) {
      // Euler: I α + ω × I ω, with α = J_ω q̈ + α_b
      Vector3 moment = euler_moment(b.inertia, b.angular_velocity, b.bias_angular_acceleration);
      for (unsigned a = 0; a < 3; ++a) inertia_force += b.angular_velocity_jacobian(a, j) * moment[a];
    }
    f[j] -= inertia_force;
  }
}

void add_kinetic_energy(const ex& T, const Symbols& s, GiNaC::matrix& M, std::vector<ex>& f) {
  if (T.is_zero()) return;
  std::size_t n = f.size();
  for (unsigned j = 0; j < n; ++j) {
    ex p = T.diff(s.velocities[j]);  // generalized momentum of T
    for (unsigned k = j; k < n; ++k) M(j, k) += p.diff(s.velocities[k]);
    ex rest = T.diff(s.coordinates[j]) - p.diff(s.time);
    for (unsigned k = 0; k < n; ++k) rest -= p.diff(s.coordinates[k]) * s.velocities[k];
    f[j] += rest;
  }
}

// T = ½ q'ᵀ M q' + b·q' + T0 (Hiller §3.5) from the finished mass matrix; M already holds
// the Hessian of [energy] kinetic, so only that energy's remaining (linear, constant) parts are added
ex kinetic_energy(const GiNaC::matrix& M, const Mechanics& mech, const Symbols& s) {
  std::size_t n = s.coordinates.size();
  ex T = mech.kinetic_at_rest;
  for (unsigned j = 0; j < n; ++j) {
    T += mech.kinetic_linear[j] * s.velocities[j] + M(j, j) * GiNaC::pow(s.velocities[j], 2) / 2;
    for (unsigned k = j + 1; k < n; ++k) T += M(j, k) * s.velocities[j] * s.velocities[k];
  }
  if (!mech.extra_kinetic_energy.is_zero()) {
    ex quadratic = 0;
    for (unsigned j = 0; j < n; ++j)
      for (unsigned k = 0; k < n; ++k)
        quadratic += mech.extra_kinetic_energy.diff(s.velocities[j]).diff(s.velocities[k]) * s.velocities[j] * s.velocities[k] / 2;
    T += mech.extra_kinetic_energy - quadratic;
  }
  return tidy(T, mech.motion);
}

// q'' by the articulated-body recursion for a tree of particles from articulated_crossover
// coordinates on, or where ModelChoice asks for it; a variant that is no longer a tree falls back
// to M = L D Lᵀ
void choose_forward_dynamics(const Model& model, const Mechanics& mech, const ParticleTree& tree, Equations& e) {
  if (model.method != "lagrange2" || model.forward_dynamics == ForwardDynamics::mass_matrix) return;
  if (!mech.tree_links.empty()) return add_joint_tree_accelerations(model, mech, e);
  if (model.forward_dynamics == ForwardDynamics::chosen && model.symbols.num_coordinates() < articulated_crossover) return;
  if (!tree.found()) return;
  derivation_stage("the articulated-body recursion");
  ArticulatedAccelerations solution = articulated_accelerations(model, mech, tree);
  std::size_t n = model.symbols.num_coordinates();
  ArticulatedForwardDynamics& articulated = e.dynamics.emplace<ArticulatedForwardDynamics>();
  for (std::size_t k = 0; k < n; ++k) articulated.acceleration_symbols.emplace_back(fmt::format("ddq{}", k));
  articulated.inverse_dynamics =
      articulated_inverse_dynamics(model, mech, tree, solution, articulated.acceleration_symbols, solution.intermediates);
  articulated.inverse_dynamics.forces = solution.forces;
  articulated.inverse_dynamics.accelerations_of_forces = solution.accelerations_of_forces;
  articulated.intermediates = std::move(solution.intermediates);
  articulated.accelerations = std::move(solution.accelerations);
}

}  // namespace

Equations derive_lagrange2(const Model& model, const Mechanics& mech) {
  const Symbols& s = model.symbols;
  std::size_t n = s.coordinates.size();
  GiNaC::matrix M(n, n);
  std::vector<ex> f(n, 0);
  derivation_stage("the bodies' terms of M and f");
  ParticleTree tree = find_particle_tree(model);
  std::optional<ParticleTreeTerms> tree_terms;
  if (tree.found()) {
    tree_terms = particle_tree_terms(model, tree);
    M = tree_terms->mass_matrix;
    f = tree_terms->inertia_forces;
  } else {
    if (mech.composite_mass_matrix) M = *mech.composite_mass_matrix;
    if (mech.tree_bias_forces) f = *mech.tree_bias_forces;
    else
      for (const BodyKinematics& b : mech.bodies) add_body(b, M, f, !mech.composite_mass_matrix);
    add_kinetic_energy(mech.extra_kinetic_energy, s, M, f);
  }
  // a tree's terms are simplified with its subtree masses as symbols, then collected in the masses
  auto simplified = [&](const ex& x) {
    ex t = tidy(x, mech.motion);
    return tree_terms ? collect_by_motion(t.subs(tree_terms->subtree_masses).expand(), mech.motion) : t;
  };
  derivation_stage("the simplified M and f");
  for (unsigned j = 0; j < n; ++j) {
    f[j] += mech.generalized_force[j] - mech.potential_gradient[j] -
            mech.dissipation.diff(s.velocities[j]);
    f[j] = simplified(f[j]);
    for (unsigned k = j; k < n; ++k) {
      M(j, k) = simplified(M(j, k));
      M(k, j) = M(j, k);
    }
  }
  Equations e;
  e.model_name = model.name;
  e.title = model.title;
  e.method = "lagrange2";
  e.source = model.source;
  e.symbols = s;
  e.degrees_of_freedom = n;
  e.intermediates = mech.intermediates;
  e.mass_matrix = M;
  e.forcing = f;
  derivation_stage("the kinetic energy from M");
  // recursive kinematics: T from the bodies' velocities, O(n) where ½ q'ᵀ M q' is O(n³)
  e.kinetic_energy = mech.intermediates.empty() ? kinetic_energy(M, mech, s) : kinetic_energy_of(mech);
  take_newton_euler_recursion(mech, e);
  e.coordinate_parents = mech.coordinate_parents;
  e.potential_energy = mech.potential_energy;
  e.dissipation = mech.dissipation;
  for (const NamedSymbolic& o : model.outputs) e.outputs.push_back({o.name, tidy(o.expression, mech.motion)});
  e.conserves_energy_without_inputs = conserves_energy_without_inputs(mech, s);
  choose_forward_dynamics(model, mech, tree, e);
  return e;
}

}  // namespace eomgen
