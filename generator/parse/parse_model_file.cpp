#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "parse/model_file.hpp"

#include "import/model_writer.hpp"
#include "parse/parse_frames.hpp"
#include "parse/parse_scenes.hpp"
#include "parse/parse_shapes.hpp"
#include "parse/toml_reader.hpp"
#include "parse/utf8.hpp"

namespace eomgen {
namespace {

using toml_reader::Entry;
using toml_reader::Reader;

const std::vector<std::string> top_level_keys = {
    "model", "parameters", "coordinates", "inputs", "frames", "points", "particles", "rigid_bodies", "gravity",
    "energy", "forces", "constraints", "pseudo_velocities", "outputs", "scenes", "variants", "definitions"};

// [model]: name, title, method, kinematics, forward_dynamics
void read_model_section(Reader& r, const toml::node& node, ModelFile& m) {
  const toml::table* t = r.table(node, "model", "name, title, method");
  if (!t) return;
  r.check_keys(*t, "model", {"name", "title", "method", "kinematics", "forward_dynamics"});
  if (const toml::node* n = t->get("name")) {
    m.name_where = r.at(*n);
    r.string(*n, "model.name", m.name);
  } else {
    r.error(r.at(node), "model", "missing key 'name'", "add name = \"my_system\" (a C++ identifier)");
  }
  if (const toml::node* n = t->get("title")) r.string(*n, "model.title", m.title);
  if (const toml::node* n = t->get("method")) {
    m.method_where = r.at(*n);
    r.string(*n, "model.method", m.method);
  }
  if (const toml::node* n = t->get("kinematics")) m.kinematics_where = r.at(*n);
  if (const toml::node* n = t->get("forward_dynamics")) m.forward_dynamics_where = r.at(*n);
}

// [parameters] / [inputs]: name = number
void read_numbers(Reader& r, const toml::node& node, const std::string& section,
                  std::vector<ParameterEntry>& out) {
  const toml::table* t = r.table(node, section, "name = value");
  if (!t) return;
  for (const Entry& e : r.entries(*t)) {
    ParameterEntry p{e.name, 0.0, e.where, section + "." + e.name};
    // a mistaken value keeps its name, with a stand-in value, so the names are still checked
    if (!r.number(*e.node, p.key, p.value)) p.value = 1, ++r.stand_ins;
    out.push_back(p);
  }
}

ExpressionText constant_text(const std::string& text, SourceLocation where, std::string key) {
  return {text, std::move(where), std::move(key)};
}

// [coordinates]: name = initial | { initial = .., rate = .. }
void read_coordinates(Reader& r, const toml::node& node, ModelFile& m) {
  const toml::table* t = r.table(node, "coordinates", "name = initial value");
  if (!t) return;
  m.coordinates_where = r.at(node);
  for (const Entry& e : r.entries(*t)) {
    std::string key = "coordinates." + e.name;
    CoordinateEntry c{e.name, constant_text("0", e.where, key + ".initial"),
                      constant_text("0", e.where, key + ".rate"), e.where, key};
    if (const toml::table* spec = e.node->as_table()) {
      r.check_keys(*spec, key, {"initial", "rate"});
      if (const toml::node* n = spec->get("initial")) r.expression(*n, key + ".initial", c.initial);
      if (const toml::node* n = spec->get("rate")) r.expression(*n, key + ".rate", c.rate);
    } else if (!r.expression(*e.node, key, c.initial)) {
      continue;
    }
    m.coordinates.push_back(c);
  }
}

std::string read_name(Reader& r, const toml::table& t, const toml::node& node, const std::string& key) {
  std::string name;
  if (const toml::node* n = t.get("name")) r.string(*n, key + ".name", name);
  else r.error(r.at(node), key, "missing key 'name'", "give every body a name = \"...\"");
  return name;
}

// [[particles]]: name, mass, position
void read_particles(Reader& r, const toml::node& node, ModelFile& m) {
  const toml::array* a = r.array(node, "particles", "[[particles]] tables");
  if (!a) return;
  for (std::size_t i = 0; i < a->size(); ++i) {
    std::string key = fmt::format("particles[{}]", i);
    const toml::table* t = r.table((*a)[i], key, "name, mass, position, frame");
    if (!t) continue;
    r.check_keys(*t, key, {"name", "mass", "position", "frame", "shape"});
    ParticleEntry p;
    p.key = key;
    p.where = r.at((*a)[i]);
    p.name = read_name(r, *t, (*a)[i], key);
    read_frame_name(r, *t, key, p.frame, p.frame_where);
    read_shapes(r, *t, key, p.shapes);
    if (const toml::node* n = t->get("mass")) r.expression(*n, key + ".mass", p.mass);
    else r.error(p.where, key, "missing key 'mass'", "add mass = \"m\" (a parameter or an expression)");
    if (const toml::node* n = t->get("position")) r.vector(*n, key + ".position", 3, p.position);
    else if (!t->contains("frame"))
      r.error(p.where, key, "missing key 'position'", "add position = [\"x\", \"y\", \"z\"]");
    m.particles.push_back(p);
  }
}

void read_inertia(Reader& r, const toml::node& node, const std::string& key, RigidBodyEntry& b) {
  const toml::array* a = node.as_array();
  if ((a && !a->empty() && (*a)[0].is_array()) || node.is_string()) {  // a string names a matrix definition
    if (node.is_string()) r.expression(node, key, b.inertia_name.emplace());
    r.matrix3(node, key, b.inertia);
  } else if (a && a->size() == 3) {
    r.vector(node, key, 3, b.principal_inertia);
  } else {
    r.error(r.at(node), key, "expected three principal moments or a 3x3 tensor",
            "write inertia = [\"A\", \"B\", \"C\"], [[..], [..], [..]] in the body frame, or the name of a "
            "3x3 matrix under [definitions]");
  }
}

// [[rigid_bodies]]: name, mass, center, rotation, inertia
void read_rigid_bodies(Reader& r, const toml::node& node, ModelFile& m) {
  const toml::array* a = r.array(node, "rigid_bodies", "[[rigid_bodies]] tables");
  if (!a) return;
  for (std::size_t i = 0; i < a->size(); ++i) {
    std::string key = fmt::format("rigid_bodies[{}]", i);
    const toml::table* t = r.table((*a)[i], key, "name, mass, center, rotation, inertia, frame");
    if (!t) continue;
    r.check_keys(*t, key, {"name", "mass", "center", "rotation", "inertia", "frame", "shape", "unphysical_inertia"});
    RigidBodyEntry b;
    b.key = key;
    b.where = r.at((*a)[i]);
    b.name = read_name(r, *t, (*a)[i], key);
    read_frame_name(r, *t, key, b.frame, b.frame_where);
    read_shapes(r, *t, key, b.shapes);
    if (const toml::node* n = t->get("mass")) r.expression(*n, key + ".mass", b.mass);
    else r.error(b.where, key, "missing key 'mass'", "add mass = \"m\"");
    if (const toml::node* n = t->get("center")) r.vector(*n, key + ".center", 3, b.center);
    else if (!t->contains("frame"))
      r.error(b.where, key, "missing key 'center'",
              "add center = [\"x\", \"y\", \"z\"], the centre of mass, or frame = \"...\" with the centre at its origin");
    if (const toml::node* n = t->get("rotation")) b.rotation = read_rotation(r, *n, key + ".rotation");
    if (const toml::node* n = t->get("inertia")) read_inertia(r, *n, key + ".inertia", b);
    else r.error(b.where, key, "missing key 'inertia'", "add inertia = [\"A\", \"B\", \"C\"] (principal moments)");
    if (const toml::node* n = t->get("unphysical_inertia")) r.boolean(*n, key + ".unphysical_inertia", b.unphysical_inertia);
    m.rigid_bodies.push_back(b);
  }
}

void read_gravity(Reader& r, const toml::node& node, ModelFile& m) {
  const toml::table* t = r.table(node, "gravity", "acceleration");
  if (!t) return;
  r.check_keys(*t, "gravity", {"acceleration"});
  if (const toml::node* n = t->get("acceleration")) r.vector(*n, "gravity.acceleration", 3, m.gravity);
  else r.error(r.at(node), "gravity", "missing key 'acceleration'", "add acceleration = [\"0\", \"-g\", \"0\"]");
}

void read_energy(Reader& r, const toml::node& node, ModelFile& m) {
  const toml::table* t = r.table(node, "energy", "kinetic, potential, dissipation");
  if (!t) return;
  r.check_keys(*t, "energy", {"kinetic", "potential", "dissipation"});
  auto read = [&](const char* name, std::optional<ExpressionText>& out) {
    if (const toml::node* n = t->get(name)) {
      ExpressionText e;
      if (r.expression(*n, std::string("energy.") + name, e)) out = e;
    }
  };
  read("kinetic", m.kinetic);
  read("potential", m.potential);
  read("dissipation", m.dissipation);
}

void read_generalized_force(Reader& r, const toml::node& node, const std::string& key, ForceEntry& f) {
  const toml::table* t = r.table(node, key, "coordinate = expression");
  if (!t) return;
  for (const Entry& e : r.entries(*t)) {
    NamedExpression g;
    g.name = e.name;
    g.where = e.where;
    if (r.expression(*e.node, key + "." + e.name, g.expression)) f.generalized.push_back(g);
  }
}

// [[forces]]: generalized = {q = expr} | at = [..], force = [..] | body, torque, frame
void read_forces(Reader& r, const toml::node& node, ModelFile& m) {
  const toml::array* a = r.array(node, "forces", "[[forces]] tables");
  if (!a) return;
  for (std::size_t i = 0; i < a->size(); ++i) {
    std::string key = fmt::format("forces[{}]", i);
    const toml::table* t = r.table((*a)[i], key, "a generalized force, a point force or a torque");
    if (!t) continue;
    r.check_keys(*t, key, {"generalized", "at", "force", "body", "torque", "frame"});
    ForceEntry f;
    f.key = key;
    f.where = r.at((*a)[i]);
    if (const toml::node* n = t->get("generalized")) {
      f.kind = ForceEntry::Kind::generalized;
      read_generalized_force(r, *n, key + ".generalized", f);
    } else if (t->contains("force") || t->contains("at")) {
      f.kind = ForceEntry::Kind::point;
      const toml::node* at = t->get("at");
      const toml::node* force = t->get("force");
      if (!at || !force) {
        r.error(f.where, key, "a point force needs both 'at' and 'force'",
                "write { at = [x, y, z], force = [Fx, Fy, Fz] } in inertial components");
        continue;
      }
      r.vector(*at, key + ".at", 3, f.at);
      r.vector(*force, key + ".force", 3, f.force);
    } else if (t->contains("torque") || t->contains("body")) {
      f.kind = ForceEntry::Kind::torque;
      const toml::node* body = t->get("body");
      const toml::node* torque = t->get("torque");
      if (!body || !torque) {
        r.error(f.where, key, "a torque needs both 'body' and 'torque'",
                "write { body = \"name\", torque = [Mx, My, Mz] }");
        continue;
      }
      f.body_where = r.at(*body);
      r.string(*body, key + ".body", f.body);
      r.vector(*torque, key + ".torque", 3, f.torque);
      if (const toml::node* fr = t->get("frame")) {
        std::string frame;
        if (r.string(*fr, key + ".frame", frame)) {
          if (frame == "inertial") f.inertial_frame = true;
          else if (frame != "body")
            r.error(r.at(*fr), key + ".frame", fmt::format("unknown frame '{}'", frame),
                    "use \"body\" (the default) or \"inertial\"");
        }
      }
    } else {
      r.error(f.where, key, "a force needs 'generalized', 'at'/'force' or 'body'/'torque'",
              "write generalized = { q = \"expr\" }, or at/force, or body/torque");
      continue;
    }
    m.forces.push_back(f);
  }
}

// rolls = { body, radius, axis }
bool read_rolling(Reader& r, const toml::node& node, const std::string& key, ConstraintEntry& c) {
  const toml::table* t = r.table(node, key, "body, radius, axis");
  if (!t) return false;
  r.check_keys(*t, key, {"body", "radius", "axis"});
  c.kind = ConstraintEntry::Kind::rolls;
  const toml::node* body = t->get("body");
  const toml::node* radius = t->get("radius");
  const toml::node* axis = t->get("axis");
  if (!body || !radius || !axis) {
    r.error(r.at(node), key, "a rolling disk needs body, radius and axis",
            "write rolls = { body = \"wheel\", radius = \"r\", axis = [0, 1, 0] } (the axis in the body frame)");
    return false;
  }
  c.body_where = r.at(*body);
  c.body_where.column += 1;
  bool ok = r.string(*body, key + ".body", c.body);
  ok = r.expression(*radius, key + ".radius", c.radius) && ok;
  return r.vector(*axis, key + ".axis", 3, c.axis) && ok;
}

void read_constraints(Reader& r, const toml::node& node, ModelFile& m) {
  const toml::array* a = r.array(node, "constraints", "[[constraints]] tables");
  if (!a) return;
  for (std::size_t i = 0; i < a->size(); ++i) {
    std::string key = fmt::format("constraints[{}]", i);
    const toml::table* t = r.table((*a)[i], key, "holonomic or nonholonomic");
    if (!t) continue;
    r.check_keys(*t, key, {"holonomic", "nonholonomic", "rolls", "name"});
    ConstraintEntry c;
    if (const toml::node* name = t->get("name")) {
      if (auto text = name->value<std::string>()) {
        c.name = *text;
        c.name_where = r.at(*name);
      } else {
        r.error(r.at(*name), key + ".name", "a constraint's name is a string", "write name = \"rod\"");
      }
    }
    c.key = key;
    c.where = r.at((*a)[i]);
    const toml::node* h = t->get("holonomic");
    const toml::node* n = t->get("nonholonomic");
    const toml::node* rolls = t->get("rolls");
    if ((h != nullptr) + (n != nullptr) + (rolls != nullptr) != 1) {
      r.error(c.where, key, "a constraint is either holonomic, nonholonomic or rolls",
              "write holonomic = \"f(q,t)\" (f = 0), nonholonomic = \"a(q,t)*der(q) + b(q,t)\" or "
              "rolls = { body = \"wheel\", radius = \"r\", axis = [0, 1, 0] }");
      continue;
    }
    if (rolls) {
      if (read_rolling(r, *rolls, key + ".rolls", c)) m.constraints.push_back(c);
      continue;
    }
    c.kind = h ? ConstraintEntry::Kind::holonomic : ConstraintEntry::Kind::nonholonomic;
    if (r.expression(h ? *h : *n, key + (h ? ".holonomic" : ".nonholonomic"), c.expression))
      m.constraints.push_back(c);
  }
}

void read_named_expressions(Reader& r, const toml::node& node, const std::string& section,
                            std::vector<NamedExpression>& out) {
  const toml::table* t = r.table(node, section, "name = expression");
  if (!t) return;
  for (const Entry& e : r.entries(*t)) {
    NamedExpression x;
    x.name = e.name;
    x.where = e.where;
    if (r.expression(*e.node, section + "." + e.name, x.expression)) out.push_back(x);
  }
}

// [definitions]: name = "expression" | ["x", "y", "z"] | [[row], [row], [row]]
void read_definitions(Reader& r, const toml::node& node, std::vector<DefinitionEntry>& out) {
  const toml::table* t = r.table(node, "definitions", "name = expression, [x, y, z] or [[..], [..], [..]]");
  if (!t) return;
  for (const Entry& e : r.entries(*t)) {
    DefinitionEntry d{e.name, {}, e.where};
    std::string key = "definitions." + e.name;
    const toml::array* a = e.node->as_array();
    bool ok = true;
    if (a && !a->empty() && (*a)[0].is_array()) {
      std::vector<std::vector<ExpressionText>> rows;
      ok = r.matrix3(*e.node, key, rows);
      for (const auto& row : rows) d.components.insert(d.components.end(), row.begin(), row.end());
    } else {
      ok = a ? r.vector(*e.node, key, 3, d.components) : r.expression(*e.node, key, d.components.emplace_back());
    }
    if (ok) out.push_back(d);
  }
}

void read_document(Reader& r, const toml::table& doc, ModelFile& m) {
  r.check_keys(doc, "", top_level_keys);
  for (const Entry& e : r.entries(doc)) {
    const toml::node& n = *e.node;
    if (e.name == "model") read_model_section(r, n, m);
    else if (e.name == "parameters") read_numbers(r, n, "parameters", m.parameters);
    else if (e.name == "coordinates") read_coordinates(r, n, m);
    else if (e.name == "inputs") read_numbers(r, n, "inputs", m.inputs);
    else if (e.name == "frames") read_frames(r, n, m);
    else if (e.name == "points") read_points(r, n, m);
    else if (e.name == "particles") read_particles(r, n, m);
    else if (e.name == "rigid_bodies") read_rigid_bodies(r, n, m);
    else if (e.name == "gravity") read_gravity(r, n, m);
    else if (e.name == "energy") read_energy(r, n, m);
    else if (e.name == "forces") read_forces(r, n, m);
    else if (e.name == "constraints") read_constraints(r, n, m);
    else if (e.name == "pseudo_velocities") read_named_expressions(r, n, "pseudo_velocities", m.pseudo_velocities);
    else if (e.name == "outputs") read_named_expressions(r, n, "outputs", m.outputs);
    else if (e.name == "definitions") read_definitions(r, n, m.definitions);
    else if (e.name == "scenes") read_scenes(r, n, m);
    else if (e.name == "variants") read_variants(r, n, m);
  }
  if (!doc.contains("model"))
    r.error({r.path(), 1, 1}, "model", "missing section [model]",
            "start the file with [model] and name = \"my_system\"");
}

}  // namespace

ModelFile parse_model_text(const std::string& text, const std::string& path, Diagnostics& diagnostics) {
  ModelFile m;
  m.path = path;
  if (text.size() > max_model_file_bytes) {
    diagnostics.error({path, 0, 0}, "",
                      fmt::format("the file has {} bytes; model files are limited to {} bytes",
                                  text.size(), max_model_file_bytes),
                      "a model file describes one system; split generated data out of it");
    return m;
  }
  if (auto bad = first_invalid_utf8(text)) {
    diagnostics.error({path, bad->line, bad->column}, "", "the file is not valid UTF-8",
                      "save the file as UTF-8");
    return m;
  }
  toml::table doc;
  try {
    doc = toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    SourceLocation where{path, static_cast<int>(e.source().begin.line), static_cast<int>(e.source().begin.column)};
    // toml++'s words for a string without its closing quote describe the line's end instead
    if (std::string(e.description()).find("unescaped control characters") != std::string::npos)
      diagnostics.error(where, "", "a string is not closed before the end of its line",
                        "add the closing \" (a string ends on the line where it starts)");
    else
      diagnostics.error(where, "", fmt::format("TOML syntax error: {}", e.description()),
                        "see https://toml.io for the syntax; expressions go in double quotes");
    return m;
  }
  Reader reader(path, diagnostics);
  std::size_t before = diagnostics.size();
  read_document(reader, doc, m);
  m.only_stand_in_mistakes = reader.stand_ins > 0 && diagnostics.size() - before == std::size_t(reader.stand_ins);
  return m;
}

ModelFile parse_model_file(const std::string& path, Diagnostics& diagnostics) {
  std::error_code error;
  std::string extension = std::filesystem::path(path).extension().string();
  if ((extension == ".xml" || extension == ".urdf" || extension == ".xacro") && std::filesystem::is_regular_file(path, error)) {
    std::optional<std::string> text = imported_model_text(path, diagnostics);
    return text ? parse_model_text(*text, path, diagnostics) : ModelFile{};
  }
  if (std::filesystem::is_directory(path, error)) {
    diagnostics.error({path, 0, 0}, "", "this is a directory, not a model file",
                      "name a .toml file, e.g. models/double_pendulum.toml");
    return {};
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    diagnostics.error({path, 0, 0}, "", "cannot open the model file", "check the path");
    return {};
  }
  in.seekg(0, std::ios::end);
  auto size = static_cast<std::size_t>(in.tellg());
  if (size > max_model_file_bytes) {
    diagnostics.error({path, 0, 0}, "",
                      fmt::format("the file has {} bytes; model files are limited to {} bytes",
                                  size, max_model_file_bytes),
                      "a model file describes one system; split generated data out of it");
    return {};
  }
  in.seekg(0);
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return parse_model_text(buffer.str(), path, diagnostics);
}

}  // namespace eomgen
