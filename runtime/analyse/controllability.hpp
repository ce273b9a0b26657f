/// @file Controllability and observability of x' = A x + B u, y = C x + D u (Hiller
/// §8.2.3): the Kalman ranks, and the PBH test per eigenvalue, which names the modes
/// an input cannot reach or an output cannot see. The transfer function of one pair is in
/// transfer_function.hpp.
#pragma once

#include <complex>
#include <vector>

#include <Eigen/Dense>

#include "analyse/transfer_function.hpp"

namespace eomgen::runtime {

struct ModeReach {
  std::complex<double> eigenvalue;
  bool controllable = true, observable = true;
  /// w with w*(A − λI) = 0, w*B = 0 (when not controllable), and v with (A − λI) v = 0, C v = 0
  /// (when not observable), in balanced coordinates: each state's component on the eigenvalues'
  /// scale, not in its own units, so that their sizes say which states take part
  Eigen::VectorXcd unreachable, unseen;
};

/// The Kalman ranks are the dimensions of the reachable and the observable spaces (orthonormal
/// Krylov bases of the system in balanced coordinates, on a time scale of one, inputs and outputs
/// of unit size), decided relative to the system's own scales.
struct Reach {
  int kalman_controllability_rank = 0, kalman_observability_rank = 0;
  bool controllable = true, observable = true;  // by the PBH test
  std::vector<ModeReach> modes;  // one per distinct eigenvalue
};

Reach controllability_and_observability(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& C);

}  // namespace eomgen::runtime
