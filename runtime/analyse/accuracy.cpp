#include "analyse/accuracy.hpp"

#include <algorithm>
#include <cmath>

namespace eomgen::runtime {

std::vector<double> state_scales(const std::vector<std::vector<double>>& reference) {
  std::size_t n = reference.empty() ? 0 : reference.front().size();
  std::vector<double> scale(n, 0.0);
  double largest = 0;
  for (const auto& row : reference)
    for (std::size_t i = 0; i < n; ++i) {
      scale[i] = std::max(scale[i], std::abs(row[i]));
      largest = std::max(largest, std::abs(row[i]));
    }
  for (double& s : scale) s = std::max({s, 1e-3 * largest, 1e-300});
  return scale;
}

double row_error(const std::vector<double>& x, const std::vector<double>& r, const std::vector<double>& scales) {
  double worst = 0;
  for (std::size_t i = 0; i < scales.size(); ++i) {
    double e = std::abs(x[i] - r[i]) / scales[i];
    if (!std::isfinite(e)) return NAN;
    worst = std::max(worst, e);
  }
  return worst;
}

double trajectory_error(const std::vector<std::vector<double>>& states, const std::vector<std::vector<double>>& reference) {
  if (reference.empty()) return NAN;
  std::vector<double> scales = state_scales(reference);
  double worst = 0;
  for (std::size_t k = 0; k < std::min(states.size(), reference.size()); ++k) {
    double e = row_error(states[k], reference[k], scales);
    if (std::isnan(e)) return NAN;
    worst = std::max(worst, e);
  }
  return worst;
}

}  // namespace eomgen::runtime
