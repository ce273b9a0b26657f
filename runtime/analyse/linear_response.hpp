/// @file Responses of x' = A x + B u by the variation-of-constants formula (Hiller
/// §6.2.4), x(t) = Φ(t) x0 + ∫₀ᵗ Φ(t − τ) B u(τ) dτ, evaluated exactly (up to the
/// matrix exponential) by augmenting A with the system that generates u: nothing for
/// an impulse, a constant for a step, a rotation for sin(ωt).
#pragma once

#include <vector>

#include <Eigen/Dense>

namespace eomgen::runtime {

enum class Excitation { initial, impulse, step, harmonic };

struct ResponseRequest {
  Excitation kind = Excitation::initial;
  Eigen::Index input = 0;  // the input that is excited (not for `initial`)
  double omega = 0;        // u = sin(ω t) for `harmonic`
  Eigen::VectorXd x0;      // the initial deviation from the equilibrium
  double t_end = 10, dt_out = 0.01;
};

struct LinearResponse {
  std::vector<double> times;          // multiples of dt_out and t_end
  std::vector<Eigen::VectorXd> states;
};

/// Unit impulse (x(0⁺) = x0 + B e_j), unit step (u = 1 for t ≥ 0) or u = sin(ωt) in input j.
LinearResponse linear_response(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const ResponseRequest& request);

}  // namespace eomgen::runtime
