#include "report/degree_colours.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace eomgen::runtime {

double DegreeColours::colour(double degree) const {
  if (std::isnan(degree) || knee <= 0) return degree;
  return std::copysign(std::log10(1 + std::abs(degree) / knee), degree);
}

std::string DegreeColours::tics() const {
  if (knee <= 0) return "";
  int low = static_cast<int>(std::ceil(std::log10(knee))), high = static_cast<int>(std::floor(std::log10(largest)));
  int step = std::max(1, (high - low + 1 + 5) / 6);  // at most about six decades labelled on each side
  std::string tics = "'0' 0";
  for (int k = high; k >= low; k -= step) {
    double d = std::pow(10.0, k);
    tics += fmt::format(", '{0:g}' {1:.12g}, '-{0:g}' {2:.12g}", d, colour(d), colour(-d));
  }
  return "(" + tics + ")";
}

DegreeColours degree_colours(const std::vector<double>& degrees) {
  std::vector<double> sizes;
  for (double d : degrees)
    if (std::isfinite(d) && d != 0) sizes.push_back(std::abs(d));
  DegreeColours c;
  // no floor in the degrees' units: a map of a slow system (degrees of 1e-15 per second) had a
  // scale of ±1e-12 and was white throughout
  if (sizes.empty()) return c;
  std::sort(sizes.begin(), sizes.end());
  c.largest = sizes.back();
  double median = sizes[sizes.size() / 2], decile = sizes[sizes.size() / 10];
  if (c.largest > 100 * median) c.knee = decile / 10;
  return c;
}

}  // namespace eomgen::runtime
