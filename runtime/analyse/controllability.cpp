#include "analyse/controllability.hpp"

#include <cmath>

#include <Eigen/Eigenvalues>

#include "analyse/linear_system.hpp"

namespace eomgen::runtime {

namespace {

using ComplexMatrix = Eigen::MatrixXcd;

double tolerance_for(const Eigen::MatrixXd& A, const Eigen::MatrixXd& other) {
  double size = std::max({1.0, A.cwiseAbs().maxCoeff(), other.size() ? other.cwiseAbs().maxCoeff() : 0.0});
  return 1e-9 * size * static_cast<double>(A.rows());
}

int rank_of(const Eigen::MatrixXd& X, double tolerance) {
  if (X.size() == 0) return 0;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(X);
  int rank = 0;
  for (Eigen::Index i = 0; i < svd.singularValues().size(); ++i) rank += svd.singularValues()(i) > tolerance;
  return rank;
}

// the singular vector of the smallest singular value, and whether that value is zero
std::pair<bool, Eigen::VectorXcd> null_direction(const ComplexMatrix& X, double tolerance, bool left) {
  Eigen::JacobiSVD<ComplexMatrix> svd(X, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Index rank = 0;
  for (Eigen::Index i = 0; i < svd.singularValues().size(); ++i) rank += svd.singularValues()(i) > tolerance;
  Eigen::Index needed = left ? X.rows() : X.cols();
  if (rank >= needed) return {false, {}};
  return {true, left ? Eigen::VectorXcd(svd.matrixU().col(needed - 1)) : Eigen::VectorXcd(svd.matrixV().col(needed - 1))};
}

}  // namespace

Reach controllability_and_observability(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& C) {
  Reach r;
  Eigen::Index n = A.rows();
  // Kalman: rank [B, AB, …, A^{n−1} B] and rank [C; CA; …; C A^{n−1}]
  Eigen::MatrixXd reach(n, B.cols() * n), see(C.rows() * n, n), AkB = B, CAk = C;
  for (Eigen::Index k = 0; k < n; ++k) {
    reach.middleCols(k * B.cols(), B.cols()) = AkB, AkB = A * AkB;
    see.middleRows(k * C.rows(), C.rows()) = CAk, CAk = CAk * A;
  }
  r.kalman_controllability_rank = rank_of(reach, tolerance_for(A, reach));
  r.kalman_observability_rank = rank_of(see, tolerance_for(A, see));
  // PBH: λ is controllable iff rank [A − λI, B] = n, observable iff rank [A − λI; C] = n
  double tolerance = tolerance_for(A, B.size() ? B : C);
  for (const EigenvalueStructure& e : jordan_structure(A).eigenvalues) {
    ModeReach m;
    m.eigenvalue = e.value;
    ComplexMatrix shifted = A.cast<std::complex<double>>() - e.value * ComplexMatrix::Identity(n, n);
    ComplexMatrix wide(n, n + B.cols()), tall(n + C.rows(), n);
    wide << shifted, B.cast<std::complex<double>>();
    tall << shifted, C.cast<std::complex<double>>();
    auto [lost, w] = null_direction(wide, tolerance, true);
    auto [hidden, v] = null_direction(tall, tolerance, false);
    m.controllable = !lost, m.observable = !hidden;
    m.unreachable = w, m.unseen = v;
    r.controllable = r.controllable && m.controllable;
    r.observable = r.observable && m.observable;
    r.modes.push_back(m);
  }
  return r;
}

}  // namespace eomgen::runtime
