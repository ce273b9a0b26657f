/// @file How well a run kept the model's first integrals (the generalized energy,
/// the momenta of cyclic coordinates): in the exact motion they stay at their
/// initial values, so their change is the integration error.
#pragma once

#include <string>
#include <vector>

#include "simulation.hpp"

namespace eomgen::runtime {

struct FirstIntegralDrift {
  std::string name;
  double initial = 0;
  double largest_change = 0;    // max |I(t) − I(0)| over the output times; inf when a value is not finite
  double relative_change = 0;   // largest_change / |I(0)|, or NaN when I(0) = 0
};

/// One entry per first integral of the model, in first_integral_names order, over every row of the run.
std::vector<FirstIntegralDrift> first_integral_drift(const eomgen_model_abi& model, const RunSummary& run);

/// Whether T + V is conserved at these parameter values with the inputs at zero, though the
/// model file has dissipation or forces (a damping parameter set to 0): its rate along the flow,
/// Σ ∂E/∂x_i x_i' + ∂E/∂t by central differences, vanishes against the size of its terms at x
/// and at states with random velocities about it.
bool energy_conserved_at(const Problem& problem, double t, const std::vector<double>& x);

}  // namespace eomgen::runtime
