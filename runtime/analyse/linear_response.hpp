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
  double omega = 0;        // u = amplitude·sin(ω t + phase) for `harmonic`
  double amplitude = 1;    // of the impulse, step or sine
  double start = 0;        // when the impulse or step comes (t ≥ 0)
  double phase = 0;        // of the sine: π/2 makes it a cosine
  Eigen::VectorXd x0;      // the initial deviation from the equilibrium
  double t_end = 10, dt_out = 0.01;
};

struct LinearResponse {
  std::vector<double> times;          // multiples of dt_out and t_end
  std::vector<Eigen::VectorXd> states;
};

/// An impulse (x jumps by amplitude·B e_j at `start`), a step (u = amplitude for t ≥ start)
/// or u = amplitude·sin(ωt + phase) in input j, on top of the free motion from x0.
LinearResponse linear_response(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const ResponseRequest& request);

}  // namespace eomgen::runtime
