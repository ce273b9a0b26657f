/// @file Pictures of the natural modes (Hiller §8.1): each body's centre of mass at the
/// equilibrium and displaced along a mode, r0 + a (∂r/∂q) φ, in the plane where the
/// bodies and their motion spread most. Where all centres coincide at the equilibrium
/// (coordinates that are displacements, as in a spring chain), the bodies stand at
/// stations 1, 2, … and their displacement is drawn across, as a string's picture.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "derive/equations.hpp"

namespace eomgen {

struct DeformedShapes {
  std::string refusal;  // why there is no picture (no bodies), or empty
  bool stations = false;
  std::string horizontal, vertical;  // axis names: "x", "y", "z" or "station", "displacement along x"
  std::vector<std::array<double, 2>> rest;                 // one point per body
  std::vector<std::vector<std::array<double, 2>>> modes;   // per mode, one point per body
};

/// `shapes`: the modes φ (one value per coordinate), drawn with the largest displacement a
/// third of the picture's size; `parameters` and `state` as for the linearization.
DeformedShapes deformed_shapes(const Equations& equations, const std::vector<double>& parameters,
                               const std::vector<double>& inputs, const std::vector<double>& state,
                               const std::vector<std::vector<double>>& shapes);

}  // namespace eomgen
