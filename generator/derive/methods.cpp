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
  return std::nullopt;
}

std::string method_refusal(const Model& model) {
  if (!model.constraints.empty()) {
    bool nonholonomic = false;
    for (const Constraint& c : model.constraints) nonholonomic = nonholonomic || !c.holonomic;
    return fmt::format(
        "the model has {} constraint{}; constrained systems are derived by method = \"lagrange1\"{}, "
        "which this version of eomgen does not have yet",
        model.constraints.size(), model.constraints.size() == 1 ? "" : "s",
        nonholonomic ? " or \"appell\"" : "");
  }
  if (!model.pseudo_velocities.empty())
    return "[pseudo_velocities] are used by method = \"appell\", which this version of eomgen does not have yet";
  if (!find_method(model.method))
    return fmt::format("method \"{}\" is not available in this version of eomgen; use method = \"lagrange2\"",
                       model.method);
  return {};
}

}  // namespace eomgen
