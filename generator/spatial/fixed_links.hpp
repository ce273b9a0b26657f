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

/// A body of a link turned by `turn` and placed at `offset` in another link's coordinates, in
/// those: centre T c + o, inertia T I Tᵀ.
TreeLink::Body body_in(const TreeLink::Body& body, const GiNaC::matrix& turn, const Vector3& offset);

/// Bodies of known numbers on one link as the one body they make (mass Σ m, centre Σ m c / Σ m,
/// inertia Σ J + m (|d|² 1 − d dᵀ) about it, d = c − the centre): the recursions' force and moment
/// per body are about 40 operations each. Bodies with a parameter among their numbers stay apart,
/// so that no quotient of parameters is formed on every call.
std::vector<TreeLink::Body> as_one_body(const std::vector<TreeLink::Body>& bodies);

}  // namespace eomgen
