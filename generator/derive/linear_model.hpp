/// @file The linearized model about an equilibrium (Hiller §5.3) as a model of its own,
/// derived like any other: M(q0) q'' = f(q0, 0, t) + ∂f/∂q (q − q0) + ∂f/∂q' q', with
/// T, V and the outputs expanded to the matching order. The cheapest candidate of a scene.
#pragma once

#include <string>
#include <vector>

#include "derive/equations.hpp"

namespace eomgen {

/// `equilibrium`: the coordinates q0 (the velocities are taken as zero). Time-dependent
/// forcing (a scene's inputs) stays as it is. The model is named `<name>_linear`.
/// Returns the refusal in `refusal` for models other than unconstrained Lagrange II.
Equations linearized_model(const Equations& equations, const std::vector<double>& equilibrium, std::string& refusal);

}  // namespace eomgen
