/// @file Lyapunov's critical case (Hiller §7.5): when the linearization has eigenvalues
/// on the imaginary axis and none to the right, the first approximation decides
/// nothing about the nonlinear system. Two checks take its place: the energy function
/// (Lagrange–Dirichlet: T + V with a strict minimum of V at an equilibrium at rest of a
/// conservative system proves stability), and a long simulation of the nonlinear model
/// from small perturbations.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "analyse/linear_stability.hpp"
#include "simulation.hpp"

namespace eomgen::runtime {

struct CriticalCase {
  bool critical = false;         // the first approximation is inconclusive
  std::string energy;            // what the energy function shows, or why it does not apply
  std::string simulation;        // what the perturbed runs showed (empty when not needed)
  std::string nonlinear_verdict;  // stable | unstable | undecided
};

/// The checks above, for the equilibrium x with its linear report; `progress` (may be empty) is
/// told (done, total) after each perturbed run, which on a model of many states may take minutes.
CriticalCase check_critical_case(const Problem& problem, const std::vector<double>& x, const StabilityReport& linear,
                                 const std::function<void(long, long)>& progress = nullptr);

}  // namespace eomgen::runtime
