/// @file Expressions of the model file (GiNaC syntax) into GiNaC, with exact
/// columns for every mistake. Written here rather than using GiNaC's own
/// parser so that any identifier can name a symbol (I, E, beta, gamma ...),
/// decimals become exact rationals, and der(q) is checked where it is read.
#pragma once

#include <array>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "model/symbols.hpp"
#include "parse/model_file.hpp"

namespace eomgen {

/// What an expression may depend on; a bit set.
enum Allow : unsigned {
  allow_parameters = 1,
  allow_coordinates = 2,
  allow_velocities = 4,
  allow_time = 8,
  allow_inputs = 16,
  allow_constants_only = 0,
  allow_configuration = allow_parameters | allow_coordinates | allow_time,
  allow_everything = allow_parameters | allow_coordinates | allow_velocities | allow_time | allow_inputs,
};

struct ExpressionRules {
  unsigned allowed = allow_everything;
  const char* context = "an expression";  // e.g. "a position", for messages
  /// definitions further down [definitions], not yet usable: named as such when used
  const std::vector<std::string>* defined_later = nullptr;
  /// the names of ball and free joints' angular velocities, which no expression takes: named as such
  const std::set<std::string>* angular_velocities = nullptr;
};

/// One factor of a product of rotations: rot_x, rot_y or rot_z of an angle, a turn by an angle
/// about a unit `direction` (Rodrigues), or a constant rotation matrix (a frame's placement
/// given as a matrix, followed by a joint).
struct ElementaryRotation {
  static constexpr int about_direction = 3, constant_matrix = 4;
  int axis;  // 0 = x, 1 = y, 2 = z, about_direction or constant_matrix
  GiNaC::ex angle;
  std::array<GiNaC::ex, 3> direction{0, 0, 0};  // about_direction: a unit vector
  GiNaC::matrix constant{3, 3};                  // constant_matrix: the rotation itself
};

/// The direction (x, y, z) divided by its length (exact: ±1 when along a coordinate axis).
/// The turn by `angle` about the direction (x, y, z), normalized; a direction along a
/// coordinate axis (either sign) becomes rot_x, rot_y or rot_z. The direction must not be zero.
std::array<GiNaC::ex, 3> unit_direction(const std::array<GiNaC::ex, 3>& direction);
ElementaryRotation turn_about(const std::array<GiNaC::ex, 3>& direction, const GiNaC::ex& angle);

/// Parses a scalar expression; on a mistake reports it and returns nothing.
std::optional<GiNaC::ex> parse_expression(const ExpressionText& text, const Symbols& symbols,
                                          ExpressionRules rules, Diagnostics& diagnostics);

/// Parses a rotation written as a product of rot_x/rot_y/rot_z/euler313/cardan123,
/// left to right, into its elementary rotations (R = R1·R2·…).
std::optional<std::vector<ElementaryRotation>> parse_rotation_product(
    const ExpressionText& text, const Symbols& symbols, ExpressionRules rules,
    Diagnostics& diagnostics);

}  // namespace eomgen
