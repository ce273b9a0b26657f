/// @file A generated header's numbers in another scalar type against double's: the
/// scalar types' value in double, and the normwise difference of two lists of numbers.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "support/awkward_scalar.hpp"

namespace eomgen::test {

inline double to_double(float v) { return v; }
inline double to_double(double v) { return v; }
inline double to_double(long double v) { return static_cast<double>(v); }
inline double to_double(awkward::Scalar v) { return v.value(); }

/// Normwise: relative to the largest number of `b` (at least 1), because an entry that is the
/// small difference of large terms (a stiff spring next to a soft one) carries the rounding
/// error of those terms in double itself, so no scalar type can agree with it elementwise.
inline double largest_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double worst = 0, scale = 1;
  for (double v : b) scale = std::max(scale, std::abs(v));
  for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]) / scale);
  return worst;
}

}  // namespace eomgen::test
