/// @file A tree of point masses read off their positions: each particle hangs from another (or
/// from the ground) by a displacement that only its own coordinates move. The structure the
/// articulated-body recursion needs to solve for q'' link by link instead of through M.
#pragma once

#include <string>
#include <vector>

#include "model/model.hpp"

namespace eomgen {

/// Particle i's link to its parent: r_i = r_parent + displacement(q_J), with J = `coordinates`
/// (indices into the model's coordinates), which move no particle outside i's subtree.
struct ParticleJoint {
  int parent = -1;  // a particle index; −1: the ground
  std::vector<std::size_t> coordinates;
  Vector3 displacement;
};

struct ParticleTree {
  std::vector<ParticleJoint> joints;  // one per particle, in the model's order
  std::vector<std::size_t> order;     // the particles, each parent before its children
  std::string why_not;                // empty when the model is such a tree; else the reason, in words
  bool found() const { return why_not.empty(); }
  /// true when particle k is i or hangs below it
  bool below(std::size_t k, std::size_t i) const;
  /// The particle whose subtree's mass couples particles i and k (M_jl = m̄ S_j · S_l for their
  /// coordinates): the deeper of the two when one hangs below the other, −1 on different branches.
  int coupling(std::size_t i, std::size_t k) const;
  /// For each of the model's n coordinates: its particle and its place in that particle's joint.
  std::vector<std::pair<std::size_t, std::size_t>> joints_of_coordinates(std::size_t n) const;
};

/// A joint's motion in the model's symbols: the columns of S = ∂d/∂q_J (one per coordinate) and
/// c = d'' at q_J'' = 0, so that d'' = S q_J'' + c.
struct JointMotion {
  std::vector<Vector3> axes;
  Vector3 bias{0, 0, 0};
};
JointMotion joint_motion(const ParticleJoint& joint, const Symbols& s);

/// The tree of the model's particles, when every coordinate moves exactly one particle relative
/// to its parent and nothing else carries mass (no rigid bodies, no [energy] kinetic, no
/// constraints, positions free of t and u, expanded kinematics).
ParticleTree find_particle_tree(const Model& model);

}  // namespace eomgen
