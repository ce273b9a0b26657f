#include "integrate/coordinate_sizes.hpp"

#include <algorithm>
#include <cmath>

namespace eomgen::runtime {

std::vector<double> coordinate_sizes(const eomgen_model_abi& m, const double* x, bool with_default_state,
                                     double when_zero) {
  std::vector<bool> radian(m.num_coordinates);
  for (std::size_t i = 0; i < m.num_coordinates; ++i) radian[i] = m.is_angle[i];
  for (std::size_t k = 0; k < 4 * m.num_quaternions; ++k) radian[m.quaternion_coordinates[k]] = true;
  double common = 0;
  for (std::size_t i = 0; i < m.num_coordinates; ++i) {
    if (radian[i] || m.is_cyclic[i]) continue;
    common = std::max(common, std::abs(x[i]));
    if (with_default_state) common = std::max(common, std::abs(m.default_state[i]));
  }
  if (!(common > 0) || !std::isfinite(common)) common = when_zero;
  std::vector<double> sizes(m.num_coordinates);
  for (std::size_t i = 0; i < m.num_coordinates; ++i) sizes[i] = radian[i] ? 1.0 : common;
  return sizes;
}

}  // namespace eomgen::runtime
