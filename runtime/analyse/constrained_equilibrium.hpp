/// @file Equilibria of Lagrange I models: a configuration on the constraints, g(q) = 0, at rest,
/// where q'' = 0 (Hiller §7.1 with the multipliers' forces among the forces). The rates are taken
/// without Baumgarte's stabilization: its gains are the model's rates in 1/s (10 unless set), not
/// the system's, and on a system whose period is 2e12 s they had outweighed gravity by 1e24.
#pragma once

#include <vector>

#include "analyse/equilibrium.hpp"
#include "simulation.hpp"

namespace eomgen::runtime {

/// The state as given: not an equilibrium where it leaves the holonomic constraints (beyond 1e-9
/// of each one's scale, Σ_j |∂g/∂q_j| s_j with s_j q_j's size; Equilibrium::unmet), moves a
/// coordinate that is not cyclic
/// (Equilibrium::moving) or has a rate past what counts as zero for it (rate_balance.hpp).
Equilibrium check_constrained_equilibrium(const Problem& problem, std::vector<double> state);

/// Newton's method on the constraint manifold from `start` at rest: steps δq = N δz in the null
/// space N of ∂g/∂q with Nᵀ (∂q''/∂q) N δz = −Nᵀ q'', each projected back onto g(q) = 0 and halved
/// until q'' shrinks (so that no step's size is in any unit). The coordinates marked `held` (of the
/// state; none where empty) keep their values: the others close the constraints around them, and
/// the steps keep them too (a four-bar with its crank named has its coupler and rocker found).
Equilibrium find_constrained_equilibrium(const Problem& problem, const std::vector<double>& start,
                                         const std::vector<bool>& held = {});

}  // namespace eomgen::runtime
