/// @file Absolute tolerances in each state's own size. A default of 1e-10 in every unit is loose
/// for a MEMS oscillator whose displacement is 1e-9 m: with rtol 1e-8 its error was 5e-5 of the
/// amplitude. Each state's size is what the problem says of it before the run: its initial value, or
/// the model's default where that is zero, and for a velocity also its coordinate's size times
/// the system's rate (the spectral scale of the balanced Jacobian at the start: an oscillator of
/// amplitude a and frequency ω has speeds of a ω). Its tolerance is the given one, or 1e-2 rtol of
/// its size where that is smaller (the default's ratio to rtol for states of size one), so that
/// a model written in SI units of order one runs exactly as before.
#pragma once

#include <vector>

#include "simulation.hpp"

namespace eomgen::runtime {

/// Each state's size as above (0 where the problem says nothing of it: a state that is zero and
/// whose default is zero).
std::vector<double> state_sizes(const Problem& problem, const std::vector<double>& x0);

/// num_states absolute tolerances for a run from x0 at relative tolerance rtol; atol is the largest.
std::vector<double> state_absolute_tolerances(const Problem& problem, const std::vector<double>& x0, double rtol, double atol);

}  // namespace eomgen::runtime
