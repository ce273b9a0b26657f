/// @file Controllability and observability of x' = A x + B u, y = C x + D u (Hiller
/// §8.2.3): the Kalman ranks, and the PBH test per eigenvalue, which names the modes
/// an input cannot reach or an output cannot see; and the transfer function of one
/// input–output pair as poles, zeros and gain.
#pragma once

#include <complex>
#include <vector>

#include <Eigen/Dense>

namespace eomgen::runtime {

struct ModeReach {
  std::complex<double> eigenvalue;
  bool controllable = true, observable = true;
  Eigen::VectorXcd unreachable;  // w with w*(A − λI) = 0, w*B = 0 (when not controllable)
  Eigen::VectorXcd unseen;       // v with (A − λI) v = 0, C v = 0 (when not observable)
};

struct Reach {
  int kalman_controllability_rank = 0, kalman_observability_rank = 0;
  bool controllable = true, observable = true;  // by the PBH test
  std::vector<ModeReach> modes;  // one per distinct eigenvalue
};

Reach controllability_and_observability(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& C);

struct TransferFunction {
  std::vector<std::complex<double>> poles, zeros;
  double gain = 0;  // k in G(s) = k Π(s − z)/Π(s − p)
  /// G(s) = C (sI − A)⁻¹ B + D for this pair
  std::complex<double> at(std::complex<double> s) const;
  Eigen::MatrixXd A;
  Eigen::VectorXd b, c;
  double d = 0;
};

/// The transfer function from input `j` to output `i`: zeros are the finite roots of
/// det [[sI − A, −b], [c, d]] (the generalized eigenvalues of the Rosenbrock pencil).
TransferFunction transfer_function(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& C,
                                   const Eigen::MatrixXd& D, Eigen::Index i, Eigen::Index j);

}  // namespace eomgen::runtime
