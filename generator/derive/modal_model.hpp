/// @file A linear model truncated to some of its modes (Hiller §8.1: principal coordinates).
/// With q = q0 + Φ η for the mass-normalized shapes Φ kept, the equations are projected onto
/// them, Φᵀ M Φ η'' = Φᵀ f(q0 + Φ η, Φ η', t) (Galerkin); for undamped or proportionally damped
/// systems that is η_k'' + 2 ζ_k ω_k η_k' + ω_k² η_k = φ_kᵀ f(q0, 0, t), one oscillator per mode.
#pragma once

#include <string>
#include <vector>

#include "derive/equations.hpp"

namespace eomgen {

struct ModalTruncation {
  std::vector<double> equilibrium;                 // q0
  std::vector<std::vector<double>> shapes;          // φ_k over the coordinates, one per mode kept
  std::vector<int> mode_numbers;                    // 1-based, by increasing frequency: η names
  std::vector<double> initial_modal_coordinates;    // η(0) = Φᵀ M (q(0) − q0)
  std::vector<double> initial_modal_rates;          // η'(0) = Φᵀ M q'(0)
  std::vector<double> parameter_values;             // the shapes hold for these alone
};

/// `linear`: a linearized_model. The result's coordinates are eta<k>; its outputs are every
/// original coordinate q and der(q) (as q0 + Φ η and Φ η') and the model's own outputs, so the
/// questions of a scene still apply. Named `<name>_modal`.
Equations modal_model(const Equations& linear, const ModalTruncation& truncation);

}  // namespace eomgen
