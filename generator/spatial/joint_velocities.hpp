/// @file The velocities of a tree of joints, in the coordinates' order: q' of a revolute or prismatic
/// joint's coordinate and of a free joint's position, and the three components of the angular
/// velocity ω of a ball or free joint in place of its quaternion's four rates (MJCF's qvel). With a
/// ball or free joint they are pseudo-velocities s (Hiller §4.4): q' = W(q)·s, with the quaternion's
/// q' = ½ q ⊗ (0, ω), and s = Y(q)·q' with ω = 2 vec(q* ⊗ q')/|q|².
#pragma once

#include <utility>
#include <vector>

#include <ginac/ginac.h>

#include "model/model.hpp"

namespace eomgen {

struct JointVelocities {
  std::vector<GiNaC::realsymbol> symbols;    // s: the model's der(q), or a joint's ω components
  std::vector<GiNaC::ex> coordinate_rates;   // q' = W(q) s, one per coordinate
  std::vector<NamedSymbolic> definitions;    // s = Y(q) q', one per velocity
  std::vector<int> of_coordinate;            // the velocity that is q', or −1 (a quaternion's)
  /// W = ∂q'/∂s row by row, its nonzero entries (velocity, W_jc): what projects a coordinate's
  /// generalized force onto the velocities, Π = Wᵀ Q
  std::vector<std::vector<std::pair<std::size_t, GiNaC::ex>>> rate_matrix;
  bool pseudo = false;                       // some are angular velocities
};

/// Whether a frame has a ball or free joint.
bool has_spherical_joints(const Model& model);

/// The velocities above; for a model without ball and free joints, its der(q).
JointVelocities joint_velocities(const Model& model);

}  // namespace eomgen
