/// @file `linear --symbolic`: the linearized system solved in closed form, in the
/// parameters where the characteristic polynomial factors into linear and quadratic
/// factors over them (as Hiller's rendezvous solution in the orbit rate, §6.4), and
/// otherwise at the parameters' exact values.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "symbolic_analysis/closed_form_solution.hpp"
#include "symbolic_analysis/exact_linear_system.hpp"

namespace eomgen {

struct LinearClosedForm {
  std::string refusal;            // why there is no closed form at all, or empty
  std::string parameter_refusal;  // why not in the parameters, when at the values
  ExactLinearSystem system;
  ClosedFormSolution solution;
  bool in_parameters() const { return refusal.empty() && parameter_refusal.empty(); }
};

/// `outputs`: the rows of C, D and of the transfer functions (states or [outputs] names).
LinearClosedForm linear_closed_form(const Equations& equations, const std::vector<double>& parameters,
                                    const std::vector<double>& inputs, const std::vector<double>& state,
                                    const std::vector<std::string>& outputs);

}  // namespace eomgen
