/// @file Whether a run's output interval can follow the motion it records. The default interval,
/// 0.01 s, is a choice in seconds: it follows a pendulum and skips a MEMS resonator's 1e5 rad/s
/// 160 periods at a time, so that the rows look like a slow motion that is not there (aliasing).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "simulation.hpp"

namespace eomgen::runtime {

/// The period of the fastest oscillation at (t, x): 2π over the largest imaginary part of the
/// rhs's Jacobian's eigenvalues (balanced; imaginary parts within rounding of the real axis left
/// out); infinite when nothing oscillates.
double fastest_period(const Problem& problem, double t, const std::vector<double>& x);

/// A warning when dt_out is longer than half that period (below two rows a period, no output can
/// show the oscillation), with the interval that gives twenty rows a period; nothing otherwise.
std::optional<std::string> aliasing_warning(const Problem& problem, double t, const std::vector<double>& x, double dt_out);

}  // namespace eomgen::runtime
