/// @file Turns that are right angles to the last digit. A robot file's rpy = "1.5707963267948966"
/// (π/2 as a double, as example-robot-data's panda.urdf writes it) reaches eomgen through MuJoCo's
/// compiler as the quaternion (0.7071067811865476, 0.7071067811865475, 0, 0): its w and x differ
/// in the last bit, and its rotation matrix holds entries of 1e-16 where the turn has zeros. Written
/// as read, the generated code multiplies by them, and the tree's constant turns stop being
/// permutations with signs that cost nothing. Within a few units of rounding such a quaternion is
/// written exactly instead (`quat(1, 1, 0, 0)`): the rotation moves by less than double precision
/// can tell. A turn the file states to fewer digits (rpy = "3.14159265359", 2e-13 from π) is
/// written as read: that is the robot the file describes.
#pragma once

#include <array>
#include <optional>

#include "import/robot.hpp"

namespace eomgen {

/// The quaternion's turn as integers w, x, y, z (quat() divides by their squared length), when its
/// rotation matrix is a permutation with signs to within 8 units of rounding; otherwise nothing.
std::optional<std::array<int, 4>> right_angle_turn(const Quaternion& q);

/// The right angle nearest to a turn, as integers w, x, y, z, and the angle between the two in
/// radians, when that angle is below 0.1 rad; otherwise nothing.
struct NearRightAngle {
  std::array<int, 4> turn{};
  double angle = 0;
};
std::optional<NearRightAngle> nearest_right_angle(const Quaternion& q);

/// What rounded_right_angles() did: the turns it rounded and the largest angle it moved one by;
/// the turns it left that are near a right angle all the same (within 1e-3 rad, not to the last
/// digit: a file that states π/2 as 1.5708) and the largest of their angles.
struct RightAngleRounding {
  int rounded = 0;
  double largest_rounded = 0;
  int near = 0;
  double largest_near = 0;
};

/// Each body's turn in its parent, where within `within` radians of a right angle, set to that
/// right angle: a file that states π/2 to five or twelve digits (1.5708, 1.57079632679) then has
/// the constant turns that the generated code skips. The robot moves by up to `within`; the
/// default, 0, moves nothing. Axes of inertia stay as read (their small turns are products of
/// inertia, folded into constants at generation).
RightAngleRounding rounded_right_angles(Robot& robot, double within);

}  // namespace eomgen
