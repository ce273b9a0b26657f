/// @file Which coordinates are angles: those the equations take through sin, cos or tan of a whole
/// multiple of them (a joint's turn, an Euler angle, the angle of a pendulum written by hand).
/// Such a coordinate is dimensionless, and its natural size is one radian whatever the units of
/// length and time; the runtime's tolerances take each coordinate's own size from this (a length's
/// is the configuration's, an angle's one radian), so that a verdict does not change when lengths
/// are scaled. A coordinate in sin(q/l) (l a parameter) is not one: q has l's units.
#pragma once

#include <vector>

#include "derive/equations.hpp"

namespace eomgen {

/// For each coordinate, whether it is an angle in the sense above.
std::vector<bool> angle_coordinates(const Equations& equations);

}  // namespace eomgen
