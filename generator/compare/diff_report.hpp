/// @file The report of `eomgen diff`: readable text (what differs first, each entry with
/// both expressions and the size of the difference; identical entries only counted; a
/// robot's tree quantities that differ, by name), or one JSON object.
#pragma once

#include <string>

#include "compare/equation_diff.hpp"

namespace eomgen {

std::string diff_text(const EquationDiff& diff);
std::string diff_json(const EquationDiff& diff);

}  // namespace eomgen
