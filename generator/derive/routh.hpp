/// @file Routh's reduction of cyclic coordinates (Hiller §3.8.4): the equations of
/// the remaining coordinates, with the conserved momenta as parameters.
#pragma once

#include <string>
#include <vector>

#include "derive/equations.hpp"
#include "kinematics/mechanics.hpp"

namespace eomgen {

/// The Routh-reduced equations of `model` with the coordinates `cyclic` eliminated: their
/// momenta become parameters p_<coordinate> (defaults from the model's initial state), the
/// state holds the other coordinates and their velocities, and `routhian` is R(q, q', t; p).
/// T is the part of R quadratic in the velocities and V the amended potential −R(q, 0, t; p).
/// Throws std::invalid_argument with the reason when a coordinate cannot be eliminated.
Equations derive_routh(const Model& model, const Mechanics& mechanics, const std::vector<std::string>& cyclic);

}  // namespace eomgen
