/// @file Why no equilibrium exists, when the equations say so plainly: at rest, one velocity's
/// rate is the same number, not zero, in every configuration (a floating base falls with gravity
/// whatever its joints do, since nothing holds it; a block pushed by a constant force speeds up
/// wherever it is). Newton's search then only reports that it found nothing.
#pragma once

#include <optional>
#include <vector>

#include "simulation.hpp"

namespace eomgen::runtime {

struct UnbalancedRate {
  std::size_t velocity = 0;  // its index among the velocities
  double rate = 0;           // its rate, the same in every configuration tried (or its force: below)
  int configurations = 0;    // how many were tried
  /// the generalized force of its row of M q'' = f is that number, not its rate: a floating
  /// humanoid's joints swing as it falls, so its base's rate changes with the configuration, but
  /// the row of its base's vertical velocity is the momentum balance, f = −m g in every one
  bool force = false;
};

/// The velocity whose rate at rest, or else whose generalized force, is one number, beyond 1e-9 of
/// the largest seen, in
/// `start`'s configuration and in random ones about it (every coordinate moved by up to 1, 100, …
/// 1e12 times one of its units or its size, quaternions kept unit, so that a weak spring far away
/// shows too); nothing when no velocity's is, or when the model has constraints (a configuration
/// moved at random would break them).
std::optional<UnbalancedRate> unbalanced_rate(const Problem& problem, const std::vector<double>& start);

}  // namespace eomgen::runtime
