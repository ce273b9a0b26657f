/// @file The value of a constant expression a user types on the command line:
/// `--at theta=Pi`, `--set alpha=3*Pi/4`, `--at x=sqrt(2)/2`.
#pragma once

#include <optional>
#include <string>

namespace eomgen {

/// `text` read by GiNaC's parser with Pi as the only name (numbers, + − * / ^, parentheses and
/// the functions sin cos tan asin acos atan exp log sqrt abs), evaluated in double; nothing when
/// it is not a finite real constant.
std::optional<double> constant_value(const std::string& text);

}  // namespace eomgen
