/// @file The articulated-body algorithm's q'' for the rhs of a joint tree
/// (spatial/joint_tree_forward_dynamics.hpp), under Lagrange II or, with ball and free joints,
/// Appell's equations in the tree's velocities.
#pragma once

#include "derive/equations.hpp"
#include "kinematics/mechanics.hpp"

namespace eomgen {

/// Sets e.joint_tree_accelerations where `--forward-dynamics articulated` asks for it or, left to
/// eomgen, where the tree is deep enough for it to pay (the header's writer then weighs its
/// operations against M's), with Q the applied part of the generalized forces (the bodies' τ =
/// −applied) but for a joint inertia a_j q''_j in it. Nothing for a model the algorithm does not
/// solve (why_not_articulated_joint_tree) or asked for M.
void add_joint_tree_accelerations(const Model& model, const Mechanics& mech, Equations& e);

}  // namespace eomgen
