/// @file A robot (robot.hpp) as an eomgen model file that a person reads and edits: frames and
/// bodies named after the robot's bodies, one frame per joint, coordinates named after the joints,
/// every number written in its shortest form that reads back as the same double.
#pragma once

#include <optional>
#include <string>

#include "common/diagnostic.hpp"

#include "import/robot.hpp"

namespace eomgen {

/// The model file's text; `name` is the model's name (a C++ identifier), `source` the file read.
std::string model_file_text(const Robot& robot, const std::string& name, const std::string& source);

/// A robot file (.xml) as model-file text named `name` (default: the robot's or the file's name), its
/// warnings on standard error, or nothing after a located error in `diagnostics`. What every command
/// does with a robot file (`in_memory`: saying so) and what `eomgen import` writes; `reading`: how
/// a URDF is read (import/mjcf_reader.hpp).
std::optional<std::string> imported_model_text(const std::string& path, Diagnostics& diagnostics, bool in_memory = true,
                                               std::string name = {}, RobotReading reading = {});

/// `text` made a C++ identifier: other characters become _, a leading digit gets a _ before it.
std::string identifier_of(const std::string& text);

}  // namespace eomgen
