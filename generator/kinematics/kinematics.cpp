#include "kinematics/mechanics.hpp"

#include <fmt/format.h>

#include "kinematics/recursive_kinematics.hpp"
#include "kinematics/vector3.hpp"
#include "spatial/joint_tree_dynamics.hpp"
#include "symbolic/gradient.hpp"

namespace eomgen {

using GiNaC::ex;

MotionSymbols motion_symbols(const Symbols& s) {
  MotionSymbols m;
  m.symbols.insert(s.time);
  for (const auto& q : s.coordinates) m.symbols.insert(q);
  for (const auto& v : s.velocities) m.symbols.insert(v);
  for (const auto& u : s.inputs) m.symbols.insert(u);
  return m;
}

bool conserves_energy_without_inputs(const Mechanics& mech, const Symbols& s) {
  GiNaC::exmap no_inputs;
  for (const auto& u : s.inputs) no_inputs[u] = 0;
  bool unforced = true;
  for (const ex& q : mech.generalized_force) unforced = unforced && q.subs(no_inputs).expand().is_zero();
  return unforced && mech.dissipation.is_zero() && mech.scleronomic;
}

ex kinetic_energy_of(const Mechanics& mech) {
  if (mech.tree_kinetic_energy) return tidy(mech.extra_kinetic_energy + *mech.tree_kinetic_energy, mech.motion);
  ex T = mech.extra_kinetic_energy;
  for (const BodyKinematics& b : mech.bodies) {
    for (unsigned a = 0; a < 3; ++a) T += b.mass * GiNaC::pow(b.velocity[a], 2) / 2;
    if (b.rotates)
      for (unsigned a = 0; a < 3; ++a)
        for (unsigned c = 0; c < 3; ++c) T += b.angular_velocity[a] * b.inertia(a, c) * b.angular_velocity[c] / 2;
  }
  return tidy(T, mech.motion);
}

bool quadratic_form_in(const ex& T, const std::vector<GiNaC::realsymbol>& velocities, const MotionSymbols& motion) {
  ex euler = -2 * T;
  for (const auto& v : velocities) euler += v * T.diff(v);
  return tidy(euler, motion).is_zero();
}

ex time_derivative(const ex& x, const Symbols& s) {
  std::vector<ex> variables(s.coordinates.begin(), s.coordinates.end());
  variables.push_back(s.time);
  std::vector<ex> d = gradient(x, variables);
  ex total = d.back();
  for (std::size_t k = 0; k < s.coordinates.size(); ++k) total += d[k] * s.velocities[k];
  return total;
}

namespace {

// J = ∂r/∂q (3 × n); v = J q̇ + ∂r/∂t; a − J q̈ = Σ ∂v/∂q_k q̇_k + ∂v/∂t
void translate(BodyKinematics& b, const Vector3& r, const Symbols& s) {
  std::size_t n = s.coordinates.size();
  b.position = r;
  b.velocity_jacobian = GiNaC::matrix(3, n);
  std::vector<ex> coordinates(s.coordinates.begin(), s.coordinates.end());
  for (unsigned a = 0; a < 3; ++a) {
    std::vector<ex> column = gradient(r[a], coordinates);
    for (unsigned j = 0; j < n; ++j) b.velocity_jacobian(a, j) = column[j];
    b.velocity[a] = time_derivative(r[a], s);
    b.bias_acceleration[a] = time_derivative(b.velocity[a], s);
  }
}

void rotate(BodyKinematics& b, const Vector3& omega, const Symbols& s) {
  std::size_t n = s.coordinates.size();
  b.rotates = true;
  b.angular_velocity = omega;
  b.angular_velocity_jacobian = GiNaC::matrix(3, n);
  for (unsigned a = 0; a < 3; ++a) {
    for (unsigned j = 0; j < n; ++j) b.angular_velocity_jacobian(a, j) = omega[a].diff(s.velocities[j]);
    b.bias_angular_acceleration[a] = time_derivative(omega[a], s);
  }
}

// the parts of T = ½ m v·v + ½ ω·I ω that explicit time dependence adds, with v = J q' + v0,
// ω = J_ω q' + ω0: b += m Jᵀ v0 + J_ωᵀ I ω0 and T0 += ½ m v0·v0 + ½ ω0·I ω0
void add_rheonomic_kinetic(const BodyKinematics& b, const Symbols& s, Mechanics& m) {
  GiNaC::exmap at_rest;
  for (const auto& v : s.velocities) at_rest[v] = 0;
  Vector3 v0, w0{0, 0, 0};
  for (unsigned a = 0; a < 3; ++a) {
    v0[a] = b.velocity[a].subs(at_rest);
    if (b.rotates) w0[a] = b.angular_velocity[a].subs(at_rest);
  }
  Vector3 Iw0{0, 0, 0};
  for (unsigned a = 0; a < 3; ++a)
    for (unsigned c = 0; c < 3; ++c) Iw0[a] += b.inertia(a, c) * w0[c];
  for (unsigned a = 0; a < 3; ++a) {
    m.kinetic_at_rest += b.mass * v0[a] * v0[a] / 2 + w0[a] * Iw0[a] / 2;
    for (unsigned j = 0; j < s.coordinates.size(); ++j) {
      m.kinetic_linear[j] += b.mass * b.velocity_jacobian(a, j) * v0[a];
      if (b.rotates) m.kinetic_linear[j] += b.angular_velocity_jacobian(a, j) * Iw0[a];
    }
  }
}

ex gravity_potential(const ex& mass, const Vector3& r, const Vector3& g) {
  return -mass * (g[0] * r[0] + g[1] * r[1] + g[2] * r[2]);
}

// Q_j += F · ∂r_at/∂q_j (virtual work of a point force)
void add_point_force(std::vector<ex>& Q, const PointForce& f, const Symbols& s, const RecursiveKinematics* frames) {
  for (unsigned a = 0; a < 3; ++a) {
    std::vector<ex> d;
    if (frames) d = frames->gradient(f.at[a]);
    for (std::size_t j = 0; j < s.coordinates.size(); ++j) Q[j] += f.force[a] * (frames ? d[j] : f.at[a].diff(s.coordinates[j]));
  }
}

// Q_j += M_B · ∂ω_B/∂q̇_j, with inertial torques turned into body components by Rᵀ
void add_torque(std::vector<ex>& Q, const BodyTorque& m, const BodyKinematics& body, const RigidBody& rigid) {
  Vector3 torque = m.torque;
  if (m.inertial_frame)
    for (unsigned a = 0; a < 3; ++a)
      torque[a] = rigid.rotation.matrix(0, a) * m.torque[0] + rigid.rotation.matrix(1, a) * m.torque[1] +
                  rigid.rotation.matrix(2, a) * m.torque[2];
  for (std::size_t j = 0; j < Q.size(); ++j)
    for (unsigned a = 0; a < 3; ++a) Q[j] += torque[a] * body.angular_velocity_jacobian(a, j);
}

// An [energy] kinetic T(q, q', t) beside ball or free joints: its Lagrange terms M_T q'' + g_T
// (Hiller §3.3) projected on the pseudo-velocities, Wᵀ(M_T q'' + g_T), with q' = W s and
// q'' = W s' + Ẇ s (a quaternion's rates ½ q ⊗ (0, ω), of Ẇ s = ½ q' ⊗ (0, ω)): the principle of
// virtual power, δq' = W δs, whose Wᵀ also annihilates the normal q of a quaternion's sphere, so that
// T may be written in the four rates (an armature's 2a|q'|² = ½ a|q|²|ω|²). Wᵀ M_T W joins the
// tree's M and −Wᵀ(g_T + M_T Ẇ s) its bias forces (the equations are then those of
// derive_joint_tree_appell)
void add_rate_kinetic_energy(Mechanics& m, const Model& model, const JointVelocities& v, const GiNaC::exmap& rates,
                             std::vector<ex>& tau) {
  const ex& T = model.kinetic;
  if (T.is_zero()) return;
  const Symbols& s = model.symbols;
  std::size_t n = s.num_coordinates();
  std::vector<ex> rate_of_rate(n, 0);  // Ẇ s, zero for a coordinate whose rate is a velocity
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = 0; k < n; ++k) rate_of_rate[i] += v.coordinate_rates[i].diff(s.coordinates[k]) * v.coordinate_rates[k];
  for (std::size_t j = 0; j < n; ++j) {
    ex p = T.diff(s.velocities[j]), g = p.diff(s.time) - T.diff(s.coordinates[j]), inertia = 0;
    for (std::size_t i = 0; i < n; ++i) {
      g += p.diff(s.coordinates[i]) * s.velocities[i];
      ex M_ji = p.diff(s.velocities[i]);
      if (M_ji.is_zero()) continue;
      g += M_ji * rate_of_rate[i];
      ex M_ji_in_velocities = M_ji.subs(rates);  // W's entries hold no rates
      for (const auto& [b, w_ib] : v.rate_matrix[i]) {
        inertia += M_ji * w_ib * m.acceleration_symbols[b];
        for (const auto& [a, w_ja] : v.rate_matrix[j])
          (*m.composite_mass_matrix)(unsigned(a), unsigned(b)) += w_ja * M_ji_in_velocities * w_ib;
      }
    }
    g = g.subs(rates);
    ex lagrange = inertia.subs(rates) + g;
    for (const auto& [c, w] : v.rate_matrix[j]) {
      tau[c] += w * lagrange;
      (*m.tree_bias_forces)[c] -= w * g;
    }
  }
}

// C, b and γ of a constraint whose expression holds frames' rotations and origins (points): a holonomic
// g gives C = ∂g/∂q through the frames, b = ∂g/∂t, γ = g̈ at q̈ = 0; a nonholonomic a·q̇ + b its
// coefficients and γ = its rate at q̈ = 0 (Hiller §2.2)
ConstraintTerms constraint_terms(const Constraint& c, const Symbols& s, const RecursiveKinematics& frames) {
  ConstraintTerms t;
  if (c.holonomic) {
    t.jacobian = frames.gradient(c.expression);
    t.bias = c.expression.diff(s.time);
    t.acceleration_bias = frames.rate_along_motion(c.expression, true);
    return t;
  }
  GiNaC::exmap at_rest;
  for (const auto& v : s.velocities) at_rest[v] = 0;
  for (const auto& v : s.velocities) t.jacobian.push_back(c.expression.diff(v));
  t.bias = c.expression.subs(at_rest);
  t.acceleration_bias = frames.rate_along_motion(c.expression, false);
  return t;
}

// τ = the bodies' τ + the applied part; a joint tree keeps the two apart, for its bodies' closed-form
// derivatives (Mechanics::bodies_gradient)
void add_applied(Mechanics& m, std::vector<ex> tau, const std::vector<ex>& applied,
                 const std::optional<JointTreeGradient>& bodies_gradient) {
  for (std::size_t j = 0; j < tau.size(); ++j) tau[j] += applied[j];
  m.inverse_dynamics = tau;
  if (!bodies_gradient) return;
  m.bodies_gradient = BodiesGradient{applied, *bodies_gradient};
}

// τ = M q'' − f with recursive kinematics (mechanics.hpp): the frames' Newton–Euler recursion, the
// bodies outside the frames projected on their Jacobians, then the applied forces, [energy] and R
void add_inverse_dynamics(Mechanics& m, const Model& model, RecursiveKinematics& frames, const std::vector<bool>& in_frame) {
  const Symbols& s = model.symbols;
  std::size_t n = s.coordinates.size();
  bool joint_tree = !why_not_a_joint_tree(model);
  JointVelocities velocities = joint_tree ? joint_velocities(model) : JointVelocities{};
  for (std::size_t k = 0; k < (velocities.pseudo ? velocities.symbols.size() : n); ++k)
    m.acceleration_symbols.emplace_back(fmt::format("ddq{}", k));
  const std::vector<GiNaC::symbol>& ddq = m.acceleration_symbols;
  std::vector<ex> tau;
  std::optional<JointTreeGradient> bodies_gradient;
  if (joint_tree) {
    // a tree of joints: M, the bias forces and τ by the recursions in the frames' own coordinates
    JointTreeDynamics tree = joint_tree_dynamics(model, velocities, ddq, m.intermediates, m.acceleration_intermediates);
    tau = tree.inverse_dynamics;
    m.composite_mass_matrix = tree.mass_matrix;
    m.tree_bias_forces = tree.bias_forces;
    m.coordinate_parents = tree.velocity_parents;
    if (velocities.pseudo) m.tree_velocities = velocities;
    m.tree_kinetic_energy = tree.kinetic_energy;
    m.potential_gradient = frames.gradient(model.potential);
    bodies_gradient = tree.gradient;
    m.tree_links = std::move(tree.links);
  } else {
    tau = frames.inverse_dynamics(ddq, model.gravity, m.acceleration_intermediates);
  }
  std::vector<GiNaC::exvector> terms(n);
  for (std::size_t i = 0; i < m.bodies.size(); ++i) {
    if (in_frame[i]) continue;
    const BodyKinematics& b = m.bodies[i];
    Vector3 acc = b.bias_acceleration, alpha = b.rotates ? b.bias_angular_acceleration : Vector3{0, 0, 0};
    for (std::size_t k = 0; k < n; ++k) {
      acc = acc + scaled(ddq[k], column(b.velocity_jacobian, unsigned(k)));
      if (b.rotates) alpha = alpha + scaled(ddq[k], column(b.angular_velocity_jacobian, unsigned(k)));
    }
    Vector3 F = scaled(b.mass, acc - model.gravity);
    Vector3 N = b.rotates ? euler_moment(b.inertia, b.angular_velocity, alpha) : Vector3{0, 0, 0};
    for (std::size_t j = 0; j < n; ++j) {
      terms[j].push_back(dot(column(b.velocity_jacobian, unsigned(j)), F));
      if (b.rotates) terms[j].push_back(dot(column(b.angular_velocity_jacobian, unsigned(j)), N));
    }
  }
  std::vector<ex> potential = frames.gradient(model.potential);
  if (velocities.pseudo) {
    // the applied forces along the pseudo-velocities, Wᵀ(∂V/∂q − Q + ∂R/∂q') with q' = W s (Hiller §4.3)
    GiNaC::exmap rates;
    for (std::size_t j = 0; j < n; ++j) rates[s.velocities[j]] = velocities.coordinate_rates[j];
    std::vector<ex> applied(tau.size(), 0);
    add_rate_kinetic_energy(m, model, velocities, rates, applied);
    for (std::size_t j = 0; j < n; ++j) {
      ex force = (potential[j] - m.generalized_force[j] + m.dissipation.diff(s.velocities[j])).subs(rates);
      for (const auto& [c, w] : velocities.rate_matrix[j]) applied[c] += w * force;
    }
    add_applied(m, tau, applied, bodies_gradient);
    return;
  }
  std::vector<ex> applied(n);
  for (std::size_t j = 0; j < n; ++j) {
    applied[j] = GiNaC::add(terms[j]) + potential[j] - m.generalized_force[j] + m.dissipation.diff(s.velocities[j]);
    // an [energy] kinetic: d/dt ∂T/∂q'_j − ∂T/∂q_j
    if (model.kinetic.is_zero()) continue;
    ex p = model.kinetic.diff(s.velocities[j]);
    applied[j] += p.diff(s.time) - model.kinetic.diff(s.coordinates[j]);
    for (std::size_t k = 0; k < n; ++k) applied[j] += p.diff(s.coordinates[k]) * s.velocities[k] + p.diff(s.velocities[k]) * ddq[k];
  }
  add_applied(m, tau, applied, bodies_gradient);
}

}  // namespace

