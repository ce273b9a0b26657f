/// @file Values of expressions at one state of a model, in double precision: its coordinates,
/// velocities, inputs and time given, the parameters at their defaults, and the intermediates of
/// recursive kinematics each evaluated once, when an expression asked first needs it (a check of
/// T and M needs a tree's kinematics and inertias, not its gradient's thousands of quantities).
#pragma once

#include <map>
#include <vector>

#include <ginac/ginac.h>

#include "model/model.hpp"

namespace eomgen {

class StateValues {
 public:
  StateValues(const Symbols& symbols, const std::vector<Intermediate>& intermediates, const std::vector<double>& coordinates,
              const std::vector<double>& velocities, const std::vector<double>& inputs, double time);
  /// The model's initial state, its default inputs and t = 0.
  static StateValues initial(const Symbols& symbols, const std::vector<Intermediate>& intermediates);
  /// A state where each coordinate and velocity has a value of its own, inputs zero (`seed` picks
  /// one of several): for checking an identity at a point no model is likely to single out.
  static StateValues spread(const Symbols& symbols, const std::vector<Intermediate>& intermediates, int seed);
  /// The value of x; NaN when it has a symbol that is none of the model's nor an intermediate.
  double operator()(const GiNaC::ex& x) const;

 private:
  double value_of(const GiNaC::symbol& symbol) const;
  mutable std::map<GiNaC::ex, double, GiNaC::ex_is_less> known_;  // and the intermediates evaluated so far
  std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less> definitions_;
};

}  // namespace eomgen
