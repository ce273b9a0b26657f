/// @file Numbers at the size of double rounding, which robot files carry from the arithmetic that
/// wrote them: a joint axis ["0", "1", "6.12323e-17"] (cos(π/2) printed to six digits, as iCub's
/// URDF has it), an origin ["0.032", "-2.67276e-51", "0"], a quaternion whose x is 2e-17 beside a w
/// of 0.7, a centre of mass 4e-19 m from a frame's origin in a robot a metre across. Each is zero
/// to within what double precision can tell: it moves no position, turn or force of the robot by
/// more than the rounding of the sums that place it. Written as read, it makes a joint about an
/// axis of its frame oblique and a turn by a right angle a full matrix, and the generated code
/// multiplies by it (iCub's: 6.27 µs per rhs). So such a number is taken as zero:
/// - a component of a unit vector or quaternion within 8 units of rounding of its length;
/// - a length within 8 units of rounding of the robot's size (its largest offset, centre, anchor);
/// - a principal moment of inertia within 8 units of rounding of its body's mass times the size².
/// Turns by a right angle are then written exactly by import/right_angles.hpp.
#pragma once

#include "import/robot.hpp"

namespace eomgen {

/// How many numbers were taken as zero, and the largest of them relative to its scale.
struct RoundingNoise {
  int numbers = 0;
  double largest = 0;  // in units of rounding (DBL_EPSILON)
};

/// The robot with those numbers set to zero.
RoundingNoise without_rounding_noise(Robot& robot);

}  // namespace eomgen
