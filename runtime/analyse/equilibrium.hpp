/// @file Equilibria and steady motions: states with q' = 0 for the non-cyclic
/// coordinates, constant velocities of the cyclic ones, and f(q, q', u) = 0
/// (Hiller §7.1), found by Newton's method with the generated derivatives.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "simulation.hpp"

namespace eomgen::runtime {

struct Equilibrium {
  std::vector<double> state;  // x = [q; q']
  double residual = 0;        // max |f| at the state
  double tolerance = 0;       // what counts as zero for this model
  bool converged = false;
  int iterations = 0;
  std::string moving;  // non-cyclic coordinates whose velocity is not zero: the state moves
  std::string unmet;   // Lagrange I: the constraints the configuration does not meet, and by how much
  std::string note;    // what the search did besides Newton from the start, for the report
};

/// How a search that found nothing ended, for a message: "largest residual 0.767", or, where its
/// last step reached a state whose equations are not finite (a singularity of the coordinates),
/// that state and why.
std::string search_end_text(const Problem& p, const Equilibrium& e);

/// The non-cyclic coordinates whose velocity in x is not zero, "name = value" each: a state where
/// any moves changes its configuration, and with it the equations, so it is no equilibrium however
/// small the forces are there (Hiller §7.1); cyclic ones may move at constant speed.
std::string moving_coordinates(const eomgen_model_abi& m, const std::vector<double>& x);

/// Checks a fully given state: named values, other coordinates at `start`, other velocities zero.
Equilibrium check_equilibrium(const Problem& problem, std::vector<double> state);

/// Newton's method on f = 0 from `start`; the unknowns are the non-cyclic coordinates
/// and the velocities of the cyclic ones; the other velocities are zero. Where that finds none, the
/// state where the model released at `start` with damping added comes to rest, polished by Newton's
/// method (said in Equilibrium::note): a servo saturated at the start, whose torque has no slope
/// there, or a tree of 21 hinges whose Newton steps go round. Where that finds none either or
/// ends at a singular mass matrix (a singularity of the coordinates), the steady motion at the
/// start's configuration with the cyclic velocities alone free, when there is one (said in
/// Equilibrium::note). A first-order form (Appell, Hamilton) is searched alike, on its own state
/// (first_order_equilibrium.hpp).
Equilibrium find_equilibrium(const Problem& problem, const std::vector<double>& start);

/// The equilibrium or steady motion that keeps the states marked `held` at their values in `state`:
/// Newton, with backtracked steps, on the other non-cyclic coordinates and the other cyclic
/// velocities, from their values in `state`; the other velocities zero. A spherical pendulum held
/// at θ = 0.8 has its conical motion's φ' solved for. An Appell model has its other non-cyclic
/// coordinates solved for, its pseudo-velocities as in `state` (a quaternion is held whole where
/// one of its components is). A Lagrange I model has its other coordinates close the constraints
/// around the held ones and then solved for on them (find_constrained_equilibrium). Not converged
/// where nothing is free or Newton finds none.
Equilibrium complete_equilibrium(const Problem& problem, std::vector<double> state, const std::vector<bool>& held);

/// The states complete_equilibrium solves for: the non-cyclic coordinates and the cyclic velocities
/// not `held` (indices into the state; an Appell or Lagrange I model's coordinates alone).
std::vector<std::size_t> unheld_unknowns(const eomgen_model_abi& m, const std::vector<bool>& held);

}  // namespace eomgen::runtime
