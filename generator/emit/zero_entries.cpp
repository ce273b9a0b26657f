#include "emit/zero_entries.hpp"

#include <cctype>
#include <set>
#include <vector>

#include <fmt/format.h>

#include "emit/statement_order.hpp"

namespace eomgen {

namespace {

std::vector<std::string> lines_of(const std::string& body) {
  std::vector<std::string> lines;
  for (std::size_t at = 0; at < body.size();) {
    std::size_t end = body.find('\n', at);
    end = end == std::string::npos ? body.size() : end + 1;
    lines.push_back(body.substr(at, end - at));
    at = end;
  }
  return lines;
}

bool mentions(const std::string& line, const std::string& name) {
  for (std::size_t at = line.find(name); at != std::string::npos; at = line.find(name, at + 1))
    if ((at == 0 || !is_identifier_char(line[at - 1])) && (at + name.size() == line.size() || !is_identifier_char(line[at + name.size()])))
      return true;
  return false;
}

// `  X[k] = value;`: k and the value, or false
bool entry(const std::string& line, const std::string& array, std::size_t& index, std::string& value) {
  std::string head = "  " + array + "[";
  if (line.compare(0, head.size(), head) != 0) return false;
  std::size_t at = head.size(), digits = at;
  while (digits < line.size() && std::isdigit(static_cast<unsigned char>(line[digits]))) ++digits;
  if (digits == at || line.compare(digits, 4, "] = ") != 0) return false;
  std::size_t end = line.find_last_of(';');
  if (end == std::string::npos || end < digits + 4) return false;
  index = std::stoul(line.substr(at, digits - at));
  value = line.substr(digits + 4, end - digits - 4);
  return true;
}

// the lines of the array's zero entries when filling first changes nothing, with the array's
// length as far as its entries say; empty otherwise
std::vector<std::size_t> movable_zeros(const std::vector<std::string>& lines, const std::string& array, std::size_t& size) {
  std::vector<std::size_t> zeros, others;
  std::set<std::size_t> assigned;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    std::size_t index;
    std::string value;
    if (entry(lines[k], array, index, value)) {
      if (!assigned.insert(index).second) return {};
      size = std::max(size, index + 1);
      if (value == "T(0)") zeros.push_back(k);
    } else if (lines[k].rfind("  (void)", 0) != 0 && mentions(lines[k], array)) {
      others.push_back(k);
    }
  }
  if (zeros.size() <= entries_by_lines_up_to) return {};
  // a loop or a pointer before the last zero might write what the fill would then overwrite
  for (std::size_t k : others)
    if (k < zeros.back()) return {};
  return zeros;
}

// the names of the `T* name` parameters
std::vector<std::string> output_arrays(const std::string& signature) {
  std::vector<std::string> names;
  for (std::size_t at = signature.find("T* "); at != std::string::npos; at = signature.find("T* ", at + 3)) {
    if (at < 2 || (signature.compare(at - 1, 1, "(") != 0 && signature.compare(at - 2, 2, ", ") != 0)) continue;
    std::size_t end = at + 3;
    while (end < signature.size() && is_identifier_char(signature[end])) ++end;
    names.push_back(signature.substr(at + 3, end - at - 3));
  }
  return names;
}

}  // namespace

std::string with_zero_fills(const std::string& signature, const std::string& body) {
  std::vector<std::string> lines = lines_of(body);
  std::vector<bool> dropped(lines.size(), false);
  std::string fills;
  for (const std::string& array : output_arrays(signature)) {
    std::size_t size = 0;
    std::vector<std::size_t> zeros = movable_zeros(lines, array, size);
    if (zeros.empty()) continue;
    for (std::size_t k : zeros) dropped[k] = true;
    fills += fmt::format("  for (std::size_t i = 0; i < {}; ++i) {}[i] = T(0);\n", size, array);
  }
  if (fills.empty()) return body;
  std::size_t first = !lines.empty() && lines[0].rfind("  (void)", 0) == 0 ? 1 : 0;
  std::string out;
  for (std::size_t k = 0; k < first; ++k) out += lines[k];
  out += fills;
  for (std::size_t k = first; k < lines.size(); ++k)
    if (!dropped[k]) out += lines[k];
  return out;
}

}  // namespace eomgen
