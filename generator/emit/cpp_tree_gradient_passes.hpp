/// @file The two forms of the header's pass over a long tree's links (detail::tree_gradient_pass,
/// emit/cpp_tree_gradient_loops.hpp): for a tree of hinges and slides, one column per link, and for a
/// tree with links of several columns (ball joints below its root), their columns and directions in
/// loops. Two texts, not one with the first a case of the second: written as loops over one column,
/// the 21-joint tree's jacobian_state took 8 % longer (6.27 µs against 5.77, g++ -O2, one core).
#pragma once

namespace eomgen {

/// detail::tree_gradient_pass for tables of one column and one direction per link
const char* one_column_gradient_pass();

/// detail::tree_gradient_pass for tables of several columns and directions per link
const char* several_columns_gradient_pass();

}  // namespace eomgen
