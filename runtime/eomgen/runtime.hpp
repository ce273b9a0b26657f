/// @file eomgen's runtime for a program that includes a generated header (find_package(eomgen),
/// target eomgen::runtime): simulate with any of eomgen's integrators, linearize and judge the
/// stability of an equilibrium, evaluate the first integrals. A generated namespace becomes the
/// runtime's model through model_abi.h:
///
///   #include <eomgen/runtime.hpp>
///   #include "double_pendulum.hpp"
///   EOMGEN_MODEL_FUNCTION(double_pendulum_model, double_pendulum)
///
///   const eomgen_model_abi& m = *double_pendulum_model();
///   eomgen::runtime::Problem problem = eomgen::runtime::default_problem(m);
///   eomgen::runtime::SimulationSettings settings;  // integrator "cvode-bdf", rtol, t_end, dt_out ...
///   eomgen::runtime::SimulationResult run = eomgen::runtime::simulate(problem, eomgen::runtime::default_state(m), settings);
#pragma once

#include <vector>

#include "analyse/equilibrium.hpp"
#include "analyse/linear_stability.hpp"
#include "analyse/state_space.hpp"
#include "model_abi.h"
#include "simulation.hpp"

namespace eomgen::runtime {

/// The model at its default parameters and inputs (change problem.parameters and problem.inputs,
/// in parameter_names and input_names order, or set problem.input_signal for inputs over time).
Problem default_problem(const eomgen_model_abi& model);

/// The model's initial state x = [q; q'] as its model file gives it.
std::vector<double> default_state(const eomgen_model_abi& model);

/// The first integrals (energy, momenta of cyclic coordinates) at (t, x), in first_integral_names order.
std::vector<double> first_integrals_at(const Problem& problem, double t, const std::vector<double>& x);

}  // namespace eomgen::runtime
