#include "compare/derivation_record.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "emit/formats.hpp"
#include "parse/json_reader.hpp"
#include "pipeline.hpp"

namespace eomgen {

namespace {

class RecordBuilder {
 public:
  RecordBuilder(const JsonValue& root, const std::string& path, Diagnostics& d) : root_(root), path_(path), d_(d) {}

  std::optional<DerivationRecord> build() {
    DerivationRecord r;
    r.path = path_;
    if (root_.kind != JsonValue::object) return wrong(root_, "the file is not a JSON object");
    for (const char* key : {"model", "method", "coordinates", "velocities", "parameters", "mass_matrix", "forcing"})
      if (!root_.find(key)) return wrong(root_, fmt::format("not a derivation: the key \"{}\" is missing", key));
    if (const JsonValue* form = root_.find("hamiltonian_form"); form && form->kind == JsonValue::string &&
                                                                  form->text == "mass_matrix")
      return wrong(*form, "Hamilton's equations in mass-matrix form (der(q) solved from M der(q) = p - b in the "
                          "generated code) cannot be compared equation by equation; compare the models' lagrange2 "
                          "derivations instead");
    r.model = text(*root_.find("model"), "model");
    r.method = text(*root_.find("method"), "method");
    r.coordinates = names(*root_.find("coordinates"), "coordinates");
    r.velocities = names(*root_.find("velocities"), "velocities");
    r.parameters = numbers(*root_.find("parameters"), "parameters");
    if (const JsonValue* inputs = root_.find("inputs")) r.inputs = numbers(*inputs, "inputs");
    if (const JsonValue* intermediates = root_.find("intermediates")) read_intermediates(*intermediates, r);
    matrix(*root_.find("mass_matrix"), "M", r);
    list(*root_.find("forcing"), "f", r);
    single("kinetic_energy", "T", r);
    single("potential_energy", "V", r);
    single("dissipation", "R", r);
    if (const JsonValue* outputs = root_.find("outputs")) {
      for (const auto& [name, value] : members(*outputs, "outputs")) {
        r.outputs.push_back(name);
        r.entries.push_back({"y[" + name + "]", text(value, "outputs." + name)});
      }
    }
    if (const JsonValue* constraints = root_.find("constraints")) read_constraints(*constraints, r);
    if (const JsonValue* multipliers = root_.find("multipliers")) r.multipliers = names(*multipliers, "multipliers");
    if (const JsonValue* definitions = root_.find("pseudo_velocities")) {
      r.pseudo_velocities = true;
      for (const auto& [name, value] : members(*definitions, "pseudo_velocities"))
        r.entries.push_back({"s[" + name + "]", text(value, "pseudo_velocities." + name)});
      const JsonValue* rates = root_.find("coordinate_rates");
      if (!rates || rates->items.size() != r.coordinates.size())
        return wrong(*definitions, "not a derivation: Appell's equations need \"coordinate_rates\", one per coordinate");
      for (std::size_t j = 0; j < r.coordinates.size(); ++j)
        r.entries.push_back({"der(" + r.coordinates[j] + ")", text(rates->items[j], "coordinate_rates")});
      single("acceleration_energy", "S", r);
    }
    if (r.entries.size() < r.velocities.size() * (r.velocities.size() + 1)) wrong(root_, "not a derivation: M and f do not match the velocities");
    if (!d_.empty()) return std::nullopt;
    return r;
  }

