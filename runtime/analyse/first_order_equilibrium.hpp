/// @file Steady motions of the first-order forms (Appell's equations with pseudo-velocities,
/// Hamilton's with momenta, a ball or free joint's angular velocities): states where the reduced
/// state (first_order_form.hpp: the non-cyclic coordinates and every velocity) stands still,
/// x' = F(x) = 0 on it, found by Newton's method with the generated jacobian_state.
#pragma once

#include <vector>

#include "analyse/equilibrium.hpp"

namespace eomgen::runtime {

/// Whether x' = 0 on the reduced state at `state`, each rate against the terms it sums
/// (rate_balance.hpp).
Equilibrium check_first_order(const Problem& problem, std::vector<double> state);

/// Newton's method on the reduced state's rates from x, in the states `unknowns` (indices into x:
/// non-cyclic coordinates, and velocities where they are to be solved for too), the others held.
Equilibrium solve_first_order(const Problem& problem, std::vector<double> x, const std::vector<int>& unknowns);

/// The search of find_equilibrium for a first-order form, the free `coordinates` given (the
/// non-cyclic ones, quaternions whole). In order, the first that converges away from a singular
/// mass matrix: the coordinates alone, the velocities as at `start`; the steady motion nearest the
/// start, coordinates and velocities solved for together (a governor's speed given to four digits,
/// a body spun near a principal axis); the steady motion at the start's configuration, the
/// velocities alone solved for (a spherical pendulum's conical motion at its initial θ); rest at
/// the start's configuration; where the model, released at `start` with damping added, comes to
/// rest (a servo saturated at the start). Each but the first says so in Equilibrium::note, as
/// Lagrange II's search (equilibrium.hpp) does; where none converges, the first.
Equilibrium find_first_order_equilibrium(const Problem& problem, const std::vector<double>& start,
                                         const std::vector<int>& coordinates);

}  // namespace eomgen::runtime
