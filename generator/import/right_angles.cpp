#include "import/right_angles.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <utility>

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

// the signed permutation nearest to R, when rounding R's entries gives a rotation
std::optional<std::pair<Matrix, std::array<int, 4>>> rounded_rotation(const std::array<std::array<double, 3>, 3>& R,
                                                                      double within_entry) {
  Matrix P{};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      double nearest = std::round(R[r][c]);
      if (std::abs(R[r][c] - nearest) > within_entry || std::abs(nearest) > 1) return std::nullopt;
      P[r][c] = int(nearest);
    }
  std::array<int, 4> turn = permutation_quaternion(P);
  int length = turn[0] * turn[0] + turn[1] * turn[1] + turn[2] * turn[2] + turn[3] * turn[3];
  Matrix back = scaled_rotation_of(turn);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      if (back[r][c] != length * P[r][c]) return std::nullopt;  // not a rotation (a reflection, say)
  return std::make_pair(P, turn);
}

}  // namespace

std::optional<NearRightAngle> nearest_right_angle(const Quaternion& q) {
  double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (!(n > 0)) return std::nullopt;
  auto rounded = rounded_rotation(rotation_of(q), 0.1);
  if (!rounded) return std::nullopt;
  const std::array<int, 4>& p = rounded->second;
  double pn = std::sqrt(double(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] + p[3] * p[3]));
  // unit quaternions u and v (taken on u's side) lie φ = 2 atan2(|u − v|, |u + v|) apart, and their
  // turns 2φ: accurate where 2 acos(u·v) loses half the digits
  double dot = 0;
  for (std::size_t k = 0; k < 4; ++k) dot += q[k] / n * p[k] / pn;
  double side = dot < 0 ? -1 : 1, apart = 0, together = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    double u = q[k] / n, v = side * p[k] / pn;
    apart += (u - v) * (u - v), together += (u + v) * (u + v);
  }
  double angle = 4 * std::atan2(std::sqrt(apart), std::sqrt(together));
  if (!(angle < 0.1)) return std::nullopt;
  return NearRightAngle{p, angle};
}

RightAngleRounding rounded_right_angles(Robot& robot, double within) {
  RightAngleRounding done;
  auto round_turn = [&](Quaternion& q) {
    if (right_angle_turn(q)) return;  // a unit of rounding off: written exactly anyway
    auto near = nearest_right_angle(q);
    if (!near || near->angle > std::max(within, 1e-3)) return;
    if (near->angle <= within) {
      // a unit quaternion, as the file's was: right_angle_turn() then writes it with integers
      const std::array<int, 4>& p = near->turn;
      double length = std::sqrt(double(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] + p[3] * p[3]));
      q = {p[0] / length, p[1] / length, p[2] / length, p[3] / length};
      ++done.rounded, done.largest_rounded = std::max(done.largest_rounded, near->angle);
    } else {
      ++done.near, done.largest_near = std::max(done.largest_near, near->angle);
    }
  };
  // the frames' turns only: a body's axes of inertia a little off its frame's are products of
  // inertia, not digits left out (a rod's slight asymmetry), and cost no rotation at run time
  for (RobotBody& b : robot.bodies) round_turn(b.orientation);
  return done;
}

std::optional<std::array<int, 4>> right_angle_turn(const Quaternion& q) {
  if (q[0] == 0 && q[1] == 0 && q[2] == 0 && q[3] == 0) return std::nullopt;
  auto rounded = rounded_rotation(rotation_of(q), 8 * DBL_EPSILON);
  if (!rounded) return std::nullopt;
  return rounded->second;
}

}  // namespace eomgen
