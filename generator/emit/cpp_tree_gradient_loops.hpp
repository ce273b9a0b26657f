/// @file The closed-form ∂τ/∂(q, q') of a long tree of hinges and slides as loops over its links
/// (spatial/joint_tree_derivatives.hpp, HingeTreeLinks): straight-line, a 21-joint tree's gradient
/// was most of its megabyte of header, and grows with the pairs of joints. The per-link inputs are
/// straight-line code, specialized as the rest of the header (constant turns folded, the axes'
/// zeros dropped); the world-frame recursion and the pairs, dense in any case, are one template,
/// written once in the header that needs it.
#pragma once

#include <string>

#include "derive/equations.hpp"
#include "emit/cpp_body_writer.hpp"

namespace eomgen {

/// detail::hinge_tree_gradient and its six-vector helpers; "" unless e has the loops.
std::string tree_gradient_loops_function(const Equations& e);

/// The links' inputs as local arrays and the call that adds the bodies' part into F (row width W).
void call_tree_gradient_loops(BodyWriter& w, const HingeTreeLinks& links, std::size_t coordinates, std::size_t width);

}  // namespace eomgen
