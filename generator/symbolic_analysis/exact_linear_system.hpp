/// @file The linearized system x' = A x + B u, y = C x + D u of Lagrange II equations
/// about a state, in exact arithmetic (Hiller §5.3, §6): A = [[0, I], [−M⁻¹Q, −M⁻¹P]],
/// B = [[0], [M⁻¹B_q]]. Either at the given values (rational where written as decimals:
/// 0.1 is 1/10) or with the parameters kept as symbols, positive where their values are.
#pragma once

#include <string>
#include <vector>

#include "derive/equations.hpp"

namespace eomgen {

struct ExactLinearSystem {
  std::string refusal;           // why the system has no exact form, or empty
  bool in_parameters = false;    // the parameters are symbols (then rational functions of them)
  GiNaC::matrix A, B, C, D;      // state: the coordinates, then the velocities; B only with inputs
  GiNaC::exmap parameter_values; // each parameter symbol of A, B, C, D → its exact value
  std::vector<std::string> assumptions;  // "n > 0" for each parameter taken positive
};

/// `outputs`: the state or [outputs] names of the rows of C and D (may be empty).
ExactLinearSystem exact_linear_system(const Equations& equations, const std::vector<double>& parameters,
                                      const std::vector<double>& inputs, const std::vector<double>& state,
                                      bool keep_parameters, const std::vector<std::string>& outputs = {});

/// The exact value A entry by entry (the parameters replaced by their values).
GiNaC::matrix at_values(const GiNaC::matrix& X, const GiNaC::exmap& values);

}  // namespace eomgen
