// RunSummary::add: the running maxima of a run's report, row by row (simulation.hpp).
#include <algorithm>
#include <cmath>

#include "simulation.hpp"

namespace eomgen::runtime {

namespace {

// max |v − v0|, infinite once v is not finite
double largest_change(double largest, double v, double v0) { return std::isfinite(v) ? std::max(largest, std::abs(v - v0)) : INFINITY; }

}  // namespace

void RunSummary::add(const Trajectory& tr, std::size_t k) {
  if (rows++ == 0) {
    first_time = tr.times[k], first_state = tr.states[k], first_energy = tr.energies[k];
    first_integrals = tr.first_integrals[k];
    largest_integral_changes.assign(first_integrals.size(), 0.0);
    if (k < tr.multipliers.size()) largest_multipliers.assign(tr.multipliers[k].size(), 0.0);
  }
  last_time = tr.times[k], last_state = tr.states[k];
  largest_energy_change = largest_change(largest_energy_change, tr.energies[k], first_energy);
  for (std::size_t i = 0; i < first_integrals.size(); ++i)
    largest_integral_changes[i] = largest_change(largest_integral_changes[i], tr.first_integrals[k][i], first_integrals[i]);
  if (k < tr.multipliers.size())
    for (std::size_t i = 0; i < largest_multipliers.size(); ++i)
      largest_multipliers[i] = std::max(largest_multipliers[i], std::abs(tr.multipliers[k][i]));
  if (k < tr.position_residuals.size()) {
    largest_position_residual = std::max(largest_position_residual, tr.position_residuals[k]);
    largest_velocity_residual = std::max(largest_velocity_residual, tr.velocity_residuals[k]);
  }
}

}  // namespace eomgen::runtime
