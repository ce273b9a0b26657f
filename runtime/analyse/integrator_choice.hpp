/// @file The integrator a model needs when the user names none: constrained models keep
/// BDF with projection, stiff ones (fast decay beside slow motion) get BDF, and the rest
/// an explicit method of order 5, which is far more accurate per evaluation than BDF
/// and keeps the energy error of a conservative oscillator small.
#pragma once

#include <string>
#include <vector>

#include "simulation.hpp"

namespace eomgen::runtime {

struct IntegratorChoice {
  std::string integrator;
  std::string reason;  // for the user: why this one
};

/// Chooses from the model and its Jacobian at (t0, x0).
IntegratorChoice choose_integrator(const Problem& problem, const std::vector<double>& x0, double t0);

}  // namespace eomgen::runtime
