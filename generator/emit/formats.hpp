/// @file Output formats of `eomgen derive`; each is one file with the same signature.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "derive/equations.hpp"

namespace eomgen {

using EquationFormat = std::string (*)(const Equations&);

/// One expression per line, named (M[0][1] = …), in a fixed order: the regression baseline.
std::string emit_canonical_text(const Equations& equations);
/// The equations typeset, Greek names as Greek letters.
std::string emit_latex(const Equations& equations);
/// The stable JSON interface documented in generator/README.md ("Output formats").
std::string emit_json(const Equations& equations);

const std::vector<std::string>& equation_format_names();
std::optional<EquationFormat> find_equation_format(const std::string& name);

/// A JSON string literal of s, quotes and escapes included.
std::string json_quoted(const std::string& s);

/// Shortest text that reads back as the same double.
std::string format_number(double value);

}  // namespace eomgen
