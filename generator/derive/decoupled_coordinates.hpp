/// @file Coordinates a question does not need (Hiller §1.1: a car braking is a point mass).
/// The coordinates a scene's outputs name, closed under what their equations contain (a
/// coupling entry of M, or q_j or der(q_j) anywhere in their rows of M and f), form a
/// subsystem that moves the same whatever the other coordinates do: those do not feed back
/// into it. They are dropped, exactly; the energies keep their values at the dropped
/// coordinates' initial state.
#pragma once

#include <string>
#include <vector>

#include "derive/equations.hpp"

namespace eomgen {

/// `needed`: coordinate, der(q) or [outputs] names. Unconstrained Lagrange II models only;
/// returns the names dropped (none when every coordinate feeds back into the needed ones, or a
/// needed name is unknown).
std::vector<std::string> drop_coordinates_not_fed_back(Equations& equations, const std::vector<std::string>& needed);

}  // namespace eomgen
