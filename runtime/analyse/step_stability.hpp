/// @file A fixed step against the region of absolute stability of its method: the
/// classical Runge–Kutta method is stable for h·λ with |1 + z + z²/2 + z³/6 + z⁴/24| ≤ 1
/// (on the imaginary axis up to h·ω = 2√2 ≈ 2.83), Störmer–Verlet for oscillations with
/// h·ω < 2. Beyond the limit the numerical solution grows although the motion does not.
#pragma once

#include <complex>
#include <string>
#include <vector>

#include "simulation.hpp"

namespace eomgen::runtime {

struct StepStability {
  bool beyond = false;               // some mode that does not grow is amplified by the method
  std::complex<double> eigenvalue;   // the mode that sets the limit
  double h_lambda = 0;               // h·|λ| for it
  double limit = 0;                  // the largest stable h·|λ| along its direction
  double largest_stable_step = 0;    // over all such modes, in s
};

/// |R(z)| ≤ 1 for the method's stability function; `integrator` is rk4 or verlet.
bool inside_stability_region(const std::string& integrator, std::complex<double> z);

/// The step h of `integrator` (rk4 or verlet) against the spectrum of ∂x'/∂x at (t, x).
/// Modes that grow by themselves (Re λ > 0) are left out: their growth is the motion's.
StepStability check_step(const Problem& p, const std::string& integrator, double h, double t, const std::vector<double>& x);

/// The warning for a step beyond the limit, for the user.
std::string step_stability_warning(const std::string& integrator, double h, const StepStability& s, double t);

}  // namespace eomgen::runtime
