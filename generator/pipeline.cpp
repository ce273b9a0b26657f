#include "pipeline.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "derive/first_integrals.hpp"
#include "derive/methods.hpp"
#include "derive/routh.hpp"
#include "kinematics/mechanics.hpp"
#include "parse/model_file.hpp"
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
  for (GiNaC::ex& x : e.momentum_bias) each(x);
  for (unsigned i = 0; i < e.momentum_mass_matrix.rows(); ++i)
    for (unsigned j = 0; j < e.momentum_mass_matrix.cols(); ++j) each(e.momentum_mass_matrix(i, j));
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

// `reduce`: the cyclic coordinates Routh's reduction eliminates, whatever the model's method;
// `method`: the method to use instead of the model's
Derivation derive(const ModelFile& file, Diagnostics diagnostics, const std::vector<std::string>& reduce = {},
                  const std::string& method = "") {
  Derivation result;
  if (diagnostics.empty()) {
    Model model = build_model(file, diagnostics);
    if (!method.empty()) model.method = method;
    if (diagnostics.empty() && !reduce.empty()) {
      try {
        result.equations = derive_routh(model, compute_mechanics(model), reduce);
        orient(*result.equations);
      } catch (const std::invalid_argument& why) {
        diagnostics.error({file.path, 1, 1}, "routh", fmt::format("Routh's reduction: {}", why.what()),
                          "name only cyclic coordinates: ones that L does not contain and no force or dissipation acts on");
      }
    } else if (diagnostics.empty()) {
      if (std::string refusal = method_refusal(model); !refusal.empty()) {
        diagnostics.error({file.path, file.method_where.line, file.method_where.column}, "model.method", refusal);
      } else {
        Mechanics mechanics = compute_mechanics(model);
        try {
          result.equations = (*find_method(model.method))(model, mechanics);
          result.equations->first_integrals = find_first_integrals(*result.equations, mechanics);
          for (const BodyKinematics& b : mechanics.bodies) result.equations->body_positions.push_back({b.name, b.position});
          orient(*result.equations);
        } catch (const std::invalid_argument& why) {
          diagnostics.error({file.path, file.method_where.line, file.method_where.column}, "model.method", why.what(),
                            "remove a dependent constraint, or choose pseudo-velocities that, with the constraints, "
                            "determine every velocity");
        }
      }
    }
  }
  result.diagnostics = std::move(diagnostics);
  return result;
}
}  // namespace

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

Derivation derive_model_text(const std::string& text, const std::string& path) {
  Diagnostics diagnostics;
  ModelFile file = parse_model_text(text, path, diagnostics);
  return derive(file, std::move(diagnostics));
}

}  // namespace eomgen
