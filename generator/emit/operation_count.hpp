/// @file The cost of a generated function, counted in its text: arithmetic operators, one
/// operation each, elementary function calls (sin, sqrt, …, and each sine or cosine taken from
/// detail::sin_cos), ten each, and the dense LDLᵀ factorization and
/// solves it calls (n³/6 + n² and 2n² multiply-adds). A measure that does not depend on the
/// machine, for comparing models of one system (eomgen scene).
#pragma once

#include <string>

namespace eomgen {

/// Operations in the body of `function` (e.g. "rhs", "jacobian_state") of a generated header
/// whose mass matrix is `n` × `n`; 0 when the header has no such function.
long count_operations(const std::string& header, const std::string& function, std::size_t n);

}  // namespace eomgen