 private:
  std::nullopt_t wrong(const JsonValue& at, const std::string& message) {
    d_.error(at.where, "", message, "give a model file (.toml) or the JSON of `eomgen derive MODEL --format json`");
    return std::nullopt;
  }
  std::string text(const JsonValue& v, const std::string& key) {
    if (v.kind != JsonValue::string) wrong(v, fmt::format("not a derivation: \"{}\" must be a string", key));
    return v.text;
  }
  std::vector<std::string> names(const JsonValue& v, const std::string& key) {
    std::vector<std::string> out;
    if (v.kind != JsonValue::array) wrong(v, fmt::format("not a derivation: \"{}\" must be an array of names", key));
    for (const JsonValue& item : v.items) out.push_back(text(item, key));
    return out;
  }
  const std::vector<std::pair<std::string, JsonValue>>& members(const JsonValue& v, const std::string& key) {
    if (v.kind != JsonValue::object) wrong(v, fmt::format("not a derivation: \"{}\" must be an object", key));
    return v.members;
  }
  std::vector<std::pair<std::string, double>> numbers(const JsonValue& v, const std::string& key) {
    std::vector<std::pair<std::string, double>> out;
    for (const auto& [name, value] : members(v, key)) {
      if (value.kind != JsonValue::number) wrong(value, fmt::format("not a derivation: \"{}.{}\" must be a number", key, name));
      out.emplace_back(name, value.value);
    }
    return out;
  }
  // an entry the derivation may leave out, or give as null (a tree's S, which its pass never forms)
  void single(const char* key, const char* name, DerivationRecord& r) {
    if (const JsonValue* v = root_.find(key); v && v->kind != JsonValue::null) r.entries.push_back({name, text(*v, key)});
  }
  void list(const JsonValue& v, const char* name, DerivationRecord& r) {
    if (v.kind != JsonValue::array) return (void)wrong(v, fmt::format("not a derivation: \"{}\" must be an array", name));
    for (std::size_t i = 0; i < v.items.size(); ++i) r.entries.push_back({fmt::format("{}[{}]", name, i), text(v.items[i], name)});
  }
  void matrix(const JsonValue& v, const char* name, DerivationRecord& r) {
    if (v.kind != JsonValue::array) return (void)wrong(v, "not a derivation: \"mass_matrix\" must be an array of rows");
    for (std::size_t i = 0; i < v.items.size(); ++i) {
      const JsonValue& row = v.items[i];
      if (row.kind != JsonValue::array || row.items.size() != v.items.size())
        return (void)wrong(row, "not a derivation: \"mass_matrix\" must be square");
      for (std::size_t j = 0; j < row.items.size(); ++j)
        r.entries.push_back({fmt::format("{}[{}][{}]", name, i, j), text(row.items[j], "mass_matrix")});
    }
  }
  void read_intermediates(const JsonValue& v, DerivationRecord& r) {
    if (v.kind != JsonValue::array) return (void)wrong(v, "not a derivation: \"intermediates\" must be an array");
    for (const JsonValue& i : v.items) {
      const JsonValue* name = i.find("name");
      const JsonValue* definition = i.find("definition");
      if (!name || !definition) return (void)wrong(i, "not a derivation: an intermediate needs \"name\" and \"definition\"");
      r.intermediates.push_back({text(*name, "intermediates.name"), text(*definition, "intermediates.definition")});
    }
  }
  void read_constraints(const JsonValue& v, DerivationRecord& r) {
    if (v.kind != JsonValue::array) return (void)wrong(v, "not a derivation: \"constraints\" must be an array");
    for (const JsonValue& c : v.items) {
      const JsonValue* name = c.find("name");
      const JsonValue* jacobian = c.find("jacobian");
      if (!name || !jacobian || jacobian->items.size() != r.coordinates.size())
        return (void)wrong(c, "not a derivation: a constraint needs \"name\" and a \"jacobian\" row per coordinate");
      std::string n = text(*name, "constraints.name");
      if (const JsonValue* g = c.find("position"); g && g->kind == JsonValue::string) r.entries.push_back({"g[" + n + "]", g->text});
      for (std::size_t j = 0; j < jacobian->items.size(); ++j)
        r.entries.push_back({"C[" + n + "][" + r.coordinates[j] + "]", text(jacobian->items[j], "constraints.jacobian")});
      if (const JsonValue* b = c.find("bias")) r.entries.push_back({"b[" + n + "]", text(*b, "constraints.bias")});
    }
  }

  const JsonValue& root_;
  std::string path_;
  Diagnostics& d_;
};

// a robot file (MJCF, URDF) that the model parser imports in memory as every command does
bool is_robot_file(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  return extension == ".xml" || extension == ".urdf" || extension == ".xacro";
}

// a model file or a robot file; anything else is taken for derived-equations JSON
bool is_model_file(const std::string& path) {
  return is_robot_file(path) || std::filesystem::path(path).extension().string() == ".toml";
}

// Equations read best written out in q, as a model's author wrote them. A tree's are compared in
// its quantities (world poses, composite inertias), which the numeric level evaluates in order,
// where writing them out takes long: oblique_tree's 5 joints ran past the 300 s limit, the
// seven-joint arm's URDF took a minute a side; trees of up to 4 velocities took under 0.4 s (models/:
// measured_arm, geared_gripper, spatial_double_pendulum, four_bar_linkage). The same rule for robot
// files, so that a robot and the model file `eomgen import` writes of it compare alike. Ball and
// free joints keep their quantities either way; a model without any is already written out.
bool written_out_is_small(const Equations& e) {
  constexpr std::size_t written_out_up_to_velocities = 4;
  return !e.intermediates.empty() && e.num_velocities() <= written_out_up_to_velocities;
}

}  // namespace

std::optional<DerivationRecord> read_derivation(const std::string& path, Diagnostics& diagnostics) {
  std::string json;
  if (is_model_file(path)) {
    Derivation d = derive_model_file_for(path, ModelChoice{});
    if (d.diagnostics.empty() && written_out_is_small(*d.equations)) d = derive_model_file_for(path, model_written_out());
    if (!d.diagnostics.empty()) {
      for (const Diagnostic& x : d.diagnostics.list()) diagnostics.error(x.where, x.key, x.message, x.hint);
      return std::nullopt;
    }
    json = emit_json(*d.equations);
  } else {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
      diagnostics.error({path, 0, 0}, "", "the file cannot be read (missing, or not readable)",
                        "give a model file (.toml), a robot file (MJCF .xml, URDF .urdf) or a derived-equations JSON");
      return std::nullopt;
    }
    std::ostringstream text;
    text << in.rdbuf();
    json = text.str();
  }
  auto root = parse_json(json, path, diagnostics);
  if (!root) return std::nullopt;
  return RecordBuilder(*root, path, diagnostics).build();
}

}  // namespace eomgen
