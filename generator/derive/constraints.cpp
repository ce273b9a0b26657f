/// @file The constraints of a model at position, velocity and acceleration level
/// (Hiller §2.2): a holonomic g(q,t) = 0 gives C = ∂g/∂q, b = ∂g/∂t; a nonholonomic
/// a(q,t)·q' + b(q,t) = 0 gives C = a directly.
#include "derive/constraints.hpp"

#include "symbolic/gradient.hpp"

namespace eomgen {

using GiNaC::ex;

std::size_t ConstraintSet::num_holonomic() const {
  std::size_t count = 0;
  for (bool h : holonomic) count += h ? 1 : 0;
  return count;
}

ConstraintSet constraint_set(const Model& model, const MotionSymbols& motion) {
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
    ex velocity_level = k.holonomic ? time_derivative(k.expression, s) : k.expression;
    c.position.push_back(k.holonomic ? tidy(k.expression, motion) : ex(0));
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

}  // namespace eomgen
