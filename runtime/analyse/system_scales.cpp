#include "analyse/system_scales.hpp"

#include <algorithm>
#include <cmath>

namespace eomgen::runtime {

namespace {

// Parlett and Reinsch: each state's row and column brought to the same size by powers of two
void balance_rows_and_columns(Eigen::MatrixXd& B, Eigen::VectorXd& scales) {
  const Eigen::Index n = B.rows();
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
}

// A state on whose value no other state's rate depends (a zero column: a free cart's
// position), or whose rate depends on no other state (a zero row), has no balance of its
// own: Parlett and Reinsch leave its scale where it was, and its neighbours' with it (the
// free cart's speed at 2^14 in a system whose entries are 5e9). It takes the scale at which
// its entries are as large as the largest off the diagonal among the other states' (its own
// had set the scale for itself: a braking car's free position and speed kept x' = 1 · v beside
// rates of 1e-12 1/s, which then clustered every eigenvalue into one); true when a scale moved
// by more than a factor of two.
bool scale_one_sided_states(Eigen::MatrixXd& B, Eigen::VectorXd& scales) {
  bool moved = false;
  for (Eigen::Index i = 0; i < B.rows(); ++i) {
    Eigen::MatrixXd off_diagonal = B - Eigen::MatrixXd(B.diagonal().asDiagonal());
    double column = off_diagonal.col(i).cwiseAbs().maxCoeff(), row = off_diagonal.row(i).cwiseAbs().maxCoeff();
    off_diagonal.row(i).setZero();
    off_diagonal.col(i).setZero();
    double largest = off_diagonal.cwiseAbs().maxCoeff();
    // one-sided, and another state to take the scale from (a triangular 2×2 has none)
    if ((column == 0) == (row == 0) || largest == 0) continue;
    double f = std::exp2(std::round(std::log2(column == 0 ? row / largest : largest / column)));
    if (!std::isfinite(f) || (f <= 2 && f >= 0.5)) continue;
    B.col(i) *= f;
    B.row(i) /= f;
    scales(i) *= f;
    moved = true;
  }
  return moved;
}

}  // namespace

Eigen::VectorXd balancing_scales(const Eigen::MatrixXd& A) {
  Eigen::MatrixXd B = A;
  Eigen::VectorXd scales = Eigen::VectorXd::Ones(B.rows());
  if (B.rows() == 0) return scales;
  // each round moves a one-sided state's neighbours half-way (in the exponent) to the others'
  // scale: 64 rounds cover any range of doubles
  for (int round = 0; round < 64; ++round) {
    balance_rows_and_columns(B, scales);
    if (!scale_one_sided_states(B, scales)) break;
  }
  return scales;
}

Eigen::MatrixXd balanced(const Eigen::MatrixXd& A) {
  Eigen::VectorXd t = balancing_scales(A);
  return t.cwiseInverse().asDiagonal() * A * t.asDiagonal();
}

std::vector<std::complex<double>> balanced_eigenvalues(const Eigen::MatrixXd& A) {
  if (A.rows() == 0) return {};
  Eigen::EigenSolver<Eigen::MatrixXd> solver(balanced(A), false);
  const Eigen::VectorXcd& values = solver.eigenvalues();
  return {values.data(), values.data() + values.size()};
}

RateRange rate_range(const Eigen::MatrixXd& A) {
  // std::max(0, NaN) is 0: a non-finite A would otherwise give the finite rates of its other entries
  if (!A.allFinite()) return {std::nan(""), std::nan("")};
  std::vector<std::complex<double>> rates = balanced_eigenvalues(A);
  RateRange range;
  for (const std::complex<double>& r : rates) range.fastest = std::max(range.fastest, std::abs(r));
  range.slowest = range.fastest;
  for (const std::complex<double>& r : rates)
    if (std::abs(r) > relative_cluster_tolerance * range.fastest) range.slowest = std::min(range.slowest, std::abs(r));
  return range;
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
