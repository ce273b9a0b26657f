/// @file The transfer function of one input–output pair of ẋ = A x + B u, y = C x + D u,
/// as poles, zeros and gain, from its minimal realization: only the modes the input
/// reaches and the output sees (a mode that is not both cancels, as the cart's position
/// does from the force to the pendulum's angle), in balanced coordinates, with every rank
/// and every zero coefficient decided relative to the system's own scale. The zeros are
/// the eigenvalues of the zero dynamics (the motion that keeps y ≡ 0), n − r of them for
/// relative degree r: a zero pencil's rounding gives no spurious zeros near infinity.
#pragma once

#include <complex>
#include <vector>

#include <Eigen/Dense>

namespace eomgen::runtime {

struct TransferFunction {
  std::vector<std::complex<double>> poles, zeros;
  double gain = 0;  // k in G(s) = k Π(s − z)/Π(s − p)
  /// The minimal realization: G(s) = c (sI − A)⁻¹ b + d; A is 0×0 when G is the constant d
  Eigen::MatrixXd A;
  Eigen::VectorXd b, c;
  double d = 0;
  int removed_modes = 0;  // modes the input does not reach or the output does not see
  /// G(s) for this pair
  std::complex<double> at(std::complex<double> s) const;
  /// G(0) from the poles, zeros and gain: infinite for a pole at 0 (within the relative
  /// tolerance of the poles' scale)
  std::complex<double> dc_gain() const;
  bool constant() const { return A.rows() == 0; }
};

/// The transfer function from input `j` to output `i`.
TransferFunction transfer_function(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& C,
                                   const Eigen::MatrixXd& D, Eigen::Index i, Eigen::Index j);

}  // namespace eomgen::runtime
