/// @file Checking a solution of the Hamilton–Jacobi equation (Hiller §3.8.5):
/// ∂S/∂t + H(q, ∂S/∂q, t) = 0 for a given S(q, α, t), symbolically where GiNaC
/// brings the residual to zero, else at random points.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "derive/equations.hpp"

namespace eomgen {

struct HamiltonJacobiCheck {
  GiNaC::ex action;                    // S
  std::vector<std::string> constants;  // the identifiers of S that are not the model's: α
  std::vector<NamedSymbolic> momenta;  // p_q = ∂S/∂q
  GiNaC::ex residual;                  // ∂S/∂t + H(q, ∂S/∂q, t), simplified
  bool symbolic = false;               // the residual simplified to 0
  int points = 0;                      // random points where it was evaluated (when not symbolic)
  double largest_relative_residual = 0;  // |residual| / (|∂S/∂t| + |H|) over those points
  std::string failure;                 // where it fails; empty when it holds
  bool holds() const { return failure.empty(); }
};

/// Checks S, written in `text` (GiNaC syntax; `#` starts a comment) over the coordinates,
/// parameters, t and constants of its own, against the Hamiltonian of `hamilton` (derived
/// by method "hamilton"). Mistakes in S and nonconservative models go to `diagnostics`.
std::optional<HamiltonJacobiCheck> check_hamilton_jacobi(const Equations& hamilton, const std::string& text,
                                                         const std::string& path, Diagnostics& diagnostics);

}  // namespace eomgen
