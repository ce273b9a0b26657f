#include "kinematics/mechanics.hpp"

namespace eomgen {

using GiNaC::ex;

ex time_derivative(const ex& x, const Symbols& s) {
  ex d = x.diff(s.time);
  for (std::size_t k = 0; k < s.coordinates.size(); ++k) d += x.diff(s.coordinates[k]) * s.velocities[k];
  return d;
}

namespace {

MotionSymbols motion_symbols(const Symbols& s) {
  MotionSymbols m;
  m.symbols.insert(s.time);
  for (const auto& q : s.coordinates) m.symbols.insert(q);
  for (const auto& v : s.velocities) m.symbols.insert(v);
  for (const auto& u : s.inputs) m.symbols.insert(u);
  return m;
}

// J = ∂r/∂q (3 × n); v = J q̇ + ∂r/∂t; a − J q̈ = Σ ∂v/∂q_k q̇_k + ∂v/∂t
void translate(BodyKinematics& b, const Vector3& r, const Symbols& s) {
  std::size_t n = s.coordinates.size();
  b.velocity_jacobian = GiNaC::matrix(3, n);
  for (unsigned a = 0; a < 3; ++a) {
    for (unsigned j = 0; j < n; ++j) b.velocity_jacobian(a, j) = r[a].diff(s.coordinates[j]);
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

// ½ m v·v + ½ ω·I ω
ex kinetic_energy_of(const BodyKinematics& b, const MotionSymbols& motion) {
  ex T = 0;
  for (unsigned a = 0; a < 3; ++a) T += b.mass * b.velocity[a] * b.velocity[a] / 2;
  if (b.rotates)
    for (unsigned a = 0; a < 3; ++a)
      for (unsigned c = 0; c < 3; ++c) T += b.angular_velocity[a] * b.inertia(a, c) * b.angular_velocity[c] / 2;
  return tidy(T, motion);
}

ex gravity_potential(const ex& mass, const Vector3& r, const Vector3& g) {
  return -mass * (g[0] * r[0] + g[1] * r[1] + g[2] * r[2]);
}

// Q_j += F · ∂r_at/∂q_j (virtual work of a point force)
void add_point_force(std::vector<ex>& Q, const PointForce& f, const Symbols& s) {
  for (std::size_t j = 0; j < s.coordinates.size(); ++j)
    for (unsigned a = 0; a < 3; ++a) Q[j] += f.force[a] * f.at[a].diff(s.coordinates[j]);
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

}  // namespace

Mechanics compute_mechanics(const Model& model) {
  const Symbols& s = model.symbols;
  Mechanics m;
  m.motion = motion_symbols(s);
  ex T = 0, V = model.potential;
  for (const Particle& p : model.particles) {
    BodyKinematics b;
    b.name = p.name;
    b.mass = p.mass;
    translate(b, p.position, s);
    T += kinetic_energy_of(b, m.motion);
    V += gravity_potential(p.mass, p.position, model.gravity);
    m.bodies.push_back(b);
  }
  std::size_t first_rigid = m.bodies.size();
  for (const RigidBody& r : model.rigid_bodies) {
    BodyKinematics b;
    b.name = r.name;
    b.mass = r.mass;
    b.inertia = r.inertia;
    translate(b, r.center, s);
    rotate(b, r.rotation.sequence.empty() && !GiNaC::ex(r.rotation.matrix).is_equal(GiNaC::unit_matrix(3))
                  ? angular_velocity_of_matrix(r.rotation.matrix, s, m.motion)
                  : angular_velocity_of_sequence(r.rotation.sequence, s),
           s);
    T += kinetic_energy_of(b, m.motion);
    V += gravity_potential(r.mass, r.center, model.gravity);
    m.bodies.push_back(b);
  }
  m.extra_kinetic_energy = model.kinetic;
  m.kinetic_energy = tidy(T + model.kinetic, m.motion);
  m.potential_energy = tidy(V, m.motion);
  m.dissipation = tidy(model.dissipation, m.motion);
  m.generalized_force = model.generalized_force;
  for (const PointForce& f : model.point_forces) add_point_force(m.generalized_force, f, s);
  for (const BodyTorque& t : model.torques)
    add_torque(m.generalized_force, t, m.bodies[first_rigid + t.body], model.rigid_bodies[t.body]);
  for (ex& q : m.generalized_force) q = tidy(q, m.motion);
  // scleronomic: at rest (q' = 0) nothing moves, and T, V have no explicit t
  GiNaC::exmap at_rest;
  for (const auto& v : s.velocities) at_rest[v] = 0;
  m.scleronomic = !m.kinetic_energy.has(s.time) && !m.potential_energy.has(s.time);
  for (const BodyKinematics& b : m.bodies)
    for (unsigned a = 0; a < 3; ++a) {
      bool moves = !b.velocity[a].subs(at_rest).expand().is_zero();
      bool turns = b.rotates && !b.angular_velocity[a].subs(at_rest).expand().is_zero();
      m.scleronomic = m.scleronomic && !moves && !turns;
    }
  return m;
}

}  // namespace eomgen
