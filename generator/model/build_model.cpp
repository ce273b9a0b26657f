#include <algorithm>
#include <cmath>
#include <exception>

#include <fmt/format.h>

#include "model/model_builder.hpp"
#include "spatial/joint_tree_dynamics.hpp"

namespace eomgen {

// Multiplied out, the derivation of a chain of frames grows about 20 times per frame from the
// third on, composed link by link polynomially: tests/benchmarks/README.md, "The 3-D chain through
// frames" (rods on universal joints, rot_z(a)*rot_x(b) per frame; `eomgen derive` multiplied out
// 0.016, 0.064, 0.72 and 15.5 s for 1 to 4 frames, composed 0.008 to 0.036 s). A chain of frames
// that is no tree of joints is composed from the depth where writing it out takes seconds; the
// shallower ones stay written out, as they were before eomgen chose (their rhs not compared).
constexpr int composed_from_depth = 4;

using GiNaC::ex;

namespace {

// the first frame moved by a ball or free joint, or null
const FrameEntry* first_spherical_joint(const ModelFile& file) {
  auto found = std::find_if(file.frames.begin(), file.frames.end(), [](const FrameEntry& f) {
    return f.joint && (f.joint->type == "ball" || f.joint->type == "free");
  });
  return found == file.frames.end() ? nullptr : &*found;
}

}  // namespace

const std::vector<std::string>& known_methods() {
  static const std::vector<std::string> methods = {"lagrange2", "lagrange1", "appell", "hamilton"};
  return methods;
}

std::optional<double> constant_value(const ex& e, const Symbols& symbols) {
  ex v = e.subs(symbols.default_parameter_values()).evalf();
  if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real()) return std::nullopt;
  double x = GiNaC::ex_to<GiNaC::numeric>(v).to_double();
  if (!std::isfinite(x)) return std::nullopt;
  return x;
}

Model ModelBuilder::build() {
  m_.name = f_.name;
  m_.title = f_.title;
  m_.method = f_.method;
  // frames with joints, or read as joints, are a tree for the spatial recursions, and deep frames
  // that are no such tree are composed link by link, unless the equations are wanted written out
  bool joints = std::any_of(f_.frames.begin(), f_.frames.end(), [](const FrameEntry& f) { return f.joint.has_value(); });
  bool lagrange = f_.method == "lagrange2" || f_.method == "lagrange1";
  m_.recursive_kinematics = reading_ == FrameReading::composed ||
                            (lagrange && reading_ != FrameReading::written_out && (joints || reading_ == FrameReading::tree));
  check_spherical_joints();
  m_.source = f_.path;
  check_header();
  declare_symbols();
  read_definitions();
  read_initial_state();
  read_frames();
  read_points();
  read_bodies();
  read_drawing();
  read_energies_and_forces();
  read_constraints();
  read_outputs();
  check_complete();
  build_scenes_and_variants(f_, m_, d_);
  return m_;
}

// Ball and free joints have angular velocities as their velocities: Appell's equations over
// the tree (the method's default for such a model), in recursive kinematics
void ModelBuilder::check_spherical_joints() {
  const FrameEntry* spherical = first_spherical_joint(f_);
  if (!spherical) return;
  std::string why = fmt::format("frame '{}' has a {} joint, whose velocities are its angular velocity (pseudo-velocities)",
                                spherical->name, spherical->joint->type);
  if (f_.method_where.line == 0) m_.method = "appell";
  else if (f_.method != "appell")
    d_.error(f_.method_where, "model.method", why + fmt::format(": method \"{}\" cannot take them", f_.method),
             "use method = \"appell\", or leave the method out");
  m_.recursive_kinematics = true;
}

std::optional<ex> ModelBuilder::parse(const ExpressionText& text, unsigned allowed, const char* context) {
  ExpressionRules rules{allowed, context};
  rules.angular_velocities = &angular_velocity_names_;
  return parse_expression(text, m_.symbols, rules, d_);
}

