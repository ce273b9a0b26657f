/// @file Which form a joint tree's gradient takes in the header (spatial/joint_tree_derivatives.hpp):
/// straight-line code, which folds the tree's constant axes and turns, or loops over the links,
/// whose code does not grow with the pairs of a joint and one at or above it. The cuts below are
/// measured (jacobian_state against the loops, the headers' sizes and build times); each constant
/// says where.
#pragma once

#include <vector>

#include "spatial/joint_tree_derivatives.hpp"

namespace eomgen {

/// Whether the tree is past the measured cut of velocities and pairs (in a plane, with ball joints
/// below its root, or neither) beyond which straight-line code grows longer than the loops.
bool beyond_straight_line_cut(const std::vector<TreeLink>& links, std::size_t velocities);

/// Whether such a tree is small enough that its straight-line gradient is worth forming and counting.
bool worth_counting_straight_line(const std::vector<TreeLink>& links);

/// Whether a straight-line gradient of this many operations (symbolic/expression_cost.hpp) is kept
/// beyond the cut.
bool short_enough_for_straight_line(long operations);

}  // namespace eomgen
