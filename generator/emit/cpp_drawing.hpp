/// @file The header's drawing section: which bodies `eomgen animate` draws, their shapes, and
/// body_poses, each body's position and rotation at a state (Equations::drawing), so that the
/// animation shows the generated code's own kinematics, not a second derivation of it.
#pragma once

#include <string>

#include "derive/equations.hpp"

namespace eomgen {

/// The constants, body_poses, drawn_shapes and gravity of the header.
std::string drawing_functions(const Equations& e);

}  // namespace eomgen
