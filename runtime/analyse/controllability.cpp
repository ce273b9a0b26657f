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

std::complex<double> TransferFunction::at(std::complex<double> s) const {
  Eigen::Index n = A.rows();
  Eigen::MatrixXcd resolvent = s * Eigen::MatrixXcd::Identity(n, n) - A.cast<std::complex<double>>();
  Eigen::VectorXcd x = resolvent.partialPivLu().solve(b.cast<std::complex<double>>());
  return c.cast<std::complex<double>>().dot(x) + d;  // dot conjugates its first argument: c is real
}

TransferFunction transfer_function(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& C,
                                   const Eigen::MatrixXd& D, Eigen::Index i, Eigen::Index j) {
  TransferFunction g;
  Eigen::Index n = A.rows();
  g.A = A, g.b = B.col(j), g.c = C.row(i).transpose(), g.d = D(i, j);
  Eigen::EigenSolver<Eigen::MatrixXd> poles(A, false);
  for (Eigen::Index k = 0; k < n; ++k) g.poles.push_back(poles.eigenvalues()(k));
  // det [[A − sI, b], [c, d]] = 0: the pencil ([[A, b], [c, d]], [[I, 0], [0, 0]])
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(n + 1, n + 1), Q = Eigen::MatrixXd::Zero(n + 1, n + 1);
  P.topLeftCorner(n, n) = A, P.topRightCorner(n, 1) = g.b, P.bottomLeftCorner(1, n) = g.c.transpose(), P(n, n) = g.d;
  Q.topLeftCorner(n, n).setIdentity();
  Eigen::GeneralizedEigenSolver<Eigen::MatrixXd> pencil(P, Q, false);
  double size = std::max(1.0, P.cwiseAbs().maxCoeff());
  for (Eigen::Index k = 0; k < n + 1; ++k) {
    std::complex<double> alpha = pencil.alphas()(k);
    double beta = pencil.betas()(k);
    if (std::abs(beta) > 1e-10 * std::abs(alpha) && std::abs(beta) > 1e-14) {
      std::complex<double> z = alpha / beta;
      if (std::abs(z) < 1e8 * size) g.zeros.push_back(z);
    }
  }
  // k from G at a point away from poles and zeros
  std::complex<double> s0(0.37 * size + 1.1, 0.61 * size + 0.7), ratio = g.at(s0);
  for (const auto& p : g.poles) ratio *= (s0 - p);
  for (const auto& z : g.zeros) ratio /= (s0 - z);
  g.gain = ratio.real();
  return g;
}

}  // namespace eomgen::runtime
