/// @file Stability of an equilibrium of a periodically time-dependent system
/// x' = F(t, x), F(t + T, x) = F(t, x) (a driven support, a parametric excitation):
/// Floquet theory. The variational equations Φ' = A(t) Φ, A = ∂F/∂x from the
/// generated jacobian_state, Φ(0) = I, give the monodromy matrix Φ(T); its
/// eigenvalues, the Floquet multipliers, decide: all |μ| < 1 asymptotically stable,
/// one |μ| > 1 unstable, |μ| = 1 semisimple marginally stable. The autonomous
/// analysis at frozen t is wrong for such systems (the Kapitza pendulum).
#pragma once

#include <complex>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "simulation.hpp"

namespace eomgen::runtime {

struct FloquetReport {
  double period = 0;
  std::vector<std::string> state_names;          // the reduced state (cyclic positions dropped)
  Eigen::MatrixXd monodromy;                     // Φ(T)
  std::vector<std::complex<double>> multipliers;  // by decreasing modulus
  double error_estimate = 0;                     // of Φ(T), from the step-halving difference
  long steps_per_period = 0;
  int cyclic_unit_multipliers = 0;               // μ = 1 of conserved cyclic momenta, left out
  std::string verdict;                           // asymptotically_stable | marginally_stable | unstable | undecided
  std::string reason;                            // what decided, or why it cannot be decided
};

/// Largest |F(t, x)| over the reduced state at 64 times in one period: zero for an
/// equilibrium of the periodic system.
double periodic_equilibrium_residual(const Problem& p, const std::vector<double>& x, double period);

/// Largest |A(t + T) − A(t)| relative to |A| at 16 times in [0, T), A balanced by one diagonal
/// scaling (system_scales.hpp): zero when the linearized equations at x are periodic with period T.
double periodicity_defect(const Problem& p, const std::vector<double>& x, double period);

/// The Floquet analysis of the equilibrium x over one period.
FloquetReport floquet_analysis(const Problem& p, const std::vector<double>& x, double period);

}  // namespace eomgen::runtime
