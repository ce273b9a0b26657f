#include "analyse/sample_statistics.hpp"

#include <algorithm>
#include <cmath>

namespace eomgen::runtime {

SampleStatistics sample_statistics(const std::vector<double>& values, const std::vector<double>& probabilities) {
  std::vector<double> finite;
  for (double v : values)
    if (std::isfinite(v)) finite.push_back(v);
  SampleStatistics s;
  s.count = static_cast<long>(finite.size());
  s.quantiles.assign(probabilities.size(), NAN);
  if (finite.empty()) {
    s.mean = s.standard_deviation = s.standard_error = NAN;
    return s;
  }
  double sum = 0;
  for (double v : finite) sum += v;
  s.mean = sum / double(finite.size());
  if (finite.size() > 1) {
    double squares = 0;  // two passes: no cancellation when the spread is small against the mean
    for (double v : finite) squares += (v - s.mean) * (v - s.mean);
    s.standard_deviation = std::sqrt(squares / double(finite.size() - 1));
    s.standard_error = s.standard_deviation / std::sqrt(double(finite.size()));
  } else {
    s.standard_deviation = s.standard_error = NAN;
  }
  std::sort(finite.begin(), finite.end());
  for (std::size_t i = 0; i < probabilities.size(); ++i) {
    double h = probabilities[i] * double(finite.size() - 1);
    std::size_t below = static_cast<std::size_t>(std::floor(h));
    std::size_t above = std::min(below + 1, finite.size() - 1);
    s.quantiles[i] = finite[below] + (h - double(below)) * (finite[above] - finite[below]);
  }
  return s;
}

SelectionDependence selection_dependence(const std::vector<std::vector<double>>& drawn, const std::vector<bool>& left_out) {
  SelectionDependence out;
  std::size_t variables = drawn.empty() ? 0 : drawn[0].size();
  for (std::size_t v = 0; v < variables; ++v) {
    double sum[2] = {0, 0}, squares[2] = {0, 0}, count[2] = {0, 0};
    for (std::size_t k = 0; k < drawn.size() && k < left_out.size(); ++k) {
      int group = left_out[k] ? 1 : 0;
      sum[group] += drawn[k][v], squares[group] += drawn[k][v] * drawn[k][v], ++count[group];
    }
    if (count[0] < 2 || count[1] < 2) continue;
    double mean[2], variance[2];
    for (int g = 0; g < 2; ++g) {
      mean[g] = sum[g] / count[g];
      variance[g] = std::max(0.0, (squares[g] - count[g] * mean[g] * mean[g]) / (count[g] - 1));
    }
    double spread = std::sqrt(variance[0] / count[0] + variance[1] / count[1]);
    if (spread == 0) continue;
    double t = (mean[1] - mean[0]) / spread;
    if (std::abs(t) > 4 && std::abs(t) > std::abs(out.t)) out = {static_cast<int>(v), t};
  }
  return out;
}

}  // namespace eomgen::runtime
