#include "model/symbols.hpp"

#include <algorithm>
#include <cctype>

namespace eomgen {

std::vector<std::string> Symbols::all_names() const {
  std::vector<std::string> names{"t", "Pi"};
  for (const auto& [name, info] : by_name) names.push_back(name);
  return names;
}

GiNaC::exmap Symbols::default_parameter_values() const {
  GiNaC::exmap values;
  for (std::size_t i = 0; i < parameters.size(); ++i)
    values[parameters[i]] = GiNaC::numeric(parameter_defaults[i]);
  return values;
}

void Symbols::remove_coordinate(std::size_t i) {
  auto erase = [i](auto& v) { v.erase(v.begin() + static_cast<std::ptrdiff_t>(i)); };
  by_name.erase(coordinate_names[i]);
  erase(coordinate_names), erase(coordinates), erase(velocities), erase(initial_coordinates), erase(initial_velocities),
      erase(initial_coordinate_expressions), erase(initial_rate_expressions);
  for (auto& [name, info] : by_name)
    if (info.kind == SymbolKind::coordinate && info.index > i) --info.index;
}

bool is_reserved_name(const std::string& name) {
  static const std::vector<std::string> reserved = {
      "t", "der", "Pi", "sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sinh", "cosh",
      "tanh", "exp", "log", "sqrt", "abs", "sign", "clamp", "below", "rotation_angle", "atan_ratio", "rot_x", "rot_y", "rot_z", "euler313", "cardan123"};
  return std::find(reserved.begin(), reserved.end(), name) != reserved.end();
}

bool is_identifier(const std::string& name) {
  if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0]))) return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

bool is_cpp_identifier(const std::string& name) {
  static const std::vector<std::string> keywords = {
      "alignas", "alignof", "and", "and_eq", "asm", "auto", "bitand", "bitor", "bool", "break",
      "case", "catch", "char", "char8_t", "char16_t", "char32_t", "class", "compl", "concept",
      "const", "consteval", "constexpr", "constinit", "const_cast", "continue", "co_await",
      "co_return", "co_yield", "decltype", "default", "delete", "do", "double", "dynamic_cast",
      "else", "enum", "explicit", "export", "extern", "false", "float", "for", "friend", "goto",
      "if", "inline", "int", "long", "mutable", "namespace", "new", "noexcept", "not", "not_eq",
      "nullptr", "operator", "or", "or_eq", "private", "protected", "public", "register",
      "reinterpret_cast", "requires", "return", "short", "signed", "sizeof", "static",
      "static_assert", "static_cast", "struct", "switch", "template", "this", "thread_local",
      "throw", "true", "try", "typedef", "typeid", "typename", "union", "unsigned", "using",
      "virtual", "void", "volatile", "wchar_t", "while", "xor", "xor_eq"};
  if (!is_identifier(name)) return false;
  if (name.find("__") != std::string::npos || (name.size() > 1 && name[0] == '_' && std::isupper(static_cast<unsigned char>(name[1]))))
    return false;
  return std::find(keywords.begin(), keywords.end(), name) == keywords.end();
}

}  // namespace eomgen
