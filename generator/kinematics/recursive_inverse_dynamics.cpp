/// @file The Newton–Euler recursion of recursive kinematics (recursive_kinematics.hpp): the
/// inverse dynamics τ(q, q', q'') of the bodies placed in frames, O(n) in the frames.
///
/// Forward, each frame's angular acceleration (body components) and its origin's acceleration
/// (inertial), q'' included: α_C = R_relᵀ α_P − ω_rel × R_relᵀ ω_P + W_rel q'' + α_rel and
/// a_C = a_P + R_P (α_P × o_rel + ω_P × (ω_P × o_rel) + 2 ω_P × ȯ_rel + ∂o_rel/∂q q'' + ö_rel).
/// Each body's force F = m (a − g) and moment N = R (I α + ω × I ω) (inertial, about its centre).
/// Backward, each frame's subtree force F_C = Σ F and moment about its origin
/// N_C = Σ (r − o_C) × F + N, a child's moment moved by (o_K − o_C) × F_K. A coordinate q_j that
/// frame C's placement contains moves the subtree by R_P ∂o_rel/∂q_j and turns it about o_C by
/// R_C ∂ω_rel/∂q̇_j, so τ_j = Σ over such frames of (R_P ∂o_rel/∂q_j)·F_C + (R_C ∂ω_rel/∂q̇_j)·N_C
/// (Hiller §3.9, the principle of virtual power applied link by link).
#include "kinematics/recursive_kinematics.hpp"
#include "kinematics/vector3.hpp"
#include "model/recursive_frames.hpp"

namespace eomgen {

using GiNaC::ex;


RecursiveKinematics::Acceleration RecursiveKinematics::child_acceleration(
    const FrameMotion& p, const Acceleration& pa, const GiNaC::matrix& relative,
    const std::vector<ElementaryRotation>& sequence, const Vector3& o, const std::vector<GiNaC::symbol>& ddq) const {
  const Symbols& s = symbols_;
  Vector3 w_rel = relative_angular_velocity(relative, sequence);
  Vector3 alpha_rel, o_rate, o_acc;
  for (unsigned a = 0; a < 3; ++a) {
    alpha_rel[a] = time_derivative(w_rel[a], s);
    o_rate[a] = time_derivative(o[a], s);
    o_acc[a] = time_derivative(o_rate[a], s);
    for (std::size_t j = 0; j < ddq.size(); ++j) {
      alpha_rel[a] += w_rel[a].diff(s.velocities[j]) * ddq[j];
      o_acc[a] += o[a].diff(s.coordinates[j]) * ddq[j];
    }
  }
  Acceleration c;
  Vector3 carried = times(relative, p.angular_velocity, true);
  c.angular = times(relative, pa.angular, true) - cross(w_rel, carried) + alpha_rel;
  Vector3 inner = cross(pa.angular, o) + cross(p.angular_velocity, cross(p.angular_velocity, o)) +
                  scaled(2, cross(p.angular_velocity, o_rate)) + o_acc;
  c.linear = pa.linear + times(p.rotation, inner);
  return c;
}

std::vector<ex> RecursiveKinematics::inverse_dynamics(const std::vector<GiNaC::symbol>& ddq, const Vector3& g,
                                                      std::vector<Intermediate>& out) {
  const Symbols& s = symbols_;
  std::size_t n = s.coordinates.size(), frames = frames_.size();
  auto named = [&](const std::string& who, const std::string& label, const Vector3& x) {
    return named_vector(out, who, label, x);
  };
  std::vector<Acceleration> acceleration(frames);
  const Acceleration at_rest;
  for (std::size_t i = 0; i < frames; ++i) {
    const FrameLink& link = model_.frame_links[i];
    bool root = link.parent < 0;
    Acceleration a = child_acceleration(root ? inertial_ : frames_[std::size_t(link.parent)],
                                        root ? at_rest : acceleration[std::size_t(link.parent)], link.relative_rotation,
                                        link.sequence, link.relative_origin, ddq);
    acceleration[i] = {named(link.name, "dalpha", a.angular), named(link.name, "da", a.linear)};
  }
  std::vector<Vector3> force(frames, Vector3{0, 0, 0}), moment(frames, Vector3{0, 0, 0});
  std::vector<GiNaC::exvector> tau(n);
  // the projections of a placement's own partial twist (translation in `to_inertial_of_shift`
  // components, rotation in `to_inertial_of_turn` components) on a force and a moment
  auto project = [&](const GiNaC::matrix& shift_to_inertial, const Vector3& origin, const GiNaC::matrix& turn_to_inertial,
                     const Vector3& w_rel, const Vector3& F, const Vector3& N) {
    for (std::size_t j = 0; j < n; ++j) {
      Vector3 shift{origin[0].diff(s.coordinates[j]), origin[1].diff(s.coordinates[j]), origin[2].diff(s.coordinates[j])};
      Vector3 turn{w_rel[0].diff(s.velocities[j]), w_rel[1].diff(s.velocities[j]), w_rel[2].diff(s.velocities[j])};
      ex power = dot(times(shift_to_inertial, shift), F) + dot(times(turn_to_inertial, turn), N);
      if (!power.is_zero()) tau[j].push_back(power);
    }
  };
  auto add_body = [&](const std::string& name, const ex& mass, const GiNaC::matrix* inertia, const FramePlacement& at) {
    std::size_t f = std::size_t(at.frame);
    const FrameMotion& frame = frames_[f];
    GiNaC::matrix relative = inertia ? at.relative : GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(3));
    Acceleration a = child_acceleration(frame, acceleration[f], relative, at.sequence, at.local, ddq);
    Vector3 F = named(name + ".cm", "F", scaled(mass, a.linear - g));
    Vector3 N{0, 0, 0};
    Vector3 w_rel = relative_angular_velocity(relative, at.sequence);
    if (inertia) {
      Vector3 w = times(relative, frame.angular_velocity, true) + w_rel;
      N = named(name + ".cm", "N", times(frame.rotation, times(relative, euler_moment(*inertia, w, a.angular))));
    }
    force[f] = force[f] + F;
    moment[f] = moment[f] + cross(times(frame.rotation, at.local), F) + N;
    // the body's own placement in its frame, when the coordinates move it there
    project(frame.rotation, at.local, frame.rotation.mul(relative), w_rel, F, N);
  };
  for (const Particle& p : model_.particles)
    if (p.placement.frame >= 0) add_body(p.name, p.mass, nullptr, p.placement);
  for (const RigidBody& b : model_.rigid_bodies)
    if (b.placement.frame >= 0) add_body(b.name, b.mass, &b.inertia, b.placement);
  for (std::size_t i = frames; i-- > 0;) {
    const FrameLink& link = model_.frame_links[i];
    Vector3 F = named(link.name, "F", force[i]), N = named(link.name, "N", moment[i]);
    const GiNaC::matrix& parent_rotation = link.parent < 0 ? inertial_.rotation : frames_[std::size_t(link.parent)].rotation;
    project(parent_rotation, link.relative_origin, frames_[i].rotation,
            relative_angular_velocity(link.relative_rotation, link.sequence), F, N);
    if (link.parent < 0) continue;
    std::size_t p = std::size_t(link.parent);
    force[p] = force[p] + F;
    moment[p] = moment[p] + N + cross(times(parent_rotation, link.relative_origin), F);
  }
  std::vector<ex> result;
  for (const GiNaC::exvector& terms : tau) result.push_back(ex(GiNaC::add(terms)).expand());
  return result;
}

}  // namespace eomgen
