/// @file [scenes.NAME] and [variants.NAME] checked against the model's symbols, each
/// mistake located: unknown names with a suggestion, inputs that depend on the state.
#include <algorithm>
#include <cctype>

#include <fmt/format.h>

#include "model/expression_parser.hpp"
#include "model/model.hpp"

namespace eomgen {

namespace {

class SceneBuilder {
 public:
  SceneBuilder(const ModelFile& f, Model& m, Diagnostics& d) : f_(f), m_(m), d_(d) {}

  void build() {
    for (const SceneEntry& e : f_.scenes) m_.scenes.push_back(scene(e));
    for (const VariantEntry& e : f_.variants) m_.variants.push_back(variant(e));
  }

 private:
  std::optional<std::size_t> index(const std::string& name, SymbolKind kind, SourceLocation where, const std::string& key,
                                   const char* what, const std::vector<std::string>& names) {
    auto it = m_.symbols.by_name.find(name);
    if (it != m_.symbols.by_name.end() && it->second.kind == kind) return it->second.index;
    d_.error(where, key, fmt::format("'{}' is not {} of the model", name, what), suggest(name, names, "names"));
    return std::nullopt;
  }

  std::vector<std::string> state_names() const {
    std::vector<std::string> out = m_.symbols.coordinate_names;
    for (const std::string& q : m_.symbols.coordinate_names) out.push_back("der(" + q + ")");
    return out;
  }

  Scene scene(const SceneEntry& e) {
    Scene s;
    std::string key = "scenes." + e.name;
    s.name = e.name;
    s.t_end = e.t_end;
    s.dt_out = e.dt_out > 0 ? e.dt_out : e.t_end / 200;
    s.accuracy = e.accuracy, s.absolute = e.absolute;
    std::vector<std::string> states = state_names();
    for (const ParameterEntry& p : e.initial) {
      if (std::find(states.begin(), states.end(), p.name) == states.end())
        d_.error(p.where, p.key, fmt::format("'{}' is not a coordinate or a velocity", p.name), suggest(p.name, states, "states"));
      else
        s.initial.push_back({p.name, p.value});
    }
    for (const ParameterEntry& p : e.set)
      if (auto i = index(p.name, SymbolKind::parameter, p.where, p.key, "a parameter", m_.symbols.parameter_names))
        s.set.push_back({*i, p.value});
    for (const NamedExpression& u : e.inputs) {
      auto i = index(u.name, SymbolKind::input, u.where, key + ".inputs." + u.name, "an input", m_.symbols.input_names);
      auto value = parse_expression(u.expression, m_.symbols, {allow_parameters | allow_time, "a scene's input (of t and the parameters)"}, d_);
      if (i && value) s.inputs.push_back({*i, *value});
    }
    std::vector<std::string> outputs = states;
    for (const NamedSymbolic& o : m_.outputs) outputs.push_back(o.name);
    for (const NameText& o : e.outputs) {
      if (std::find(outputs.begin(), outputs.end(), o.name) == outputs.end())
        d_.error(o.where, key + ".outputs", fmt::format("'{}' is not an output, a coordinate or a velocity", o.name),
                 suggest(o.name, outputs, "names"));
      else
        s.outputs.push_back(o.name);
    }
    if (s.outputs.empty()) s.outputs = m_.symbols.coordinate_names;
    return s;
  }

  // the variant's model is named MODEL_NAME: its header's file name and namespace
  void check_variant_name(const VariantEntry& e, const std::string& key) {
    if (!is_identifier(e.name)) {
      d_.error(e.where, key, fmt::format("'{}' cannot name a variant: the variant's model is {}_{}", e.name, f_.name, e.name),
               "use letters, digits and _, starting with a letter");
      return;
    }
    for (const VariantEntry& other : f_.variants) {
      if (&other == &e) break;
      if (other.name.size() == e.name.size() &&
          std::equal(other.name.begin(), other.name.end(), e.name.begin(),
                     [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b)); }))
        d_.error(e.where, key,
                 fmt::format("variants '{}' and '{}' differ only in case: their headers {}_{}.hpp and {}_{}.hpp are one file on a "
                             "case-insensitive file system",
                             other.name, e.name, f_.name, other.name, f_.name, e.name),
                 "rename one of them");
    }
  }

  Variant variant(const VariantEntry& e) {
    Variant v;
    std::string key = "variants." + e.name;
    v.name = e.name;
    check_variant_name(e, key);
    const auto& parameters = m_.symbols.parameter_names;
    const auto& coordinates = m_.symbols.coordinate_names;
    for (const NameText& p : e.neglect)
      if (auto i = index(p.name, SymbolKind::parameter, p.where, key + ".neglect", "a parameter", parameters)) v.neglect.push_back(*i);
    for (const NameText& q : e.freeze)
      if (auto i = index(q.name, SymbolKind::coordinate, q.where, key + ".freeze", "a coordinate", coordinates)) v.freeze.push_back(*i);
    if (!v.freeze.empty() && v.freeze.size() == coordinates.size())
      d_.error(e.where, key + ".freeze", "the variant freezes every coordinate", "leave at least one coordinate free");
    for (const NamedExpression& q : e.tie) {
      auto i = index(q.name, SymbolKind::coordinate, q.where, key + ".tie." + q.name, "a coordinate", coordinates);
      auto value = parse_expression(q.expression, m_.symbols, {allow_parameters | allow_coordinates, "a tie (of the other coordinates)"}, d_);
      if (i && value && value->has(m_.symbols.coordinates[*i]))
        d_.error(q.expression.where, q.expression.key, fmt::format("{} is tied to an expression of itself", q.name),
                 "write it in the other coordinates, e.g. x3 = \"x2\"");
      else if (i && value)
        v.tie.push_back({*i, *value});
    }
    for (const NamedExpression& a : e.small_angle) {
      auto i = index(a.name, SymbolKind::coordinate, a.where, key + ".small_angle", "a coordinate", coordinates);
      const std::string& kind = a.expression.text;
      if (kind != "quadratic" && kind != "one")
        d_.error(a.expression.where, a.expression.key, fmt::format("unknown small-angle form '{}'", kind),
                 "write \"quadratic\" (cos -> 1 - phi^2/2) or \"one\" (cos -> 1); sin -> phi in both");
      else if (i)
        v.small_angle.push_back({*i, kind == "quadratic"});
    }
    for (const NamedExpression& r : e.replace) {
      auto i = index(r.name, SymbolKind::parameter, r.where, key + ".replace." + r.name, "a parameter", parameters);
      auto value = parse_expression(r.expression, m_.symbols, {allow_parameters, "a replacement (of the parameters)"}, d_);
      if (i && value) v.replace.push_back({*i, *value});
    }
    return v;
  }

  const ModelFile& f_;
  Model& m_;
  Diagnostics& d_;
};

}  // namespace

void build_scenes_and_variants(const ModelFile& file, Model& model, Diagnostics& diagnostics) {
  SceneBuilder(file, model, diagnostics).build();
}

}  // namespace eomgen
