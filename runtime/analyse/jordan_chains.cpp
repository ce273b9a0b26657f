#include "analyse/jordan_chains.hpp"

#include <algorithm>

#include "analyse/system_scales.hpp"

namespace eomgen::runtime {

namespace {

using ComplexMatrix = Eigen::MatrixXcd;

// an orthonormal basis of the null space of X of the given dimension (its smallest singular directions)
ComplexMatrix null_space(const ComplexMatrix& X, Eigen::Index dimension) {
  Eigen::JacobiSVD<ComplexMatrix> svd(X, Eigen::ComputeFullV);
  return svd.matrixV().rightCols(dimension);
}

// `count` orthonormal directions in the span of K that lie outside the span of S
ComplexMatrix outside(const ComplexMatrix& K, const ComplexMatrix& S, Eigen::Index count) {
  ComplexMatrix P = K;
  if (S.cols() > 0) {
    Eigen::HouseholderQR<ComplexMatrix> qr(S);
    ComplexMatrix Q = qr.householderQ() * ComplexMatrix::Identity(S.rows(), S.cols());
    P -= Q * (Q.adjoint() * K);
  }
  Eigen::JacobiSVD<ComplexMatrix> svd(P, Eigen::ComputeThinU);
  return svd.matrixU().leftCols(count);
}

int nullity(const std::vector<int>& blocks, int j) {
  int out = 0;
  for (int b : blocks) out += std::min(b, j);
  return out;
}

// the chains of one eigenvalue, appended to `columns` and `blocks`
void chains_of(const Eigen::MatrixXd& A, const EigenvalueStructure& e, std::vector<Eigen::VectorXcd>& columns,
               std::vector<JordanBasis::Block>& blocks) {
  Eigen::Index n = A.rows();
  ComplexMatrix N = A.cast<std::complex<double>>() - e.value * ComplexMatrix::Identity(n, n);
  int largest = e.jordan_blocks.empty() ? 0 : e.jordan_blocks.front();
  std::vector<ComplexMatrix> kernels{ComplexMatrix(n, 0)};
  ComplexMatrix power = ComplexMatrix::Identity(n, n);
  for (int j = 1; j <= largest; ++j) power = N * power, kernels.push_back(null_space(power, nullity(e.jordan_blocks, j)));
  std::vector<Eigen::VectorXcd> tops;  // the chosen chain tops with their sizes
  std::vector<int> sizes;
  for (int k = largest; k >= 1; --k) {
    Eigen::Index wanted = std::count(e.jordan_blocks.begin(), e.jordan_blocks.end(), k);
    if (wanted == 0) continue;
    // S: ker N^(k−1) and the level-k members of the longer chains
    ComplexMatrix S(n, kernels[k - 1].cols() + Eigen::Index(tops.size()));
    S.leftCols(kernels[k - 1].cols()) = kernels[k - 1];
    for (std::size_t c = 0; c < tops.size(); ++c) {
      Eigen::VectorXcd v = tops[c];
      for (int step = 0; step < sizes[c] - k; ++step) v = N * v;
      S.col(kernels[k - 1].cols() + Eigen::Index(c)) = v;
    }
    ComplexMatrix fresh = outside(kernels[k], S, wanted);
    for (Eigen::Index c = 0; c < fresh.cols(); ++c) tops.push_back(fresh.col(c)), sizes.push_back(k);
  }
  for (std::size_t c = 0; c < tops.size(); ++c) {
    std::vector<Eigen::VectorXcd> chain{tops[c]};
    for (int step = 1; step < sizes[c]; ++step) chain.push_back(N * chain.back());
    blocks.push_back({e.value, sizes[c], Eigen::Index(columns.size())});
    columns.insert(columns.end(), chain.rbegin(), chain.rend());  // eigenvector first
  }
}

}  // namespace

JordanBasis jordan_basis(const Eigen::MatrixXd& unbalanced, const JordanStructure& structure) {
  JordanBasis out;
  Eigen::Index n = unbalanced.rows();
  // the chains of the balanced B = D⁻¹ A D, whose null spaces and ranks do not depend on the
  // states' units (those of A did: a free cart in μm and km), and V = D V_B
  Eigen::VectorXd d = balancing_scales(unbalanced);
  Eigen::MatrixXd A = d.cwiseInverse().asDiagonal() * unbalanced * d.asDiagonal();
  std::vector<Eigen::VectorXcd> columns;
  for (const EigenvalueStructure& e : structure.eigenvalues) chains_of(A, e, columns, out.blocks);
  if (Eigen::Index(columns.size()) != n) {
    out.refusal = "the Jordan blocks found do not span the state space";
    return out;
  }
  ComplexMatrix V(n, n);
  for (Eigen::Index c = 0; c < n; ++c) V.col(c) = columns[std::size_t(c)];
  ComplexMatrix J = ComplexMatrix::Zero(n, n);
  for (const JordanBasis::Block& b : out.blocks)
    for (int i = 0; i < b.size; ++i) {
      J(b.first + i, b.first + i) = b.eigenvalue;
      if (i + 1 < b.size) J(b.first + i, b.first + i + 1) = 1;
    }
  // column by column against what it is computed from, |A| |v_k| + |v_(k−1)| along a chain: the
  // chain's columns differ in length by powers of |A|, and one bound for all grew with |A|
  double scale = A.norm();
  ComplexMatrix residual = A.cast<std::complex<double>>() * V - V * J;
  for (Eigen::Index k = 0; k < n; ++k) {
    double bound = scale * V.col(k).norm() + (k > 0 ? std::abs(J(k - 1, k)) * V.col(k - 1).norm() : 0.0);
    if (bound > 0) out.residual = std::max(out.residual, residual.col(k).norm() / bound);
  }
  // the directions, each column of length one: along a chain the lengths differ by powers of
  // the rate (v and (A − λI) v), which says nothing about dependence
  Eigen::JacobiSVD<ComplexMatrix> svd(V * V.colwise().norm().cwiseInverse().asDiagonal());
  const auto& sigma = svd.singularValues();
  if (sigma(n - 1) < 1e-10 * sigma(0)) out.refusal = "the generalized eigenvectors found are (nearly) dependent";
  out.V = d.cast<std::complex<double>>().asDiagonal() * V;
  return out;
}

}  // namespace eomgen::runtime
