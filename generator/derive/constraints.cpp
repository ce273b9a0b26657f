/// @file The constraints of a model at position, velocity and acceleration level
/// (Hiller §2.2): a holonomic g(q,t) = 0 gives C = ∂g/∂q, b = ∂g/∂t; a nonholonomic
/// a(q,t)·q' + b(q,t) = 0 gives C = a directly.
#include "derive/constraints.hpp"

#include "common/independent_rows.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "derive/state_values.hpp"
#include "symbolic/gradient.hpp"

namespace eomgen {

using GiNaC::ex;

std::size_t ConstraintSet::num_holonomic() const {
  std::size_t count = 0;
  for (bool h : holonomic) count += h ? 1 : 0;
  return count;
}

ConstraintSet constraint_set(const Model& model, const Mechanics& mechanics) {
  const MotionSymbols& motion = mechanics.motion;
  const Symbols& s = model.symbols;
  std::size_t n = s.coordinates.size(), m = model.constraints.size();
  ConstraintSet c;
  c.jacobian = GiNaC::matrix(m, n);
  std::vector<ex> coordinates(s.coordinates.begin(), s.coordinates.end());
  GiNaC::exmap at_rest;
  for (const auto& v : s.velocities) at_rest[v] = 0;
  for (unsigned i = 0; i < m; ++i) {
    const Constraint& k = model.constraints[i];
    c.names.push_back(k.name);
    c.holonomic.push_back(k.holonomic);
    c.position.push_back(k.holonomic ? tidy(k.expression, motion) : ex(0));
    if (!mechanics.constraint_terms.empty()) {
      const ConstraintTerms& t = mechanics.constraint_terms[i];
      for (unsigned j = 0; j < n; ++j) c.jacobian(i, j) = tidy(t.jacobian[j], motion);
      c.bias.push_back(tidy(t.bias, motion));
      c.acceleration_bias.push_back(tidy(t.acceleration_bias, motion));
      continue;
    }
    ex velocity_level = k.holonomic ? time_derivative(k.expression, s) : k.expression;
    for (unsigned j = 0; j < n; ++j) c.jacobian(i, j) = tidy(velocity_level.diff(s.velocities[j]), motion);
    c.bias.push_back(tidy(velocity_level.subs(at_rest), motion));
    // d/dt (C q' + b) without the C q'' part: the velocity-level residual is linear in q',
    // so its total derivative along q and t is exactly that
    c.acceleration_bias.push_back(tidy(time_derivative(velocity_level, s), motion));
  }
  return c;
}

bool constraints_scleronomic(const ConstraintSet& c, const Symbols& s) {
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (!c.bias[i].is_zero() || c.position[i].has(s.time)) return false;
    for (unsigned j = 0; j < c.jacobian.cols(); ++j)
      if (c.jacobian(i, j).has(s.time)) return false;
  }
  return true;
}

double initial_value(const GiNaC::ex& e, const Symbols& s, const std::vector<Intermediate>& intermediates) {
  return StateValues::initial(s, intermediates)(e);
}

std::vector<std::string> dependent_constraints(const ConstraintSet& c, const Symbols& s,
                                               const std::vector<Intermediate>& intermediates) {
  // the rows of C in file order: a row (nearly) in the span of the rows before it adds no restriction
  IndependentRows rows;
  std::vector<std::string> dependent;
  StateValues initial = StateValues::initial(s, intermediates);
  for (unsigned i = 0; i < c.size(); ++i) {
    std::vector<double> row;
    for (unsigned j = 0; j < c.jacobian.cols(); ++j) row.push_back(initial(c.jacobian(i, j)));
    if (!rows.add(row)) dependent.push_back(c.names[i]);
  }
  return dependent;
}

void require_independent(const ConstraintSet& c, const Symbols& s, const std::vector<Intermediate>& intermediates) {
  std::vector<std::string> dependent = dependent_constraints(c, s, intermediates);
  if (dependent.empty()) return;
  std::string names;
  for (const std::string& d : dependent) names += (names.empty() ? "'" : ", '") + d + "'";
  throw UndeterminedVelocities(fmt::format(
      "the constraint Jacobian does not have full rank at the initial state: {} depend{} on the constraints before "
      "{} in the file, so the model has more degrees of freedom than {} coordinates minus {} constraints",
      names, dependent.size() == 1 ? "s" : "", dependent.size() == 1 ? "it" : "them", s.coordinates.size(), c.size()));
}

}  // namespace eomgen
