/// @file Pseudo-velocities s = Y(q,t)·q' + y(q,t) (Hiller §4.3) and the kinematic
/// equations q' = W(q,t)·s + w(q,t) that follow from them and the constraints.
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "derive/equations.hpp"
#include "symbolic/simplify.hpp"

namespace eomgen {

struct PseudoVelocities {
  std::vector<GiNaC::realsymbol> symbols;  // s
  std::vector<NamedSymbolic> definitions;  // s = Y q' + y, as given or chosen
  std::vector<GiNaC::ex> coordinate_rates;  // q' = W s + w, one per coordinate
  std::vector<double> initial_values;       // s at the model's initial state
};

/// The model's [pseudo_velocities], or, when it has none, the velocities of a set
/// of independent coordinates: the first set, in file order, whose complement the
/// constraints determine at the initial state. A mistake is returned as text.
std::variant<PseudoVelocities, std::string> pseudo_velocities(const Model& model, const ConstraintSet& constraints,
                                                               const MotionSymbols& motion);

}  // namespace eomgen
