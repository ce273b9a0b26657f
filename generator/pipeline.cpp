#include "pipeline.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "common/deadline.hpp"
#include "derive/constraints.hpp"
#include "derive/first_integrals.hpp"
#include "derive/methods.hpp"
#include "derive/quadratic_kinetic_energy.hpp"
#include "derive/routh.hpp"
#include "derive/vanishing_coordinates.hpp"
#include "kinematics/drawn_bodies.hpp"
#include "kinematics/mechanics.hpp"
#include "model/variants.hpp"
#include "parse/model_file.hpp"
#include "spatial/joint_tree_forward_dynamics.hpp"
#include "symbolic/trig_orientation.hpp"

namespace eomgen {

namespace {

// every derived expression with its trigonometric arguments in one orientation, so that
// the same system written in two ways prints the same (symbolic/trig_orientation.hpp)
void orient(Equations& e) {
  auto each = [](GiNaC::ex& x) { x = orient_trigonometric_arguments(x); };
  for (unsigned i = 0; i < e.mass_matrix.rows(); ++i)
    for (unsigned j = 0; j < e.mass_matrix.cols(); ++j) each(e.mass_matrix(i, j));
  for (GiNaC::ex& x : e.forcing) each(x);
  each(e.kinetic_energy), each(e.potential_energy), each(e.dissipation), each(e.acceleration_energy);
  for (NamedSymbolic& o : e.outputs) each(o.expression);
  for (NamedSymbolic& p : e.pseudo_velocity_definitions) each(p.expression);
  for (GiNaC::ex& x : e.coordinate_rates) each(x);
  if (MomentumSolve* momentum = e.momentum()) {
    for (GiNaC::ex& x : momentum->bias) each(x);
    for (unsigned i = 0; i < momentum->mass_matrix.rows(); ++i)
      for (unsigned j = 0; j < momentum->mass_matrix.cols(); ++j) each(momentum->mass_matrix(i, j));
  }
  for (FirstIntegral& f : e.first_integrals) each(f.expression);
  each(e.routhian);
  for (NamedSymbolic& r : e.eliminated_coordinates) each(r.expression);
  ConstraintSet& c = e.constraints;
  for (GiNaC::ex& x : c.position) each(x);
  for (GiNaC::ex& x : c.bias) each(x);
  for (GiNaC::ex& x : c.acceleration_bias) each(x);
  for (unsigned i = 0; i < c.jacobian.rows(); ++i)
    for (unsigned j = 0; j < c.jacobian.cols(); ++j) each(c.jacobian(i, j));
}

// the scene (its inputs, parameters and initial state), then the variant and the frozen coordinates,
// which are held at the scene's initial values
void chosen_model(const ModelFile& file, const ModelChoice& choice, Model& model, Diagnostics& diagnostics) {
  SourceLocation top{file.path, 1, 1};
  auto unknown = [&](const char* section, const std::string& name, const std::vector<std::string>& names) {
    diagnostics.error(top, section, fmt::format("the model has no {} '{}'", section, name),
                      names.empty() ? fmt::format("add [{}.{}] to the model file", section, name) : suggest(name, names, section));
  };
  if (!choice.scene.empty()) {
    std::vector<std::string> names;
    for (const Scene& x : model.scenes) names.push_back(x.name);
    auto s = std::find(names.begin(), names.end(), choice.scene);
    if (s == names.end()) return unknown("scenes", choice.scene, names);
    model = apply_scene(model, model.scenes[std::size_t(s - names.begin())]);
  }
  try {
    if (!choice.variant.empty()) {
      std::vector<std::string> names;
      for (const Variant& x : model.variants) names.push_back(x.name);
      auto v = std::find(names.begin(), names.end(), choice.variant);
      if (v == names.end()) return unknown("variants", choice.variant, names);
      model = apply_variant(model, model.variants[std::size_t(v - names.begin())]);
    }
    std::vector<std::size_t> frozen;
    std::vector<double> values;
    for (const std::string& q : choice.freeze)
      for (std::size_t i = 0; i < model.symbols.coordinates.size(); ++i)
        if (model.symbols.coordinate_names[i] == q) frozen.push_back(i), values.push_back(model.symbols.initial_coordinates[i]);
    if (!frozen.empty()) model = freeze_coordinates(model, frozen, values);
  } catch (const std::invalid_argument& why) {
    diagnostics.error(top, "variants." + choice.variant, fmt::format("variant {}: {}", choice.variant, why.what()),
                      "neglect parameters that multiply terms, not ones that divide them; replace them instead");
  }
}

// a variant that neglects the only mass of a coordinate leaves it undetermined: dropped unless the scene
// asks for it (derive/vanishing_coordinates.hpp)
void drop_undetermined(Equations& e, const Model& model, const ModelChoice& choice) {
  std::vector<std::string> keep;
  for (const Scene& s : model.scenes)
    if (s.name == choice.scene) keep = s.outputs;
  remove_vanishing_coordinates(e, keep);
}

// `reduce`: the cyclic coordinates Routh's reduction eliminates, whatever the model's method;
// `method`: the method to use instead of the model's
Derivation derive(const ModelFile& file, Diagnostics diagnostics, const std::vector<std::string>& reduce = {},
                  const std::string& method = "", const ModelChoice& choice = {}) {
  Derivation result;
  DerivationDeadline deadline(file.path);
  if (diagnostics.empty() || file.only_stand_in_mistakes) {
    derivation_stage("the model");
    Model model = build_model(file, diagnostics, !reduce.empty() || !method.empty() || choice.written_out);
    if (!method.empty()) model.method = method;
    // the form asked for is checked on the file's own model: a variant that is no tree falls back
    model.forward_dynamics = choice.forward_dynamics;
    if (diagnostics.empty()) check_forward_dynamics(model, {file.path, 1, 1}, diagnostics);
    if (diagnostics.empty()) chosen_model(file, choice, model, diagnostics);
    if (diagnostics.empty() && !reduce.empty() && model.recursive_kinematics)
      diagnostics.error({file.path, 1, 1}, "routh",
                        "Routh's reduction works on equations written out in q, which a ball or free joint's quaternion "
                        "does not give",
                        "reduce a model whose frames turn by Euler or Cardan angles");
    if (diagnostics.empty() && !reduce.empty()) {
      try {
        result.equations = derive_routh(model, compute_mechanics(model), reduce);
        orient(*result.equations);
      } catch (const std::invalid_argument& why) {
        diagnostics.error({file.path, 1, 1}, "routh", fmt::format("Routh's reduction: {}", why.what()),
                          "name only cyclic coordinates: ones that L does not contain and no force or dissipation acts on");
      }
    } else if (diagnostics.empty()) {
      result.equations = derive_built_model(model, {file.path, file.method_where.line, file.method_where.column}, diagnostics);
      if (result.equations && !choice.variant.empty()) drop_undetermined(*result.equations, model, choice);
    }
  }
  result.diagnostics = std::move(diagnostics);
  return result;
}
}  // namespace

std::optional<Equations> derive_built_model(const Model& model, SourceLocation method_where, Diagnostics& diagnostics) {
  if (std::string refusal = method_refusal(model); !refusal.empty()) {
    diagnostics.error(method_where, "model.method", refusal);
    return std::nullopt;
  }
  DerivationDeadline deadline(method_where.file);
  try {
    derivation_stage("the kinematics");
    Mechanics mechanics = compute_mechanics(model);
    derivation_stage(model.method == "lagrange2"   ? "Lagrange's equations of the second kind"
                     : model.method == "lagrange1" ? "Lagrange's equations of the first kind"
                     : model.method == "appell"    ? "Appell's equations"
                                                   : "Hamilton's equations");
    Equations e = (*find_method(model.method))(model, mechanics);
    derivation_stage("the first integrals");
    e.first_integrals = find_first_integrals(e, mechanics);
    for (const BodyKinematics& b : mechanics.bodies) e.body_positions.push_back({b.name, b.position});
    e.drawing = drawn_bodies(model);
    e.gravity = model.gravity;
    e.scenes = model.scenes;
    e.variants_declared = model.variants;
    derivation_stage("the oriented trigonometric terms");
    orient(e);
    e.kinetic_energy_from_mass_matrix = kinetic_energy_is_quadratic_form(e);
    derivation_stage("the finished equations");
    return e;
  } catch (const UndeterminedVelocities& why) {
    diagnostics.error(method_where, "model.method", why.what(),
                      "remove a dependent constraint, or choose pseudo-velocities that, with the constraints, "
                      "determine every velocity");
    return std::nullopt;
  } catch (const std::invalid_argument& why) {
    // GiNaC's refusals (a polynomial operation on coefficients that are not rational had read as a
    // dependent constraint): a limit of the derivation, not a fault of the model
    diagnostics.error(method_where, "model.method", fmt::format("the symbolic derivation stopped: {}", why.what()),
                      "derive the model for another method meanwhile, and report this model file: the derivation "
                      "should not stop on it");
    return std::nullopt;
  } catch (const SingularJointDirection& why) {
    diagnostics.error(method_where, "model.method", why.what(),
                      "give the links this joint moves the mass and inertia they have (a URDF link its <inertial>): "
                      "without them, a joint below that turns about the same axis leaves this turn free");
    return std::nullopt;
  } catch (const std::domain_error& why) {
    // GiNaC's pole_error and the like: the model's expressions divide by zero or leave a function's
    // domain somewhere along the derivation (a singular position, a parameter that is 0)
    diagnostics.error(method_where, "model.method", fmt::format("the derivation divides by zero: {}", why.what()),
                      "check the model for a quantity that is identically zero where it divides (a position whose "
                      "derivative vanishes, a parameter set to 0, a degenerate rotation)");
    return std::nullopt;
  }
}

Derivation derive_model_file_for(const ModelFile& file, const ModelChoice& choice) {
  return derive(file, {}, {}, "", choice);
}

Derivation derive_model_file_for(const std::string& path, const ModelChoice& choice) {
  Diagnostics diagnostics;
  ModelFile file = parse_model_file(path, diagnostics);
  return derive(file, std::move(diagnostics), {}, "", choice);
}

Derivation derive_model_file(const std::string& path) {
  Diagnostics diagnostics;
  ModelFile file = parse_model_file(path, diagnostics);
  return derive(file, std::move(diagnostics));
}

Derivation derive_reduced_model_file(const std::string& path, const std::vector<std::string>& cyclic) {
  Diagnostics diagnostics;
  ModelFile file = parse_model_file(path, diagnostics);
  return derive(file, std::move(diagnostics), cyclic);
}

Derivation derive_model_file_as(const std::string& path, const std::string& method) {
  Diagnostics diagnostics;
  ModelFile file = parse_model_file(path, diagnostics);
  return derive(file, std::move(diagnostics), {}, method);
}

Derivation derive_model_text(const std::string& text, const std::string& path, const ModelChoice& choice) {
  Diagnostics diagnostics;
  ModelFile file = parse_model_text(text, path, diagnostics);
  return derive(file, std::move(diagnostics), {}, "", choice);
}

}  // namespace eomgen
