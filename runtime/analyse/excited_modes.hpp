/// @file Which natural modes a motion excites (Hiller §8.1): the motion q(t) about q0,
/// projected on the mass-normalized modes, η_k(t) = φ_kᵀ M (q(t) − q0), η_k'(t) = φ_kᵀ M q'(t),
/// and each mode's part in the outputs y = C x, largest over the motion, relative to each
/// output's range. The modes whose parts add up to less than a bound can be left out.
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "analyse/modal_analysis.hpp"

namespace eomgen::runtime {

struct ExcitedModes {
  std::vector<double> share;      // per mode: max over t and outputs of |C x_k(t)| / range
  std::vector<std::size_t> kept;  // the modes needed, by increasing frequency
};

/// `states`: x = [q; q'] along the motion; `C`: outputs × 2n; `ranges`: each output's range over
/// the motion. Leaves out the least excited modes while their shares add up to no more than `bound`.
ExcitedModes excited_modes(const ModalAnalysis& modes, const Eigen::MatrixXd& M, const std::vector<double>& q0,
                           const std::vector<std::vector<double>>& states, const Eigen::MatrixXd& C,
                           const std::vector<double>& ranges, double bound);

}  // namespace eomgen::runtime
