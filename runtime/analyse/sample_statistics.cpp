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

}  // namespace eomgen::runtime