Mechanics compute_mechanics(const Model& model) {
  const Symbols& s = model.symbols;
  Mechanics m;
  m.motion = motion_symbols(s);
  m.kinetic_linear.assign(s.coordinates.size(), 0);
  m.kinetic_at_rest = 0;
  std::optional<RecursiveKinematics> frames;
  if (model.recursive_kinematics) {
    m.intermediates = model.intermediates;
    frames.emplace(model, m.intermediates);
  }
  ex V = model.potential;
  std::vector<bool> in_frame;  // the bodies placed by the recursion
  for (const Particle& p : model.particles) {
    in_frame.push_back(frames && p.placement.frame >= 0);
    BodyKinematics b;
    if (in_frame.back()) b = frames->body(p.name, p.mass, p.position, p.placement, false);
    else {
      b.name = p.name;
      b.mass = p.mass;
      translate(b, p.position, s);
      add_rheonomic_kinetic(b, s, m);
    }
    V += gravity_potential(p.mass, p.position, model.gravity);
    m.bodies.push_back(b);
  }
  std::size_t first_rigid = m.bodies.size();
  for (const RigidBody& r : model.rigid_bodies) {
    in_frame.push_back(frames && r.placement.frame >= 0);
    if (in_frame.back()) {
      m.bodies.push_back(frames->body(r.name, r.mass, r.center, r.placement, true));
      m.bodies.back().inertia = r.inertia;
      V += gravity_potential(r.mass, r.center, model.gravity);
      continue;
    }
    BodyKinematics b;
    b.name = r.name;
    b.mass = r.mass;
    b.inertia = r.inertia;
    translate(b, r.center, s);
    rotate(b, r.rotation.sequence.empty() && !GiNaC::ex(r.rotation.matrix).is_equal(GiNaC::unit_matrix(3))
                  ? angular_velocity_of_matrix(r.rotation.matrix, s, m.motion)
                  : angular_velocity_of_sequence(r.rotation.sequence, s),
           s);
    add_rheonomic_kinetic(b, s, m);
    V += gravity_potential(r.mass, r.center, model.gravity);
    m.bodies.push_back(b);
  }
  m.extra_kinetic_energy = model.kinetic;
  for (const Intermediate& i : m.intermediates) m.motion.symbols.insert(i.symbol);
  for (ex& b : m.kinetic_linear) b = tidy(b, m.motion);
  m.kinetic_at_rest = tidy(m.kinetic_at_rest, m.motion);
  m.potential_energy = tidy(V, m.motion);
  m.dissipation = tidy(model.dissipation, m.motion);
  m.generalized_force = model.generalized_force;
  for (const PointForce& f : model.point_forces) add_point_force(m.generalized_force, f, s, frames ? &*frames : nullptr);
  for (const BodyTorque& t : model.torques)
    add_torque(m.generalized_force, t, m.bodies[first_rigid + t.body], model.rigid_bodies[t.body]);
  for (ex& q : m.generalized_force) q = tidy(q, m.motion);
  if (frames) m.potential_gradient = frames->gradient(m.potential_energy);
  if (frames) add_inverse_dynamics(m, model, *frames, in_frame);
  for (const Intermediate& i : m.intermediates) m.motion.symbols.insert(i.symbol);  // a joint tree's, too
  if (frames && !m.composite_mass_matrix) m.composite_mass_matrix = frames->composite_mass_matrix(m.intermediates);
  if (frames)
    for (const Constraint& c : model.constraints) m.constraint_terms.push_back(constraint_terms(c, s, *frames));
  if (!frames)
    for (const auto& q : s.coordinates) m.potential_gradient.push_back(m.potential_energy.diff(q));
  // scleronomic: at rest (q' = 0) nothing moves, and T, V have no explicit t
  GiNaC::exmap at_rest;
  for (const auto& v : s.velocities) at_rest[v] = 0;
  // An [energy] kinetic written in a moving frame (a rotating orbit's Clohessy–Wiltshire T) has terms
  // linear in and free of the velocities: the frame's drive does work, and T + V is not conserved
  // although nothing depends on t (only h = T2 − T0 + V is, Hiller §3.6)
  m.scleronomic = !m.extra_kinetic_energy.has(s.time) && !m.potential_energy.has(s.time) &&
                  quadratic_form_in(m.extra_kinetic_energy, s.velocities, m.motion);
  // (frames placed by the coordinates alone do not move at rest: their ω is a symbol here)
  for (std::size_t i = 0; i < m.bodies.size(); ++i)
    for (unsigned a = 0; a < 3 && !in_frame[i]; ++a) {
      const BodyKinematics& b = m.bodies[i];
      bool moves = !b.velocity[a].subs(at_rest).expand().is_zero();
      bool turns = b.rotates && !b.angular_velocity[a].subs(at_rest).expand().is_zero();
      m.scleronomic = m.scleronomic && !moves && !turns;
    }
  return m;
}

}  // namespace eomgen
