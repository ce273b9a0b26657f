#include "parse/toml_reader.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace eomgen::toml_reader {

std::string type_name(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a number";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::date:
    case toml::node_type::time:
    case toml::node_type::date_time: return "a date or time";
    default: return "nothing";
  }
}

SourceLocation Reader::at(const toml::source_region& region) const {
  return {path_, static_cast<int>(region.begin.line), static_cast<int>(region.begin.column)};
}

std::vector<Entry> Reader::entries(const toml::table& table) const {
  std::vector<Entry> out;
  for (auto&& [k, v] : table) out.push_back({std::string(k.str()), &v, at(k.source())});
  std::stable_sort(out.begin(), out.end(), [](const Entry& a, const Entry& b) {
    return std::tie(a.where.line, a.where.column) < std::tie(b.where.line, b.where.column);
  });
  return out;
}

void Reader::check_keys(const toml::table& table, const std::string& key,
                        const std::vector<std::string>& allowed) {
  for (const Entry& e : entries(table)) {
    if (std::find(allowed.begin(), allowed.end(), e.name) != allowed.end()) continue;
    std::string where = key.empty() ? e.name : key + "." + e.name;
    error(e.where, where, fmt::format("unknown key '{}'", e.name), suggest(e.name, allowed, "keys"));
  }
}

const toml::table* Reader::table(const toml::node& node, const std::string& key, const char* what) {
  if (const toml::table* t = node.as_table()) return t;
  error(at(node), key, fmt::format("expected a table ({}), got {}", what, type_name(node)));
  return nullptr;
}

const toml::array* Reader::array(const toml::node& node, const std::string& key, const char* what) {
  if (const toml::array* a = node.as_array()) return a;
  error(at(node), key, fmt::format("expected an array ({}), got {}", what, type_name(node)));
  return nullptr;
}

bool Reader::string(const toml::node& node, const std::string& key, std::string& out) {
  if (const auto* s = node.as_string()) {
    out = s->get();
    return true;
  }
  error(at(node), key, fmt::format("expected a string, got {}", type_name(node)));
  return false;
}

bool Reader::boolean(const toml::node& node, const std::string& key, bool& out) {
  if (const auto* b = node.as_boolean()) {
    out = b->get();
    return true;
  }
  error(at(node), key, fmt::format("expected true or false, got {}", type_name(node)),
        node.is_string() ? "write true or false without quotes" : "");
  return false;
}

bool Reader::number(const toml::node& node, const std::string& key, double& out) {
  if (auto v = node.value<double>(); v && (node.is_integer() || node.is_floating_point())) {
    if (!std::isfinite(*v)) {
      error(at(node), key, "expected a finite number", "use a finite value in SI units");
      return false;
    }
    out = *v;
    return true;
  }
  std::string hint = node.is_string() ? "write the number without quotes, e.g. 1.5" : "";
  error(at(node), key, fmt::format("expected a number, got {}", type_name(node)), hint);
  return false;
}

bool Reader::expression(const toml::node& node, const std::string& key, ExpressionText& out) {
  out.key = key;
  out.where = at(node);
  if (const auto* s = node.as_string()) {
    out.text = s->get();
    out.where.column += 1;  // the opening quote
    return true;
  }
  if (node.is_integer() || node.is_floating_point()) {
    double v = *node.value<double>();
    if (!std::isfinite(v)) {
      error(at(node), key, "expected a finite number");
      return false;
    }
    out.text = node.is_integer() ? fmt::format("{}", *node.value<std::int64_t>()) : fmt::format("{}", v);
    return true;
  }
  error(at(node), key, fmt::format("expected an expression (a string or a number), got {}", type_name(node)));
  return false;
}

bool Reader::vector(const toml::node& node, const std::string& key, std::size_t length,
                    std::vector<ExpressionText>& out) {
  // a 3-vector may be named: a vector definition or a point, read as NAME.x, NAME.y, NAME.z
  if (const auto* name = node.as_string(); name && length == 3) {
    out.assign(3, {});
    for (std::size_t i = 0; i < 3; ++i) {
      expression(node, fmt::format("{}[{}]", key, i), out[i]);
      out[i].text = component_name(name->get(), i);
    }
    return true;
  }
  const toml::array* a = array(node, key, fmt::format("{} expressions", length).c_str());
  if (!a) return false;
  if (a->size() != length) {
    error(at(node), key, fmt::format("expected {} components, got {}", length, a->size()),
          length == 3 ? "write [x, y, z], e.g. [\"l*sin(phi)\", \"-l*cos(phi)\", \"0\"]" : "");
    return false;
  }
  bool ok = true;
  out.resize(length);
  for (std::size_t i = 0; i < length; ++i)
    ok = expression((*a)[i], fmt::format("{}[{}]", key, i), out[i]) && ok;
  return ok;
}

bool Reader::matrix3(const toml::node& node, const std::string& key,
                     std::vector<std::vector<ExpressionText>>& out) {
  // a matrix may be named: a matrix definition, read as NAME.xx, NAME.xy, ... NAME.zz
  if (const auto* name = node.as_string()) {
    out.assign(3, std::vector<ExpressionText>(3));
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) {
        expression(node, fmt::format("{}[{}][{}]", key, i, j), out[i][j]);
        out[i][j].text = entry_name(name->get(), i, j);
      }
    return true;
  }
  const toml::array* a = array(node, key, "3 rows of 3 expressions");
  if (!a) return false;
  if (a->size() != 3) {
    error(at(node), key, fmt::format("expected 3 rows, got {}", a->size()), "write [[..], [..], [..]]");
    return false;
  }
  bool ok = true;
  out.assign(3, {});
  for (std::size_t i = 0; i < 3; ++i)
    ok = vector((*a)[i], fmt::format("{}[{}]", key, i), 3, out[i]) && ok;
  return ok;
}

}  // namespace eomgen::toml_reader
