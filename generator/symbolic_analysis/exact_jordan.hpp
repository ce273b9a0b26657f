/// @file The Jordan structure of the linearized system decided by exact arithmetic
/// (Hiller §6.3), when A is rational: rational parameter values (as written, 0.1 is
/// 1/10), a rational equilibrium and functions that are rational there (cos 0 = 1).
#pragma once

#include <complex>
#include <string>
#include <vector>

#include "derive/equations.hpp"

namespace eomgen {

/// One irreducible factor f of the characteristic polynomial over the rationals, f^multiplicity:
/// every root of f has algebraic multiplicity `multiplicity` and the same Jordan blocks.
struct ExactFactor {
  GiNaC::ex polynomial;  // f(lambda), monic
  int degree = 0, multiplicity = 0;
  std::vector<int> jordan_blocks;  // sizes for each root, largest first
};

struct ExactJordan {
  std::string refusal;  // why A is not exact, or empty
  GiNaC::symbol lambda{"lambda"};
  std::vector<ExactFactor> factors;
};

/// A = [[0, I], [−M⁻¹Q, −M⁻¹P]] of Lagrange II equations at the state x with the given
/// values; dim ker f(A)^k = deg f · Σ_blocks min(size, k) gives the blocks of f's roots.
ExactJordan exact_jordan_structure(const Equations& equations, const std::vector<double>& parameters,
                                   const std::vector<double>& inputs, const std::vector<double>& state);

/// The factor whose root z is, within 1e-6 of the size of its terms; nullptr if none.
const ExactFactor* factor_of(const ExactJordan& exact, std::complex<double> z);

}  // namespace eomgen
