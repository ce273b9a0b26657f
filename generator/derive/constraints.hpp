/// @file The constraint set of a model, shared by Lagrange I and Appell.
#pragma once

#include <stdexcept>

#include "derive/equations.hpp"
#include "kinematics/mechanics.hpp"

namespace eomgen {

/// C, b, g and the acceleration bias of every [[constraints]] entry, in file order (through the
/// frames, Mechanics::constraint_terms, with recursive kinematics).
ConstraintSet constraint_set(const Model& model, const Mechanics& mechanics);

/// No constraint depends on time: ideal constraints then do no work, and T + V stays.
bool constraints_scleronomic(const ConstraintSet& constraints, const Symbols& symbols);

/// The value of e at the model's initial state, default parameters and inputs, t = 0, with the
/// values of `intermediates` (recursive kinematics) computed in their order.
double initial_value(const GiNaC::ex& e, const Symbols& symbols, const std::vector<Intermediate>& intermediates = {});

/// The constraints whose row of C, at the model's initial state and default parameters,
/// depends on the rows before it (empty when C has full rank there).
std::vector<std::string> dependent_constraints(const ConstraintSet& constraints, const Symbols& symbols,
                                               const std::vector<Intermediate>& intermediates = {});

/// Constraints and pseudo-velocities that leave some velocity undetermined: dependent constraints,
/// or pseudo-velocities that with the constraints do not determine every velocity. Its own type, so
/// that the pipeline's hint (remove a constraint, choose other pseudo-velocities) goes with it and
/// not with GiNaC's invalid arguments.
struct UndeterminedVelocities : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// Throws UndeterminedVelocities naming the dependent constraints, if there are any.
void require_independent(const ConstraintSet& constraints, const Symbols& symbols,
                         const std::vector<Intermediate>& intermediates = {});

}  // namespace eomgen
