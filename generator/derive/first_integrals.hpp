/// @file The first integrals the book derives from the Lagrangian (Hiller §3.6,
/// §3.8.3), found for every derivation method: the generalized energy
/// (Jacobi integral) and the momenta of the cyclic coordinates.
#pragma once

#include <vector>

#include "derive/equations.hpp"
#include "kinematics/mechanics.hpp"

namespace eomgen {

/// The first integrals of the equations `e`, each written in the variables of e's state
/// (q and q', the pseudo-velocities, or the momenta), with the reason it is conserved.
std::vector<FirstIntegral> find_first_integrals(const Equations& e, const Mechanics& mechanics);

}  // namespace eomgen
