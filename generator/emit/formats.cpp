#include "emit/formats.hpp"

#include <fmt/format.h>

namespace eomgen {

const std::vector<std::string>& equation_format_names() {
  static const std::vector<std::string> names = {"text", "latex", "json"};
  return names;
}

std::optional<EquationFormat> find_equation_format(const std::string& name) {
  if (name == "text") return &emit_canonical_text;
  if (name == "latex") return &emit_latex;
  if (name == "json") return &emit_json;
  return std::nullopt;
}

std::string format_number(double value) { return fmt::format("{}", value + 0.0); }  // + 0.0: no "-0"

}  // namespace eomgen
