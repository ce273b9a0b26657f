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

}  // namespace eomgen
