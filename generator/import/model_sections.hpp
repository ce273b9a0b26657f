/// @file What the parts of an imported model file share while it is written (model_writer.cpp,
/// transmission_text.cpp): the names taken, each joint's symbols, and the file's sections.
#pragma once

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "emit/formats.hpp"
#include "import/model_writer.hpp"

namespace eomgen {

/// The names of the model's symbols, each used once.
class Names {
 public:
  std::string take(const std::string& wanted) {
    std::string name = identifier_of(wanted), out = name;
    for (int k = 2; !used_.insert(out).second; ++k) out = fmt::format("{}_{}", name, k);
    return out;
  }
  /// `wanted`, or when that is taken `wanted`_`kind` (a motor named after its joint: knee_motor)
  std::string take(const std::string& wanted, const std::string& kind) {
    std::string name = identifier_of(wanted);
    return used_.count(name) ? take(name + "_" + kind) : take(name);
  }

 private:
  std::set<std::string> used_{"t", "der", "Pi", "g"};
};

/// The coordinates and velocities a joint gets.
struct JointSymbols {
  std::vector<std::string> coordinates;  // in qpos order
  std::vector<std::string> angular;      // ball, free: ω's names
  /// a hinge or slide that follows another joint's coordinate `leader` (joint_followers.hpp): it
  /// moves by multiplier·leader + offset, and its own name in `coordinates` is not declared
  std::string leader;
  double multiplier = 1, offset = 0;
  bool follows() const { return !leader.empty(); }
  // the hinge's or slide's angle and rate in the model's coordinates
  std::string angle() const {
    if (!follows()) return coordinates[0];
    if (multiplier == 1 && offset == 0) return leader;
    std::string scaled = multiplier == 1 ? leader : fmt::format("{}*{}", format_number(multiplier), leader);
    if (offset == 0) return "(" + scaled + ")";
    return fmt::format("({} {} {})", scaled, offset < 0 ? "-" : "+", format_number(std::abs(offset)));
  }
  std::string rate() const {
    if (!follows() || multiplier == 1) return "der(" + (follows() ? leader : coordinates[0]) + ")";
    return fmt::format("({}*der({}))", format_number(multiplier), leader);
  }
};

/// The model file's sections as they are filled, and what it cannot carry.
struct Sections {
  std::string coordinates, frames, bodies, inputs, forces, points, scenes;
  std::vector<std::string> kinetic, dissipation, potential, warnings;
};

}  // namespace eomgen
