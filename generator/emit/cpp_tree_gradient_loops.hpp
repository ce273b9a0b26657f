/// @file The closed-form ∂τ/∂(q, q') of a long tree whose joints turn with their links (hinges,
/// slides, ball joints) as loops over its links (spatial/joint_tree_derivatives.hpp, TreeLinkTables): straight-line, a 21-joint tree's gradient
/// was most of its megabyte of header, and grows with the pairs of joints. The per-link inputs are
/// straight-line code, specialized as the rest of the header (constant turns folded, the axes'
/// zeros dropped); the world-frame recursion and the pairs, dense in any case, are one template,
/// written once in the header that needs it.
#pragma once

#include <string>

#include "derive/equations.hpp"
#include "emit/cpp_body_writer.hpp"

namespace eomgen {

/// detail::tree_gradient_pass, its six-vector helpers and detail::tree_tables, and with
/// `with_mass_matrix_and_forcing` detail::tree_loops_mass_matrix_and_forcing; "" unless e has the loops.
std::string tree_gradient_loops_function(const Equations& e, bool with_mass_matrix_and_forcing);

/// Declares `detail::tree_link_tables<L, Columns, Directions, T> tree` and fills them by detail::tree_tables, and its
/// root joint's motion at the accelerations ddq (the caller has t, x, ddq, u and p).
void call_tree_tables(BodyWriter& w, const Equations& e);
/// The root joint's motion at the accelerations ddq again, when the tree has one.
void call_root_motion(BodyWriter& w, const Equations& e);

/// The tree's tables and the call that adds the bodies' M and f at q'' = 0 into M and f.
void call_tree_mass_matrix_and_forcing(BodyWriter& w, const Equations& e);

/// The tree's tables and the call that adds the bodies' part of ∂τ/∂(q, q') into F (row width W).
void call_tree_gradient_loops(BodyWriter& w, const Equations& e, std::size_t coordinates, std::size_t width);

}  // namespace eomgen
