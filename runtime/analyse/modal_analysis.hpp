/// @file Small oscillations of M q'' + D q' + K q = 0 about an equilibrium (Hiller
/// §8.1): natural frequencies and mass-normalized mode shapes from the symmetric-
/// definite problem K v = ω² M v, rigid-body modes (ω = 0) counted, and the modal
/// damping ratios, exact when D is proportional (Rayleigh: D = αM + βK).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "analyse/linear_stability.hpp"

namespace eomgen::runtime {

struct NaturalMode {
  double omega = 0;         // rad/s
  double damping_ratio = 0; // (ΦᵀDΦ)_ii / (2 ω_i); exact for proportional damping
  Eigen::VectorXd shape;    // mass-normalized: vᵀ M v = 1, largest component positive
  bool rigid_body = false;  // ω = 0 within rounding
};

struct ModalAnalysis {
  std::string refusal;  // why the symmetric problem does not apply (empty when it does)
  std::vector<NaturalMode> modes;  // by increasing ω
  int rigid_body_modes = 0;
  /// "none" (D = 0), "proportional" (D = αM + βK within rounding) or "nonproportional"
  std::string damping = "none";
  double rayleigh_alpha = 0, rayleigh_beta = 0;
  /// the largest |off-diagonal entry| of ΦᵀDΦ relative to its largest diagonal one: the error
  /// of treating the modes as decoupled by the damping (0 when proportional)
  double coupling = 0;
  double orthonormality_error = 0;  // max |ΦᵀMΦ − I|
  /// max |R(φ_i) − ω_i²| / max ω²: Rayleigh's quotient is exact at each mode (§8.1.4)
  double rayleigh_error = 0;
  /// §8.1.4: fixing one coordinate (a constraint) gives frequencies that interlace the free
  /// system's, ω_i ≤ ω̃_i ≤ ω_{i+1}; one entry per coordinate (two coordinates or more)
  struct Constrained {
    Eigen::Index fixed = 0;
    std::vector<double> omegas;
    bool interlaces = true;
  };
  std::vector<Constrained> constrained;
};

/// Why K v = ω² M v does not describe the motion of this linearization (first-order form,
/// gyroscopic or circulatory forces: the eigenvalues of A do then), or empty.
std::string symmetric_problem_refusal(const StabilityReport& linearization);

/// M symmetric positive definite, K symmetric (the conservative stiffness), D symmetric.
ModalAnalysis modal_analysis(const Eigen::MatrixXd& M, const Eigen::MatrixXd& D, const Eigen::MatrixXd& K);

/// Rayleigh's quotient vᵀKv / vᵀMv: an upper bound of ω₁², exact at the first mode (§8.1.4).
double rayleigh_quotient(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, const Eigen::VectorXd& v);

}  // namespace eomgen::runtime
