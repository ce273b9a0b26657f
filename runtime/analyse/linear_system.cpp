#include "analyse/linear_system.hpp"

#include <algorithm>
#include <cmath>

#include <unsupported/Eigen/MatrixFunctions>

#include "analyse/system_scales.hpp"

namespace eomgen::runtime {

namespace {

using ComplexMatrix = Eigen::MatrixXcd;

// the rank of X with singular values below `tolerance` taken as zero; `uncertain` is set
// when one lies within a factor 100 of it
int rank_of(const ComplexMatrix& X, double tolerance, bool& uncertain) {
  Eigen::JacobiSVD<ComplexMatrix> svd(X);
  int rank = 0;
  for (Eigen::Index i = 0; i < svd.singularValues().size(); ++i) {
    double sigma = svd.singularValues()(i);
    if (sigma > tolerance) ++rank;
    if (sigma > tolerance / 100 && sigma < tolerance * 100) uncertain = true;
  }
  return rank;
}

}  // namespace

JordanStructure jordan_structure(const Eigen::MatrixXd& unbalanced) {
  JordanStructure out;
  Eigen::Index n = unbalanced.rows();
  if (n == 0) return out;
  // in balanced coordinates (the same eigenvalues and ranks), against their own scale: the
  // structure does not change when the system is scaled in time or in units
  Eigen::MatrixXd A = balanced(unbalanced);
  double size = A.cwiseAbs().maxCoeff();
  out.rank_tolerance = 1e-9 * size * static_cast<double>(n);
  Eigen::EigenSolver<Eigen::MatrixXd> solver(A, false);
  std::vector<std::complex<double>> values(solver.eigenvalues().data(), solver.eigenvalues().data() + n);
  // a Jordan block of size k splits its eigenvalue by about (ε|A|)^(1/k), 6e-6 |A| for k = 3:
  // eigenvalues closer than 1e-4 |A| are taken as one, and the ranks then decide
  double cluster = 1e-4 * size, rounding = 1e-12 * eigenvalue_scale(A, values);
  std::vector<bool> taken(values.size(), false);
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (taken[i]) continue;
    std::complex<double> sum = 0;
    int count = 0;
    for (std::size_t j = i; j < values.size(); ++j)
      if (!taken[j] && std::abs(values[j] - values[i]) <= cluster) taken[j] = true, sum += values[j], ++count;
    EigenvalueStructure e;
    e.value = sum / double(count);
    if (std::abs(e.value.imag()) <= rounding) e.value.imag(0);
    if (std::abs(e.value.real()) <= rounding) e.value.real(0);
    e.algebraic_multiplicity = count;
    // ranks of (A − λI)^k until they stop falling; blocks of size ≥ k: rank_{k−1} − rank_k
    ComplexMatrix shifted = A.cast<std::complex<double>>() - e.value * ComplexMatrix::Identity(n, n), power = shifted;
    std::vector<int> ranks{static_cast<int>(n)};
    for (int k = 1; k <= count; ++k) {
      ranks.push_back(rank_of(power, out.rank_tolerance * std::pow(size, k - 1), out.uncertain));
      power = power * shifted;
    }
    ranks.push_back(ranks.back());
    e.geometric_multiplicity = ranks[0] - ranks[1];
    // no rank drop: the cluster joined eigenvalues that are close but distinct, or the
    // tolerance is wrong for this matrix; either way the structure is not decided
    if (e.geometric_multiplicity == 0) out.uncertain = true;
    for (int k = count; k >= 1; --k) {
      int at_least_k = ranks[k - 1] - ranks[k], at_least_next = ranks[k] - ranks[k + 1];
      for (int b = 0; b < at_least_k - at_least_next; ++b) e.jordan_blocks.push_back(k);
    }
    out.eigenvalues.push_back(e);
  }
  std::sort(out.eigenvalues.begin(), out.eigenvalues.end(), [](const EigenvalueStructure& a, const EigenvalueStructure& b) {
    return a.value.real() != b.value.real() ? a.value.real() > b.value.real() : a.value.imag() > b.value.imag();
  });
  return out;
}

Eigen::MatrixXd fundamental_matrix(const Eigen::MatrixXd& A, double t) {
  Eigen::MatrixXd At = A * t;
  return At.exp();
}

}  // namespace eomgen::runtime
