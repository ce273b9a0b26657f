#include "analyse/system_scales.hpp"

#include <algorithm>
#include <cmath>

namespace eomgen::runtime {

Eigen::VectorXd balancing_scales(const Eigen::MatrixXd& A) {
  Eigen::MatrixXd B = A;
  const Eigen::Index n = B.rows();
  Eigen::VectorXd scales = Eigen::VectorXd::Ones(n);
  for (bool converged = false; !converged;) {
    converged = true;
    for (Eigen::Index i = 0; i < n; ++i) {
      double column = B.col(i).cwiseAbs().sum() - std::abs(B(i, i)), row = B.row(i).cwiseAbs().sum() - std::abs(B(i, i));
      if (column == 0 || row == 0 || !std::isfinite(column + row)) continue;
      // f = 2^k with column·f ≈ row/f: the column is multiplied by f, the row divided
      double f = 1, c = column;
      while (c < row / 2) f *= 2, c *= 4;
      while (c >= row * 2) f /= 2, c /= 4;
      // only when the norm falls by a fair margin, so that the iteration ends
      if (column * f + row / f < 0.95 * (column + row)) {
        converged = false;
        B.col(i) *= f;
        B.row(i) /= f;
        scales(i) *= f;
      }
    }
  }
  return scales;
}

Eigen::MatrixXd balanced(const Eigen::MatrixXd& A) {
  Eigen::VectorXd t = balancing_scales(A);
  return t.cwiseInverse().asDiagonal() * A * t.asDiagonal();
}

double spectral_scale(const Eigen::MatrixXd& A) { return A.size() == 0 ? 0.0 : balanced(A).cwiseAbs().maxCoeff(); }

double eigenvalue_scale(const Eigen::MatrixXd& balanced_A, const std::vector<std::complex<double>>& eigenvalues) {
  double radius = 0;
  for (const auto& l : eigenvalues) radius = std::max(radius, std::abs(l));
  double largest = balanced_A.size() ? balanced_A.cwiseAbs().maxCoeff() : 0.0;
  return std::max(radius, 1e-6 * largest);
}

MassNormalized mass_normalized(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, const Eigen::MatrixXd& D,
                               const Eigen::MatrixXd& G, const Eigen::MatrixXd& N) {
  MassNormalized out{K, D, G, N, 0};
  if (M.rows() == 0) return out;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(M);
  if (eigen.info() == Eigen::Success && eigen.eigenvalues().minCoeff() > 0) {
    Eigen::MatrixXd L = eigen.operatorInverseSqrt();
    out.K = L * K * L, out.D = L * D * L, out.G = L * G * L, out.N = L * N * L;
  }
  auto largest = [](const Eigen::MatrixXd& X) { return X.size() ? X.cwiseAbs().maxCoeff() : 0.0; };
  out.rate = std::max({std::sqrt(largest(out.K)), largest(out.D), largest(out.G), std::sqrt(largest(out.N))});
  return out;
}

}  // namespace eomgen::runtime
