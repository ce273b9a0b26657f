/// @file The stage equations Z_i = h Σ_j a_ij F(t + c_i h, x + Z_j), i = 1, 2, with
///     c = 1/2 ∓ √3/6,  A = [[1/4, 1/4 − √3/6], [1/4 + √3/6, 1/4]],  b = [1/2, 1/2],
/// are solved by simplified Newton iteration with the Jacobian J = ∂F/∂x at the start
/// of the step, (I − h A⊗J) ΔZ = −Z + h (A⊗I) F(Z); then x(t + h) = x + d_1 Z_1 + d_2 Z_2
/// with d = bᵀA⁻¹ = [−√3, √3], which needs no further evaluation of F.
#include "integrate/gauss_legendre.hpp"

#include <cmath>

namespace eomgen::runtime {

namespace {

const double root3 = std::sqrt(3.0);
const double c[2] = {0.5 - root3 / 6, 0.5 + root3 / 6};
const double a[2][2] = {{0.25, 0.25 - root3 / 6}, {0.25 + root3 / 6, 0.25}};
const double d[2] = {-root3, root3};

}  // namespace

bool GaussLegendreStep::step(RightHandSide& f, double t, double h, std::vector<double>& x) {
  const Eigen::Index n = static_cast<Eigen::Index>(n_);
  Eigen::Map<Eigen::VectorXd> state(x.data(), n);
  Eigen::Matrix<double, -1, -1, Eigen::RowMajor> J(n, n);
  if (f.jacobian(t, x.data(), J.data()) || !J.allFinite()) return false;
  ++jacobians_;
  Eigen::MatrixXd system = Eigen::MatrixXd::Identity(2 * n, 2 * n);
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) system.block(i * n, j * n, n, n) -= h * a[i][j] * J;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu(system);
  // first guess: the previous step's increments scaled to this step, else zero
  Eigen::VectorXd z = z_.size() == 2 * n ? z_ : Eigen::VectorXd::Zero(2 * n);
  Eigen::VectorXd stage(n), value(2 * n), residual(2 * n);
  // the size that roundoff is judged against: the state's and the stages' own, with no floor of one
  // unit (a quartic oscillator of 1e-9 m had its stages solved to 1e-15 m, 1e-6 of itself, and its
  // energy drifted three times as fast as at 1 m)
  const double state_size = state.cwiseAbs().maxCoeff();
  double previous = INFINITY;
  for (int iteration = 0; iteration < 40; ++iteration) {
    for (int i = 0; i < 2; ++i) {
      stage = state + z.segment(i * n, n);
      if (f(t + c[i] * h, stage.data(), value.data() + i * n)) return false;
    }
    for (int i = 0; i < 2; ++i)
      residual.segment(i * n, n) = -z.segment(i * n, n) + h * (a[i][0] * value.segment(0, n) + a[i][1] * value.segment(n, n));
    Eigen::VectorXd correction = lu.solve(residual);
    z += correction;
    if (!z.allFinite()) return false;
    // converged to roundoff, or stalled there: what symplecticity needs (a loose tolerance
    // would let the energy drift as an explicit method's does)
    double size = correction.cwiseAbs().maxCoeff(), scale = std::max(state_size, z.cwiseAbs().maxCoeff());
    bool converged = size <= 1e-15 * scale || (size <= 1e-12 * scale && size >= 0.5 * previous);
    previous = size;
    if (converged) {
      state += d[0] * z.segment(0, n) + d[1] * z.segment(n, n);
      z_ = z;
      return true;
    }
  }
  return false;
}

}  // namespace eomgen::runtime
