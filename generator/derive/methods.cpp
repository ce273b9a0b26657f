#include "derive/methods.hpp"
#include "spatial/joint_velocities.hpp"

#include <fmt/format.h>

#include "symbolic/gradient.hpp"
#include "symbolic/simplify.hpp"

namespace eomgen {

const std::vector<GiNaC::symbol>& Equations::acceleration_symbols() const {
  static const std::vector<GiNaC::symbol> none;
  if (const NewtonEulerRecursion* recursion = newton_euler()) return recursion->acceleration_symbols;
  if (const ArticulatedForwardDynamics* tree = articulated()) return tree->acceleration_symbols;
  return none;
}

void take_newton_euler_recursion(const Mechanics& mech, Equations& e) {
  if (mech.inverse_dynamics.empty()) return;
  e.dynamics = NewtonEulerRecursion{mech.acceleration_symbols, mech.acceleration_intermediates, mech.inverse_dynamics,
                                    mech.bodies_gradient, std::nullopt};
}

void Equations::solve_by_mass_matrix() {
  if (articulated()) dynamics = std::monostate{};
  if (NewtonEulerRecursion* recursion = newton_euler()) recursion->joint_tree_accelerations.reset();
}

SymbolDependence::SymbolDependence(const std::vector<Intermediate>& intermediates) {
  for (const Intermediate& i : intermediates) {
    GiNaC::exset mine;
    add(i.definition, mine);
    of_[i.symbol] = std::move(mine);
  }
}

void SymbolDependence::add(const GiNaC::ex& x, GiNaC::exset& out) const {
  GiNaC::exset used;
  collect_symbols(x, used);
  for (const GiNaC::ex& s : used) {
    auto found = of_.find(s);
    if (found == of_.end()) out.insert(s);
    else out.insert(found->second.begin(), found->second.end());
  }
}

// Cyclic: no equation depends on the coordinate. With Appell's equations that includes
// the kinematic equations of the coordinates that are not cyclic themselves, and with
// Lagrange I the constraints (the multipliers depend on them).
std::vector<bool> cyclic_coordinates(const Equations& e) {
  std::size_t n = e.symbols.num_coordinates(), k = e.forcing.size();
  const ConstraintSet& c = e.constraints;
  std::vector<bool> cyclic;
  if (!e.intermediates.empty()) {
    // recursive kinematics (Lagrange II): what M and f depend on, through the intermediates
    SymbolDependence dependence(e.intermediates);
    GiNaC::exset used;
    for (unsigned i = 0; i < k; ++i) {
      dependence.add(e.forcing[i], used);
      for (unsigned j = 0; j < k; ++j) dependence.add(e.mass_matrix(i, j), used);
    }
    for (std::size_t q = 0; q < n; ++q) cyclic.push_back(!used.count(e.symbols.coordinates[q]));
    return cyclic;
  }
  for (std::size_t q = 0; q < n; ++q) {
    const auto& x = e.symbols.coordinates[q];
    bool free = true;
    for (unsigned i = 0; i < k && free; ++i) {
      free = !e.forcing[i].has(x);
      for (unsigned j = 0; j < k && free; ++j) free = !e.mass_matrix(i, j).has(x);
    }
    // Hamilton's equations in mass-matrix form: der(q) follows from M der(q) = p − b
    for (unsigned i = 0; e.momentum() && i < e.momentum()->bias.size() && free; ++i) {
      free = !e.momentum()->bias[i].has(x);
      for (unsigned j = 0; j < e.momentum()->bias.size() && free; ++j) free = !e.momentum()->mass_matrix(i, j).has(x);
    }
    for (unsigned i = 0; e.has_multipliers && i < c.size() && free; ++i) {
      free = !c.position[i].has(x) && !c.bias[i].has(x) && !c.acceleration_bias[i].has(x);
      for (unsigned j = 0; j < n && free; ++j) free = !c.jacobian(i, j).has(x);
    }
    cyclic.push_back(free);
  }
  for (bool changed = true; changed && e.uses_pseudo_velocities();) {
    changed = false;
    for (std::size_t q = 0; q < n; ++q)
      for (std::size_t j = 0; j < n && cyclic[q]; ++j)
        if (!cyclic[j] && e.coordinate_rates[j].has(e.symbols.coordinates[q])) cyclic[q] = false, changed = true;
  }
  return cyclic;
}

void add_linearization(Equations& e) {
  const Symbols& s = e.symbols;
  std::size_t n = e.forcing.size(), nq = s.num_coordinates(), m = s.inputs.size();
  MotionSymbols motion = motion_symbols(s);
  e.linear_damping_gyroscopic = GiNaC::matrix(n, n);
  e.linear_stiffness_circulatory = GiNaC::matrix(n, nq);
  e.linear_input = GiNaC::matrix(n, std::max<std::size_t>(m, 1));
  for (unsigned i = 0; i < n; ++i) {
    for (unsigned j = 0; j < n; ++j) e.linear_damping_gyroscopic(i, j) = tidy(-e.forcing[i].diff(s.velocities[j]), motion);
    for (unsigned j = 0; j < nq; ++j) e.linear_stiffness_circulatory(i, j) = tidy(-e.forcing[i].diff(s.coordinates[j]), motion);
    for (unsigned j = 0; j < m; ++j) e.linear_input(i, j) = tidy(e.forcing[i].diff(s.inputs[j]), motion);
  }
  e.has_linearization = true;
}

std::optional<DerivationMethod> find_method(const std::string& name) {
  if (name == "lagrange2") return &derive_lagrange2;
  if (name == "lagrange1") return &derive_lagrange1;
  if (name == "appell") return &derive_appell;
  if (name == "hamilton") return &derive_hamilton;
  return std::nullopt;
}

std::string method_refusal(const Model& model) {
  if (!find_method(model.method))
    return fmt::format("method \"{}\" is not available in this version of eomgen; use \"lagrange2\", "
                       "\"lagrange1\" (constraints with multipliers), \"appell\" (pseudo-velocities) or \"hamilton\"",
                       model.method);
  if (model.recursive_kinematics && model.method != "lagrange2" && model.method != "lagrange1" && !has_spherical_joints(model))
    return fmt::format("frames derived link by link give Lagrange's equations of the second kind or of the first "
                       "kind only, not method \"{}\": use method = \"lagrange2\" or \"lagrange1\"",
                       model.method);
  if (model.method == "hamilton" && !model.constraints.empty())
    return "Hamilton's canonical equations here need independent coordinates and no constraints: use method = "
           "\"lagrange1\" (multipliers) or \"appell\" (pseudo-velocities) for a constrained system";
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
