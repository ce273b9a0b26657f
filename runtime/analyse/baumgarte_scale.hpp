/// @file Baumgarte's gains against the system's own rate. The gains are rates in 1/s (the model's
/// 10 unless given), so a model scaled in time keeps them while its motion speeds up or slows
/// down: a Cartesian pendulum whose period is 2e12 s corrected a constraint error 3e12 times faster
/// than it swung, and BDF at rtol 1e-10 gave up after swinging it over the top.
#pragma once

#include <vector>

#include "simulation.hpp"

namespace eomgen::runtime {

/// The larger of the gains alpha and beta over the system's rate at x: the spectral scale of the
/// balanced Jacobian without Baumgarte's terms (system_scales.hpp); 1 where the gains are zero or
/// the rate is not known (zero or not finite).
double baumgarte_gain_ratio(const Problem& problem, const std::vector<double>& x, double alpha, double beta);

}  // namespace eomgen::runtime
