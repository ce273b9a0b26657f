/// @file Principal coordinates (Hiller §6.3): the coordinates in which the linear
/// system decouples. For M q'' + D q' + K q = B u with proportional (or no) damping,
/// q = Φ η with the mass-normalized modes, η_i'' + 2ζ_i ω_i η_i' + ω_i² η_i = φ_iᵀ B u;
/// otherwise x = V η with A's eigenvectors, η_i' = λ_i η_i + (V⁻¹B)_i u, or, when A is not
/// diagonalizable, with its Jordan chains: η_i' = λ_i η_i + η_(i+1) + (V⁻¹B)_i u inside a block.
#pragma once

#include <complex>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "analyse/jordan_chains.hpp"
#include "analyse/linear_system.hpp"
#include "analyse/modal_analysis.hpp"

namespace eomgen::runtime {

struct PrincipalCoordinates {
  std::string kind;    // "modal", "eigenvectors", "jordan" or "none"
  std::string reason;  // for "none": why the system does not decouple
  Eigen::MatrixXd modal_matrix;     // modal: Φ, n × n, the columns the modes
  Eigen::MatrixXd modal_inputs;     // modal: ΦᵀB, n × inputs
  Eigen::MatrixXcd eigenvectors;    // eigenvectors: V, N × N
  Eigen::MatrixXcd eigen_inputs;    // eigenvectors: V⁻¹B
  std::vector<std::complex<double>> eigenvalues;  // eigenvectors, jordan: λ_i in V's column order
  std::vector<bool> chained;        // jordan: η_i' also has + η_(i+1)
  double jordan_residual = 0;       // jordan: JordanBasis::residual
};

/// `second_order_inputs`: B of M q'' + … = B u (n × inputs); `state_inputs`: B of x' = A x + B u.
PrincipalCoordinates principal_coordinates(const ModalAnalysis& modes, const Eigen::MatrixXd& second_order_inputs,
                                           const Eigen::MatrixXd& A, const Eigen::MatrixXd& state_inputs,
                                           const JordanStructure& structure);

}  // namespace eomgen::runtime
