/// @file The self-contained C++ header of a model (DESIGN.md's contract).
#pragma once

#include <string>

#include "derive/equations.hpp"

namespace eomgen {

/// One header, namespaced eomgen::models::NAME, needing only the C++17 standard library.
std::string emit_cpp_header(const Equations& equations);

}  // namespace eomgen
