/// @file The generated header's summary lines after its title: which equations it holds, its
/// state, and how its functions compute them (the dynamics form, the articulated-body rhs, M and f
/// by loops).
#pragma once

#include <string>

#include "derive/equations.hpp"

namespace eomgen {

/// The summary's text, lines after the first joined by "\n// "; `functions` is the header's code,
/// searched for what it calls.
std::string header_summary(const Equations& e, const std::string& functions);

}  // namespace eomgen
