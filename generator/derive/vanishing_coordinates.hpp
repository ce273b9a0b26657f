/// @file Coordinates a simpler model no longer determines: when a variant neglects the
/// only mass a coordinate moves (the light second bob of a double pendulum, m2 = 0), its
/// row and column of M and its f vanish and the rest of the equations does not contain
/// it. It is dropped, with the outputs, positions and first integrals that use it.
#pragma once

#include <string>
#include <vector>

#include "derive/equations.hpp"

namespace eomgen {

/// Coordinate j gone from M, f, the symbols, and with every output, body position and first
/// integral that uses it (the caller has made sure nothing else of the motion does).
void remove_coordinate(Equations& equations, std::size_t j);

/// Removes such coordinates from `equations` (unconstrained models only) unless `keep` names
/// them or an output that uses them; returns the names removed.
std::vector<std::string> remove_vanishing_coordinates(Equations& equations, const std::vector<std::string>& keep);

}  // namespace eomgen