void ModelBuilder::check_header() {
  if (f_.name.empty()) return;  // reported by the parser
  if (!is_cpp_identifier(f_.name))
    d_.error(f_.name_where, "model.name", fmt::format("'{}' is not a C++ identifier", f_.name),
             "the name becomes the header's file name and namespace: use letters, digits and _, e.g. double_pendulum");
  else if (f_.name == "std")
    d_.error(f_.name_where, "model.name", "'std' would name the header's namespace eomgen::models::std, which hides the "
             "standard library from the header's own code", "choose another name, e.g. std_model");
  const auto& methods = known_methods();
  if (std::find(methods.begin(), methods.end(), f_.method) == methods.end())
    d_.error(f_.method_where, "model.method", fmt::format("unknown method '{}'", f_.method),
             suggest(f_.method, methods, "methods"));
  if (f_.kinematics_where.line != 0)
    d_.error(f_.kinematics_where, "model.kinematics",
             fmt::format("the key is retired: eomgen derives frames that carry or read as joints over the tree of "
                         "joints, chains of other frames {} or more deep by composing them link by link, and the rest "
                         "written out in q",
                         composed_from_depth),
             "remove the line; the analyses that need equations written out in q (derive --written-out and "
             "--linearize, diff, stability --symbolic, derive --reduce) write them out themselves");
  if (f_.forward_dynamics_where.line != 0)
    d_.error(f_.forward_dynamics_where, "model.forward_dynamics",
             fmt::format("the key is retired: eomgen chooses how the header's rhs solves for q'' (the "
                         "articulated-body recursion for a tree of particles of {} coordinates or more and for a "
                         "tree of joints {} or more deep on average where it has fewer operations, M = L D L^T "
                         "otherwise)",
                         articulated_crossover, articulated_mean_depth),
             "remove the line; `eomgen generate --forward-dynamics mass_matrix` or `articulated` writes a header in "
             "the other form, to compare the two");
}

void ModelBuilder::declare(const std::string& name, SourceLocation where, const std::string& key,
                         SymbolKind kind, std::size_t index, const char* what) {
  static const char* kind_names[] = {"a parameter", "a coordinate", "an input", "a definition", "a vector", "a matrix"};
  if (!is_identifier(name)) {
    d_.error(where, key, fmt::format("'{}' is not a valid name", name), "use letters, digits and _, starting with a letter");
    return;
  }
  if (is_reserved_name(name)) {
    d_.error(where, key, fmt::format("'{}' is reserved and cannot name {}", name, what),
             "t is time, der() a velocity, Pi is pi; the others are functions");
    return;
  }
  auto [it, fresh] = m_.symbols.by_name.emplace(name, SymbolInfo{kind, index});
  if (!fresh) {
    SourceLocation first = declared_at_[name];
    d_.error(where, key,
             fmt::format("symbol '{}' is defined twice: as {} (line {}) and as {}", name,
                         kind_names[static_cast<int>(it->second.kind)], first.line, what),
             "give each parameter, coordinate and input its own name");
    return;
  }
  declared_at_[name] = where;
}

void ModelBuilder::declare_symbols() {
  Symbols& s = m_.symbols;
  for (const ParameterEntry& p : f_.parameters) {
    declare(p.name, p.where, p.key, SymbolKind::parameter, s.parameters.size(), "a parameter");
    s.parameter_names.push_back(p.name);
    s.parameters.emplace_back(p.name);
    s.parameter_defaults.push_back(p.value);
  }
  for (const CoordinateEntry& c : f_.coordinates) {
    declare(c.name, c.where, c.key, SymbolKind::coordinate, s.coordinates.size(), "a coordinate");
    s.coordinate_names.push_back(c.name);
    s.coordinates.emplace_back(c.name);
    s.velocities.emplace_back("der(" + c.name + ")");
  }
  for (const ParameterEntry& u : f_.inputs) {
    declare(u.name, u.where, u.key, SymbolKind::input, s.inputs.size(), "an input");
    s.input_names.push_back(u.name);
    s.inputs.emplace_back(u.name);
    s.input_defaults.push_back(u.value);
  }
  m_.generalized_force.assign(s.coordinates.size(), 0);
}

