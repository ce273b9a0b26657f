#include "derive/methods.hpp"

#include <fmt/format.h>

#include "symbolic/simplify.hpp"

namespace eomgen {

std::vector<bool> cyclic_coordinates(const Equations& e) {
  std::vector<bool> cyclic;
  std::size_t n = e.forcing.size();
  for (std::size_t k = 0; k < n; ++k) {
    bool free = true;
    for (unsigned i = 0; i < n && free; ++i) {
      free = !e.forcing[i].has(e.symbols.coordinates[k]);
      for (unsigned j = 0; j < n && free; ++j) free = !e.mass_matrix(i, j).has(e.symbols.coordinates[k]);
    }
    cyclic.push_back(free);
  }
  return cyclic;
}

void add_linearization(Equations& e) {
  const Symbols& s = e.symbols;
  std::size_t n = e.forcing.size(), m = s.inputs.size();
  MotionSymbols motion = motion_symbols(s);
  e.linear_damping_gyroscopic = GiNaC::matrix(n, n);
  e.linear_stiffness_circulatory = GiNaC::matrix(n, n);
  e.linear_input = GiNaC::matrix(n, std::max<std::size_t>(m, 1));
  for (unsigned i = 0; i < n; ++i) {
    for (unsigned j = 0; j < n; ++j) {
      e.linear_damping_gyroscopic(i, j) = tidy(-e.forcing[i].diff(s.velocities[j]), motion);
      e.linear_stiffness_circulatory(i, j) = tidy(-e.forcing[i].diff(s.coordinates[j]), motion);
    }
    for (unsigned j = 0; j < m; ++j) e.linear_input(i, j) = tidy(e.forcing[i].diff(s.inputs[j]), motion);
  }
  e.has_linearization = true;
}

std::optional<DerivationMethod> find_method(const std::string& name) {
  if (name == "lagrange2") return &derive_lagrange2;
  if (name == "lagrange1") return &derive_lagrange1;
  if (name == "appell") return &derive_appell;
  return std::nullopt;
}

std::string method_refusal(const Model& model) {
  if (!find_method(model.method))
    return fmt::format("method \"{}\" is not available in this version of eomgen; use \"lagrange2\", "
                       "\"lagrange1\" (constraints with multipliers) or \"appell\" (pseudo-velocities)",
                       model.method);
  if (model.method == "lagrange2" && !model.constraints.empty()) {
    bool nonholonomic = false;
    for (const Constraint& c : model.constraints) nonholonomic = nonholonomic || !c.holonomic;
    return fmt::format("the model has {} constraint{}; Lagrange's equations of the second kind need independent "
                       "coordinates: use method = \"lagrange1\" (multipliers){}",
                       model.constraints.size(), model.constraints.size() == 1 ? "" : "s",
                       nonholonomic ? " or \"appell\" (pseudo-velocities)" : " or \"appell\"");
  }
  if (model.method != "appell" && !model.pseudo_velocities.empty())
    return "[pseudo_velocities] are used by Appell's equations: use method = \"appell\", or remove the section";
  if (model.constraints.size() >= model.symbols.coordinates.size())
    return fmt::format("{} constraints leave no degree of freedom of the {} coordinates", model.constraints.size(),
                       model.symbols.coordinates.size());
  return {};
}

}  // namespace eomgen
