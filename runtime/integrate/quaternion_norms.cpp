#include "integrate/quaternion_norms.hpp"

#include <algorithm>
#include <cmath>

namespace eomgen::runtime {

double quaternion_length(const eomgen_model_abi& m, const double* x, std::size_t k) {
  const std::size_t* q = m.quaternion_coordinates + 4 * k;
  return std::sqrt(x[q[0]] * x[q[0]] + x[q[1]] * x[q[1]] + x[q[2]] * x[q[2]] + x[q[3]] * x[q[3]]);
}

double quaternion_norm_error(const eomgen_model_abi& m, const double* x) {
  double largest = 0;
  for (std::size_t k = 0; k < m.num_quaternions; ++k) largest = std::max(largest, std::abs(quaternion_length(m, x, k) - 1));
  return largest;
}

double normalize_quaternions(const eomgen_model_abi& m, double* x) {
  double largest = 0;
  for (std::size_t k = 0; k < m.num_quaternions; ++k) {
    double norm = quaternion_length(m, x, k);
    largest = std::max(largest, std::abs(norm - 1));
    if (!(norm > 0) || !std::isfinite(norm)) continue;
    for (int c = 0; c < 4; ++c) x[m.quaternion_coordinates[4 * k + std::size_t(c)]] /= norm;
  }
  return largest;
}

int zero_quaternion(const eomgen_model_abi& m, const double* x) {
  for (std::size_t k = 0; k < m.num_quaternions; ++k)
    if (!(quaternion_length(m, x, k) > 0)) return int(k);
  return -1;
}

}  // namespace eomgen::runtime
