/// @file Whether the kinetic energy is the quadratic form T = ½ vᵀ M v of the velocities of the
/// state (a scleronomic system: no term linear in or free of the velocities), for the header to
/// compute T from M instead of writing the recursion's T out a second time.
#pragma once

#include "derive/equations.hpp"

namespace eomgen {

/// True for a tree of particles solved by the articulated-body recursion, and for equations from
/// recursive kinematics or a joint tree whose T is written in the recursion's quantities (long
/// code) where T = ½ vᵀ M v at two states, to 1e-12 of the largest term; false otherwise (a T in
/// the model's symbols alone, a top's, stays the formula it is).
bool kinetic_energy_is_quadratic_form(const Equations& e);

}  // namespace eomgen
