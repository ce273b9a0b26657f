/// @file The order of a generated function's statements: each value computed just before it is
/// first needed, so that few values are alive at once.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace eomgen {

/// `statements` (lines of C++) with every run of plain statements, `const T name = …;` and
/// `array[k] = …;`, put in the order in which the outputs need them: the array writes in the order
/// in which their operands become available, each preceded by what it needs and is not yet
/// written. Other lines (calls, loops, declarations) stay where they are and bound the runs. The
/// values and the operations are unchanged, only their order; the result depends on the text alone.
/// A run shorter than `shortest_reordered` statements keeps the order it was written in; 0 orders
/// every run, and without it the cut is the one measured in statement_order.cpp.
std::string in_order_of_use(const std::string& statements, std::size_t shortest_reordered);
std::string in_order_of_use(const std::string& statements);

inline bool is_identifier_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

/// Calls visit(name) for each identifier in text[from, to) that does not start with a digit.
template <class Visit>
void for_each_identifier(std::string_view text, std::size_t from, std::size_t to, Visit visit) {
  for (std::size_t i = from; i < to;) {
    if (!is_identifier_char(text[i])) {
      ++i;
      continue;
    }
    std::size_t end = i;
    while (end < to && is_identifier_char(text[end])) ++end;
    if (text[i] < '0' || text[i] > '9') visit(text.substr(i, end - i));
    i = end;
  }
}

}  // namespace eomgen
