#include "parse/parse_scenes.hpp"

#include <fmt/format.h>

namespace eomgen {

using toml_reader::Entry;
using toml_reader::Reader;

namespace {

void read_numbers_into(Reader& r, const toml::node& node, const std::string& key, const char* what,
                       std::vector<ParameterEntry>& out) {
  const toml::table* t = r.table(node, key, what);
  if (!t) return;
  for (const Entry& e : r.entries(*t)) {
    ParameterEntry p{e.name, 0.0, e.where, key + "." + e.name};
    if (r.number(*e.node, p.key, p.value)) out.push_back(p);
  }
}

void read_expressions_into(Reader& r, const toml::node& node, const std::string& key, const char* what,
                           std::vector<NamedExpression>& out) {
  const toml::table* t = r.table(node, key, what);
  if (!t) return;
  for (const Entry& e : r.entries(*t)) {
    NamedExpression x;
    x.name = e.name;
    x.where = e.where;
    if (r.expression(*e.node, key + "." + e.name, x.expression)) out.push_back(x);
  }
}

void read_names(Reader& r, const toml::node& node, const std::string& key, const char* example, std::vector<NameText>& out) {
  const toml::array* a = r.array(node, key, example);
  if (!a) return;
  for (std::size_t i = 0; i < a->size(); ++i) {
    NameText n{"", r.at((*a)[i])};
    if (r.string((*a)[i], fmt::format("{}[{}]", key, i), n.name)) out.push_back(n);
  }
}

// a positive number of seconds (or a positive accuracy)
void read_positive(Reader& r, const toml::table& t, const char* name, const std::string& key, double& out, const char* hint) {
  const toml::node* n = t.get(name);
  if (!n) return;
  double v = 0;
  if (!r.number(*n, key + "." + name, v)) return;
  if (!(v > 0) || !std::isfinite(v)) r.error(r.at(*n), key + "." + name, fmt::format("{} must be positive and finite", name), hint);
  else out = v;
}

void read_scene(Reader& r, const Entry& e, ModelFile& m) {
  std::string key = "scenes." + e.name;
  const toml::table* t = r.table(*e.node, key, "t_end, dt_out, initial, set, inputs, outputs, accuracy, absolute");
  if (!t) return;
  r.check_keys(*t, key, {"t_end", "dt_out", "initial", "set", "inputs", "outputs", "accuracy", "absolute"});
  SceneEntry s;
  s.name = e.name;
  s.where = e.where;
  read_positive(r, *t, "t_end", key, s.t_end, "write t_end = 10 (seconds)");
  read_positive(r, *t, "dt_out", key, s.dt_out, "write dt_out = 0.01 (seconds), or leave it out for t_end/200");
  read_positive(r, *t, "accuracy", key, s.accuracy, "write accuracy = 1e-3: the error allowed relative to each output's range");
  if (const toml::node* n = t->get("absolute")) {
    if (r.number(*n, key + ".absolute", s.absolute) && !(s.absolute >= 0 && std::isfinite(s.absolute)))
      r.error(r.at(*n), key + ".absolute", "absolute must be zero or positive", "write absolute = 1e-6");
  }
  if (const toml::node* n = t->get("initial")) read_numbers_into(r, *n, key + ".initial", "coordinate = value, \"der(q)\" = rate", s.initial);
  if (const toml::node* n = t->get("set")) read_numbers_into(r, *n, key + ".set", "parameter = value", s.set);
  if (const toml::node* n = t->get("inputs")) read_expressions_into(r, *n, key + ".inputs", "input = \"expression of t\"", s.inputs);
  if (const toml::node* n = t->get("outputs")) read_names(r, *n, key + ".outputs", "[\"phi\", \"tip_x\"]", s.outputs);
  if (s.dt_out > s.t_end)
    r.error(e.where, key, fmt::format("dt_out = {} is longer than t_end = {}", s.dt_out, s.t_end), "make dt_out at most t_end");
  m.scenes.push_back(s);
}

void read_variant(Reader& r, const Entry& e, ModelFile& m) {
  std::string key = "variants." + e.name;
  const toml::table* t = r.table(*e.node, key, "neglect, freeze, tie, small_angle, replace");
  if (!t) return;
  r.check_keys(*t, key, {"neglect", "freeze", "tie", "small_angle", "replace"});
  VariantEntry v;
  v.name = e.name;
  v.where = e.where;
  if (const toml::node* n = t->get("neglect")) read_names(r, *n, key + ".neglect", "[\"m2\"]", v.neglect);
  if (const toml::node* n = t->get("freeze")) read_names(r, *n, key + ".freeze", "[\"q3\"]", v.freeze);
  if (const toml::node* n = t->get("small_angle")) {
    if (n->is_array()) {  // ["phi"]: cos φ → 1 − φ²/2
      std::vector<NameText> names;
      read_names(r, *n, key + ".small_angle", "[\"phi\"]", names);
      for (const NameText& name : names) v.small_angle.push_back({name.name, {"quadratic", name.where, key + ".small_angle"}, name.where});
    } else {
      read_expressions_into(r, *n, key + ".small_angle", "[\"phi\"] or { phi = \"quadratic\" | \"one\" }", v.small_angle);
    }
  }
  if (const toml::node* n = t->get("replace")) read_expressions_into(r, *n, key + ".replace", "parameter = \"expression\"", v.replace);
  if (const toml::node* n = t->get("tie")) read_expressions_into(r, *n, key + ".tie", "coordinate = \"expression of the others\"", v.tie);
  if (v.neglect.empty() && v.freeze.empty() && v.tie.empty() && v.small_angle.empty() && v.replace.empty())
    r.error(e.where, key, "the variant changes nothing", "give neglect, freeze, tie, small_angle or replace");
  m.variants.push_back(v);
}

}  // namespace

void read_scenes(Reader& r, const toml::node& node, ModelFile& m) {
  const toml::table* t = r.table(node, "scenes", "[scenes.NAME] tables");
  if (!t) return;
  for (const Entry& e : r.entries(*t)) read_scene(r, e, m);
}

void read_variants(Reader& r, const toml::node& node, ModelFile& m) {
  const toml::table* t = r.table(node, "variants", "[variants.NAME] tables");
  if (!t) return;
  for (const Entry& e : r.entries(*t)) read_variant(r, e, m);
}

}  // namespace eomgen
