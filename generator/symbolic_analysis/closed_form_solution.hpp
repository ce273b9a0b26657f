/// @file The linearized system solved in closed form (Hiller §6.2, §6.4): the fundamental
/// matrix Φ(t) = e^{At} = L⁻¹{(sI − A)⁻¹} by partial fractions of each entry of the
/// resolvent, and the transfer functions G(s) = C (sI − A)⁻¹ B + D, for exact A whose
/// characteristic polynomial factors into linear and quadratic factors.
#pragma once

#include <string>
#include <vector>

#include <ginac/ginac.h>

namespace eomgen {

struct ClosedFormSolution {
  std::string refusal;                  // why there is no closed form, or empty
  GiNaC::symbol t{"t"}, s{"s"};
  GiNaC::matrix fundamental;            // Φ(t)
  GiNaC::matrix transfer;               // G(s), each entry factored
  std::vector<std::string> conditions;  // where the form holds, e.g. "k/m - Omega^2 > 0"
};

/// `values`: the exact value of each symbol in A, B, C, D, which decides whether a quadratic
/// factor has complex roots (sin, cos) or real ones (sinh, cosh); B, C, D may be empty.
ClosedFormSolution closed_form_solution(const GiNaC::matrix& A, const GiNaC::matrix& B, const GiNaC::matrix& C,
                                        const GiNaC::matrix& D, const GiNaC::exmap& values);

}  // namespace eomgen
