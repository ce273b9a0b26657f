/// @file Stability conditions in closed form (Hiller §7.3–7.4): the
/// characteristic polynomial of the linearization with chosen parameters kept
/// as symbols, and the Hurwitz conditions as inequalities in them.
#pragma once

#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "derive/equations.hpp"

namespace eomgen {

struct StabilityConditions {
  std::vector<std::string> kept;                  // the parameters kept as symbols
  std::vector<std::string> equilibrium_unknowns;  // coordinates/velocities left symbolic because the equilibrium moves
  std::vector<GiNaC::ex> equilibrium_equations;   // = 0, when it does
  GiNaC::ex characteristic_polynomial;            // in `lambda`
  GiNaC::symbol lambda{"lambda"};
  std::vector<GiNaC::ex> conditions;              // each expression > 0 (necessary and sufficient together)
  /// Conditions that vanish identically ("the coefficient of lambda^0", "the Hurwitz
  /// determinant Delta_2"): then no values make the first method decide, at best marginal.
  std::vector<std::string> vanishing;
  /// Kept parameters that appear neither in the polynomial nor in the equilibrium's
  /// equations (one that sets only the initial state was taken at its value): conditions
  /// cannot be stated in them.
  std::vector<std::string> absent;
};

/// `parameters` and `inputs` give every value (kept ones are replaced by their
/// symbols); `state` is the numeric equilibrium x = [q; q'] at those values.
/// Parameters are taken as positive when conditions are simplified.
StabilityConditions stability_conditions(const Equations& equations, const std::vector<std::string>& kept,
                                         const std::vector<double>& parameters, const std::vector<double>& inputs,
                                         const std::vector<double>& state);

/// A double as the exact rational of its decimal form with `digits` significant digits
/// (0: the shortest form that reads back as the same double; 9.81 → 981/100).
GiNaC::numeric exact_number(double value, int digits = 0);

/// Non-integer numbers of `e` as decimals with `digits` significant digits, for printing.
GiNaC::ex rounded_for_display(const GiNaC::ex& e, int digits = 6);

}  // namespace eomgen
