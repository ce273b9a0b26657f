/// @file A joint tree with its fixed links folded into the links they hang from. A link without a
/// joint moves with its parent, so its bodies belong to the nearest link above it that has a joint
/// (or to the root), in that link's coordinates, and the links below it hang from that link by
/// the composed constant turn and offset. The closed-form derivatives then do a moving link's work
/// once per link that moves: a URDF's sensor, camera and caster frames (TIAGo: 38 links, 12 of them
/// jointed) cost nothing at run time.
#pragma once

#include <vector>

#include "spatial/joint_tree_derivatives.hpp"

namespace eomgen {

/// The links that have a joint, and the root, in the same order; each fixed link's bodies moved
/// into its host's coordinates (centre T c + o, inertia T I Tᵀ for the fixed link's turn T and
/// offset o in the host).
std::vector<TreeLink> with_fixed_links_fused(const std::vector<TreeLink>& links);

}  // namespace eomgen
