#include "import/right_angles.hpp"

#include <cfloat>
#include <cmath>

namespace eomgen {

namespace {

using Matrix = std::array<std::array<int, 3>, 3>;

// R(q) of the unit quaternion q/|q| (Hiller §2.1's Euler parameters), in double
std::array<std::array<double, 3>, 3> rotation_of(const Quaternion& q) {
  double n = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
  double w = q[0], x = q[1], y = q[2], z = q[3];
  return {{{(w * w + x * x - y * y - z * z) / n, 2 * (x * y - w * z) / n, 2 * (x * z + w * y) / n},
           {2 * (x * y + w * z) / n, (w * w - x * x + y * y - z * z) / n, 2 * (y * z - w * x) / n},
           {2 * (x * z - w * y) / n, 2 * (y * z + w * x) / n, (w * w - x * x - y * y + z * z) / n}}};
}

// R of the integer quaternion q, times |q|², exactly
Matrix scaled_rotation_of(const std::array<int, 4>& q) {
  int w = q[0], x = q[1], y = q[2], z = q[3];
  return {{{w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)},
           {2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)},
           {2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z}}};
}

int sign(int v) { return (v > 0) - (v < 0); }

// The quaternion of a signed permutation P: 4q_k² are 1 + tr P and 1 + 2P_kk − tr P; with the
// largest taken positive, the others' signs follow from P's off-diagonal sums and differences.
// For a rotation among these, the nonzero |q_k| are all equal (one, two or four of them).
std::array<int, 4> permutation_quaternion(const Matrix& P) {
  int trace = P[0][0] + P[1][1] + P[2][2];
  int squares[4] = {1 + trace, 1 + 2 * P[0][0] - trace, 1 + 2 * P[1][1] - trace, 1 + 2 * P[2][2] - trace};
  int k = 0;
  for (int i = 1; i < 4; ++i)
    if (squares[i] > squares[k]) k = i;
  // 4 q_k q_i for i ≠ k
  int products[4][4] = {};
  products[0][1] = P[2][1] - P[1][2], products[0][2] = P[0][2] - P[2][0], products[0][3] = P[1][0] - P[0][1];
  products[1][2] = P[0][1] + P[1][0], products[1][3] = P[0][2] + P[2][0], products[2][3] = P[1][2] + P[2][1];
  std::array<int, 4> q{};
  for (int i = 0; i < 4; ++i) {
    if (squares[i] == 0) continue;
    q[std::size_t(i)] = i == k ? 1 : sign(i < k ? products[i][k] : products[k][i]);
  }
  return q;
}

}  // namespace

std::optional<std::array<int, 4>> right_angle_turn(const Quaternion& q) {
  if (q[0] == 0 && q[1] == 0 && q[2] == 0 && q[3] == 0) return std::nullopt;
  auto R = rotation_of(q);
  Matrix P{};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      double nearest = std::round(R[r][c]);
      if (std::abs(R[r][c] - nearest) > 8 * DBL_EPSILON || std::abs(nearest) > 1) return std::nullopt;
      P[r][c] = int(nearest);
    }
  std::array<int, 4> turn = permutation_quaternion(P);
  int length = turn[0] * turn[0] + turn[1] * turn[1] + turn[2] * turn[2] + turn[3] * turn[3];
  Matrix back = scaled_rotation_of(turn);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      if (back[r][c] != length * P[r][c]) return std::nullopt;  // not a rotation (a reflection, say)
  return turn;
}

}  // namespace eomgen
