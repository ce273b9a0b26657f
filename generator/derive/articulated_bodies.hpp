/// @file Forward dynamics of a tree of point masses by the articulated-body recursion
/// (Featherstone's, for particles: 3×3 articulated masses where rigid bodies need 6×6
/// inertias). q'' in O(n) operations, where forming M and factoring it takes O(n³).
#pragma once

#include <vector>

#include "kinematics/mechanics.hpp"
#include "kinematics/particle_tree.hpp"

namespace eomgen {

/// A particle's motion relative to its parent, d'' = S q_J'' + c: S and c in the recursion's
/// quantities, and the same in the model's symbols (to be differentiated).
struct RelativeMotion {
  std::vector<Vector3> axes;  // the columns of S = ∂d/∂q_J, one per coordinate of the joint
  Vector3 bias{0, 0, 0};      // c = d'' at q_J'' = 0
  std::vector<Vector3> axis_expressions;
  Vector3 bias_expression{0, 0, 0};
};

struct ArticulatedAccelerations {
  /// the recursion's quantities, each defined in the model's symbols and earlier ones
  std::vector<Intermediate> intermediates;
  std::vector<GiNaC::ex> accelerations;  // q'', one per coordinate
  std::vector<RelativeMotion> motions;   // one per particle
  /// q'' = M⁻¹ b for generalized forces b given as the symbols `forces`, by the same recursion
  /// without gravity, velocities and other forces: O(n) operations per b where L D Lᵀ takes O(n²)
  std::vector<GiNaC::symbol> forces;
  std::vector<GiNaC::ex> accelerations_of_forces;
};

/// The generalized force on coordinate j besides gravity and inertia: applied forces, [energy]
/// potential and dissipation.
GiNaC::ex applied_generalized_force(const Model& model, const Mechanics& mechanics, std::size_t j);

/// Σ_{j in subtree(i)} (m_j a_j − m_j g) = IA_i a_i + pA_i, built from the leaves to the root
/// with each joint's equation S_iᵀ f_i = Q_i (Q: the generalized forces other than gravity and
/// inertia), then a_i = a_parent + c_i + S_i q_i'' from the root to the leaves.
ArticulatedAccelerations articulated_accelerations(const Model& model, const Mechanics& mechanics,
                                                   const ParticleTree& tree);

}  // namespace eomgen
