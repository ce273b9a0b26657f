/// @file Whether a tree of joints moves in one plane: every hinge about one world direction n
/// and every slide across it (a planar walker, hopper or swimmer). Its world twists, velocities
/// and accelerations then keep three of their six components at zero whatever q, so that the
/// straight-line closed form of ∂τ/∂(q, q') (joint_tree_derivatives.hpp) folds most of its
/// operations, and stays faster than the loops for many more pairs of joints.
#pragma once

#include <vector>

#include "spatial/joint_tree_derivatives.hpp"

namespace eomgen {

/// Whether `links` (parents first) are hinges and slides, one velocity each, that move in one
/// plane: judged at two arbitrary sets of values of every symbol in the links' turns and
/// columns (coordinates and parameters), so that an axis that is parallel only by accident of
/// a value does not count.
bool moves_in_a_plane(const std::vector<TreeLink>& links);

}  // namespace eomgen