double ModelBuilder::constant(const ExpressionText& text, const char* context, ex* expression) {
  auto e = parse(text, allow_parameters, context);
  if (!e) return 0;
  if (expression) *expression = *e;
  auto v = constant_value(*e, m_.symbols);
  if (!v) d_.error(text.where, text.key, "the value is not a finite real number");
  return v.value_or(0);
}

void ModelBuilder::read_definitions() {
  std::vector<std::string> later;
  for (const DefinitionEntry& e : f_.definitions) later.push_back(e.name);
  for (const DefinitionEntry& e : f_.definitions) {
    later.erase(later.begin());
    std::string key = "definitions." + e.name;
    if (e.components.size() == 1) {
      auto value = parse_expression(e.components[0], m_.symbols, {allow_everything, "a definition", &later}, d_);
      define(e.name, e.where, key, value.value_or(0));
      continue;
    }
    std::vector<ex> values(e.components.size(), 0);
    for (std::size_t i = 0; i < values.size(); ++i)
      if (auto c = parse_expression(e.components[i], m_.symbols, {allow_everything, "a definition", &later}, d_))
        values[i] = *c;
    define_whole(e.name, e.where, key, values);
  }
}

void ModelBuilder::define(const std::string& name, SourceLocation where, const std::string& key, const ex& value) {
  Symbols& s = m_.symbols;
  declare(name, where, key, SymbolKind::definition, s.definitions.size(), "a definition");
  s.definition_names.push_back(name);
  s.definitions.push_back(value);
}

void ModelBuilder::define_whole(const std::string& name, SourceLocation where, const std::string& key, const std::vector<ex>& values) {
  Symbols& s = m_.symbols;
  if (!is_identifier(name)) {
    d_.error(where, key, fmt::format("'{}' is not a valid name", name), "use letters, digits and _, starting with a letter");
    return;
  }
  bool matrix = values.size() == 9;
  std::vector<std::string>& wholes = matrix ? s.matrix_names : s.vector_names;
  declare(name, where, key, matrix ? SymbolKind::matrix : SymbolKind::vector, wholes.size(), matrix ? "a matrix" : "a vector");
  wholes.push_back(name);
  for (std::size_t k = 0; k < values.size(); ++k) {
    std::string component = matrix ? entry_name(name, k / 3, k % 3) : component_name(name, k);
    s.by_name[component] = {SymbolKind::definition, s.definitions.size()};
    s.definition_names.push_back(component);
    s.definitions.push_back(values[k]);
  }
}

void ModelBuilder::read_initial_state() {
  Symbols& s = m_.symbols;
  for (const CoordinateEntry& c : f_.coordinates) {
    ex q0 = 0, rate0 = 0;
    s.initial_coordinates.push_back(constant(c.initial, "an initial value", &q0));
    s.initial_velocities.push_back(constant(c.rate, "an initial rate", &rate0));
    s.initial_coordinate_expressions.push_back(q0);
    s.initial_rate_expressions.push_back(rate0);
  }
}

void ModelBuilder::read_outputs() {
  for (const NamedExpression& o : f_.outputs) {
    std::string key = "outputs." + o.name;
    if (!is_cpp_identifier(o.name))
      d_.error(o.where, key, fmt::format("'{}' is not a C++ identifier", o.name), "output names become C++ names");
    auto e = parse(o.expression, allow_everything, "an output");
    if (e) m_.outputs.push_back({o.name, *e});
  }
}

