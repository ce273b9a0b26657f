/// @file The equilibrium a stability analysis is about: one named by --at (checked), or one
/// searched for from the model's initial state; and the models the analyses refuse.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analyse/equilibrium.hpp"
#include "studies/loaded_problem.hpp"

namespace eomgen::studies {

/// Why stability and sweep cannot analyse this model (Lagrange I always; symbolic
/// conditions of Appell models), printed; nothing when they can.
std::optional<int> stability_refusal(const LoadedProblem& loaded, const std::string& model, bool symbolic,
                                     bool on_manifold);

/// The equilibrium of `problem`: checked when --at names one, else searched for.
/// Returns the exit status when there is none.
/// `initial` is the model's initial state (with --set applied): where the search starts,
/// and the coordinates --at does not name.
std::optional<int> equilibrium_of(const runtime::Problem& problem, const std::vector<std::string>& at,
                                  const std::vector<double>& initial, runtime::Equilibrium& out);

}  // namespace eomgen::studies
