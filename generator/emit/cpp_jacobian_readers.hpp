/// @file The entries of jacobian_state's lower block for a tree of particles: each load (a column of
/// ∂τ/∂x, emit/cpp_articulated_jacobian.hpp) has its effect at its own node (bias_above, own_response,
/// relative_below, computed before), and these passes carry it to every other coordinate by
/// "readers" propagated along the tree with the recursion's factors (across, accelerance, response,
/// gain): up a row's ancestors, down its subtree and across branch points. O(1) operations per entry.
#pragma once

#include <cstddef>
#include <string>

#include "emit/cpp_component_text.hpp"

namespace eomgen {

struct ReaderShape {
  std::size_t nodes = 0;
  std::size_t inverse_columns = 0;  // local columns of −M⁻¹ (array `inverse`), 0: none
  bool chain = false;               // node m hangs from m − 1
  bool identity = false;            // node m is coordinate m (no table `coordinate`)
  std::size_t uniform_loads = 0;    // loads per node when every node has as many (no table `first_load`)
};

/// The passes' C++ text, in the generated jacobian_state after the loads' effects.
std::string reader_passes(const ComponentText& k, const ReaderShape& shape);

}  // namespace eomgen
