#include "model/quaternion.hpp"

namespace eomgen {

using GiNaC::ex;

GiNaC::matrix quaternion_rotation(const std::array<ex, 4>& q, const ex& n) {
  const ex &w = q[0], &x = q[1], &y = q[2], &z = q[3];
  return GiNaC::matrix{{(w * w + x * x - y * y - z * z) * n, 2 * (x * y - w * z) * n, 2 * (x * z + w * y) * n},
                       {2 * (x * y + w * z) * n, (w * w - x * x + y * y - z * z) * n, 2 * (y * z - w * x) * n},
                       {2 * (x * z - w * y) * n, 2 * (y * z + w * x) * n, (w * w - x * x - y * y + z * z) * n}};
}

GiNaC::matrix quaternion_rotation(const std::array<ex, 4>& q) {
  return quaternion_rotation(q, 1 / (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]));
}

std::array<ex, 4> quaternion_rates(const std::array<ex, 4>& q, const std::array<ex, 3>& w) {
  return {-(q[1] * w[0] + q[2] * w[1] + q[3] * w[2]) / 2, (q[0] * w[0] + q[2] * w[2] - q[3] * w[1]) / 2,
          (q[0] * w[1] + q[3] * w[0] - q[1] * w[2]) / 2, (q[0] * w[2] + q[1] * w[1] - q[2] * w[0]) / 2};
}

}  // namespace eomgen
