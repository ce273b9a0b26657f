/// @file How a quantity changes with a displacement r of the state from a point, read on the
/// radii 10^k across the range of double: its leading power law, the one at the smallest
/// radii where the change rises above its rounding, and how far out that law holds. Both
/// belong to the system, not to the units it is written in: a potential well whose barrier
/// lies 1e-3 m away and one whose barrier lies 1 m away differ only in where on these radii
/// their laws end. Lyapunov's critical case (critical_case.cpp) asks both questions: does V
/// rise at all in a direction (the sign of its leading law), and how small is a small
/// perturbation (well inside the law that holds at the equilibrium).
#pragma once

#include <cmath>
#include <vector>

#include "simulation.hpp"

namespace eomgen::runtime {

/// The radii 10^-40, 10^-39, …, 10^40.
const std::vector<double>& probe_radii();

struct PowerLaw {
  bool found = false;  // no three radii in a row change the quantity by a power law
  double exponent = 0;
  int sign = 0;              // of the change
  double from = 0;           // the smallest radius of the law
  double change = 0;         // the change there
  double extent = INFINITY;  // the largest radius up to which it holds; infinite when to the grid's end
};

/// The leading power law of `changes` (one per probe radius; a NaN or infinity ends them): the
/// first three radii in a row whose changes are nonzero, of one sign, and rise by the same
/// exponent ≥ 1/2 to within 0.1 across both decades. Rounding noise rises by no steady law, so
/// it is passed over; so are the changes up to the last of three or more exact zeros between
/// nonzero ones (the rounding of terms that cancel for every r, which may rise steadily). The law then holds out to the last radius before the local exponent moves
/// by more than 0.1 from it or the change's sign turns.
PowerLaw leading_power_law(const std::vector<double>& changes);

/// For each component of the state the length over which the right-hand side keeps the power law
/// it follows at x, when that component alone is moved: the smallest extent over the rhs's rows
/// (infinity when every row keeps its law over the whole grid, as in a linear system).
std::vector<double> nonlinearity_lengths(const Problem& problem, const std::vector<double>& x);

}  // namespace eomgen::runtime
