/// @file The frame a tree's straight-line gradient is written in: the world's, or the axes of a
/// link about its root's origin (spatial/joint_tree_derivatives.hpp, gradient_in), whichever takes
/// the fewest operations once common subexpressions are shared. Every entry of the gradient is the
/// same in each; near the chosen link the turns fold.
#pragma once

#include <cstddef>
#include <vector>

#include <ginac/ginac.h>

#include "spatial/joint_tree_derivatives.hpp"

namespace eomgen {

/// The closed form as expressions, its quantities appended to `out`, in the frame where it takes the
/// fewest operations: the world's, or one of the links' up to three joints below a root (at most
/// eight), the world's where they tie.
InverseDynamicsGradient written_out_gradient(const std::vector<TreeLink>& links, const Vector3& gravity,
                                             const std::vector<GiNaC::ex>& ddq, std::size_t velocities, std::size_t coordinates,
                                             std::vector<Intermediate>& out);

}  // namespace eomgen
