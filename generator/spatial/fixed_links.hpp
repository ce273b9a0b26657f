/// @file Bodies moved between links of a joint tree: a fixed link's into the link it hangs from
/// (spatial/joint_tree_dynamics.cpp folds a link without a joint into its parent, so that the
/// recursions and the closed-form derivatives do a moving link's work once: a URDF's sensor,
/// camera and caster frames cost nothing at run time), and a link's bodies of known numbers as one.
#pragma once

#include <vector>

#include "spatial/joint_tree_derivatives.hpp"

namespace eomgen {

/// A body of a link turned by `turn` and placed at `offset` in another link's coordinates, in
/// those: centre T c + o, inertia T I Tᵀ.
TreeLink::Body body_in(const TreeLink::Body& body, const GiNaC::matrix& turn, const Vector3& offset);

/// Bodies of known numbers on one link as the one body they make (mass Σ m, centre Σ m c / Σ m,
/// inertia Σ J + m (|d|² 1 − d dᵀ) about it, d = c − the centre): the recursions' force and moment
/// per body are about 40 operations each. Bodies with a parameter among their numbers stay apart,
/// so that no quotient of parameters is formed on every call.
std::vector<TreeLink::Body> as_one_body(const std::vector<TreeLink::Body>& bodies);

}  // namespace eomgen
