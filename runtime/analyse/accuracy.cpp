#include "analyse/accuracy.hpp"

#include <algorithm>
#include <cmath>

namespace eomgen::runtime {

double trajectory_error(const std::vector<std::vector<double>>& states, const std::vector<std::vector<double>>& reference) {
  if (reference.empty()) return NAN;
  std::size_t n = reference.front().size();
  std::vector<double> scale(n, 0.0);
  double largest = 0;
  for (const auto& row : reference)
    for (std::size_t i = 0; i < n; ++i) {
      scale[i] = std::max(scale[i], std::abs(row[i]));
      largest = std::max(largest, std::abs(row[i]));
    }
  for (double& s : scale) s = std::max({s, 1e-3 * largest, 1e-300});
  double worst = 0;
  for (std::size_t k = 0; k < std::min(states.size(), reference.size()); ++k)
    for (std::size_t i = 0; i < n; ++i) {
      double e = std::abs(states[k][i] - reference[k][i]) / scale[i];
      if (!std::isfinite(e)) return NAN;
      worst = std::max(worst, e);
    }
  return worst;
}

}  // namespace eomgen::runtime