void ModelBuilder::check_complete() {
  SourceLocation top{f_.path, 1, 1};
  if (f_.coordinates.empty() && f_.coordinates_where)
    d_.error(*f_.coordinates_where, "coordinates", "[coordinates] is empty: the model has no coordinates",
             "add one per degree of freedom under it, e.g. phi = { initial = 0.1, rate = 0 }");
  else if (f_.coordinates.empty())
    d_.error(top, "coordinates", "the model has no coordinates",
             "add a [coordinates] section, e.g. phi = { initial = 0.1, rate = 0 }");
  bool has_mass = !f_.particles.empty() || !f_.rigid_bodies.empty() || f_.kinetic;
  if (!f_.coordinates.empty() && !has_mass)
    d_.error(top, "", "nothing in the model has mass or kinetic energy",
             "add [[particles]], [[rigid_bodies]] or [energy] kinetic = \"...\"");
}

namespace {

// the most frames that the coordinates move on one path from the inertial frame
int moving_depth(const Model& model) {
  std::vector<int> depth;
  int deepest = 0;
  for (const FrameLink& l : model.frame_links) {
    bool moves = moves_with(l.relative_rotation, model.symbols) ||
                 moves_with(l.relative_origin[0] + l.relative_origin[1] + l.relative_origin[2], model.symbols);
    depth.push_back((l.parent < 0 ? 0 : depth[std::size_t(l.parent)]) + (moves ? 1 : 0));
    deepest = std::max(deepest, depth.back());
  }
  return deepest;
}

// A ball or free joint's velocities are its angular velocity, which the recursions over a tree of
// joints derive; written out in q, the quaternion's four rates would be the velocities, one too many
void refuse_spherical_joints_off_a_tree(const ModelFile& file, const Model& model, Diagnostics& diagnostics) {
  const FrameEntry* spherical = first_spherical_joint(file);
  if (!spherical) return;
  std::optional<std::string> why = why_not_a_joint_tree(model);
  if (!why) return;
  diagnostics.error(spherical->joint->where, spherical->joint->key,
                    fmt::format("frame '{}' has a {} joint, which eomgen derives over a tree of joints only, and the model is none: {}",
                                spherical->name, spherical->joint->type, *why),
                    "make it one: every body still in a frame moved by one joint, gravity constant and each "
                    "coordinate moving a joint; or turn the frame by hinges or by angles in its rotation instead");
}

}  // namespace

// Frames and bodies that the coordinates turn and slide are a tree of joints when each of them has
// a joint or reads as joints (model/frame_joints.hpp) and the bodies then sit still in the links:
// the model is built as that tree, which the spatial algorithms derive. Otherwise a chain of
// frames composed_from_depth deep is composed link by link (kinematics/recursive_kinematics.hpp),
// and shallower ones are written out in q. A wheel that rolls stays as written: its contact
// conditions are derived from its rotation written out in q (read_rolling refuses it otherwise).
// `written_out` multiplies out every tree but one of ball or free joints.
Model build_model(const ModelFile& file, Diagnostics& diagnostics, bool written_out) {
  using Reading = ModelBuilder::FrameReading;
  if (written_out) return ModelBuilder(file, diagnostics, Reading::written_out).build();
  bool rolls = std::any_of(file.constraints.begin(), file.constraints.end(),
                           [](const ConstraintEntry& c) { return c.kind == ConstraintEntry::Kind::rolls; });
  if (!file.frames.empty() && file.kinematics_where.line == 0 && !rolls) {
    // a trial: whatever stops it (a mistake, an expression the frame recursion cannot take) leaves
    // the model as written, whose build reports the mistakes
    try {
      Diagnostics trial;
      Model tree = ModelBuilder(file, trial, Reading::tree).build();
      if (trial.empty() && tree.recursive_kinematics && !why_not_a_joint_tree(tree)) return tree;
      if (file.method == "lagrange2" || file.method == "lagrange1") {
        Diagnostics composing;
        Model composed = ModelBuilder(file, composing, Reading::composed).build();
        if (composing.empty() && moving_depth(composed) >= composed_from_depth) return composed;
      }
    } catch (const std::exception&) {
    }
  }
  Model model = ModelBuilder(file, diagnostics).build();
  if (diagnostics.empty()) refuse_spherical_joints_off_a_tree(file, model, diagnostics);
  return model;
}

}  // namespace eomgen
