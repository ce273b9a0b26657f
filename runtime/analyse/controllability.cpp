#include "analyse/controllability.hpp"

#include <cmath>
#include <optional>

#include <Eigen/Eigenvalues>

#include "analyse/linear_system.hpp"
#include "analyse/system_scales.hpp"

namespace eomgen::runtime {

namespace {

// A vector whose every component, once the space so far is taken off, is below this fraction of
// its rounding bound adds nothing
constexpr double relative_breakdown = 1e-9;

// The system without its units: x = T x̃ with T from balancing_scales(A), A over its spectral
// scale, and each input's column of B and each output's row of C of length one. Reachability and
// observability do not change under any of these; ranks decided in them do not change when the
// system is scaled in time, in its states' units, or in its inputs' and outputs'.
struct UnitFreeSystem {
  Eigen::MatrixXd A, B, C;
  double scale = 1;
  UnitFreeSystem(const Eigen::MatrixXd& A0, const Eigen::MatrixXd& B0, const Eigen::MatrixXd& C0) {
    Eigen::VectorXd t = balancing_scales(A0);
    A = t.cwiseInverse().asDiagonal() * A0 * t.asDiagonal();
    double size = A.size() ? spectral_scale(A) : 0.0;
    scale = size > 0 ? size : 1.0;
    A /= scale;
    B = t.cwiseInverse().asDiagonal() * B0;
    C = C0 * t.asDiagonal();
    for (Eigen::Index j = 0; j < B.cols(); ++j)
      if (B.col(j).norm() > 0) B.col(j).normalize();
    for (Eigen::Index i = 0; i < C.rows(); ++i)
      if (C.row(i).norm() > 0) C.row(i).normalize();
  }
};

// An orthonormal basis of span{B, A B, A² B, …}, the reachable space, whose dimension is the rank
// of Kalman's matrix: grown one vector at a time, each column of B and each A q orthogonalized
// against the basis (twice, for orthogonality) and kept when what is left of some component
// exceeds that component's rounding bound by more than the breakdown test: |b| for B's column,
// |A| |q| for A q, and |Q| |Qᵀ w| for the projections taken off. Kalman's matrix holds columns
// |A|^k apart, whose rank no tolerance decides at every scale; and a test against the vector's
// norm lost a free cart's speed, 241 in a component whose bound was 48 beside a pendulum's 5e12.
Eigen::MatrixXd reachable_space(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) {
  const Eigen::Index n = A.rows();
  Eigen::MatrixXd Q(n, 0);
  auto add = [&](Eigen::VectorXd w, Eigen::VectorXd bound) {
    for (int twice = 0; twice < 2; ++twice) {
      Eigen::VectorXd along = Q.transpose() * w;
      w -= Q * along;
      bound += Q.cwiseAbs() * along.cwiseAbs();
    }
    if (!((w.cwiseAbs() - relative_breakdown * bound).maxCoeff() > 0)) return;
    Q.conservativeResize(n, Q.cols() + 1);
    Q.col(Q.cols() - 1) = w.normalized();
  };
  for (Eigen::Index j = 0; j < B.cols() && Q.cols() < n; ++j) add(B.col(j), B.col(j).cwiseAbs());
  Eigen::MatrixXd magnitude = A.cwiseAbs();
  for (Eigen::Index k = 0; k < Q.cols() && Q.cols() < n; ++k) add(A * Q.col(k), magnitude * Q.col(k).cwiseAbs());
  return Q;
}

// An orthonormal basis of the space orthogonal to Q's columns
Eigen::MatrixXd complement(const Eigen::MatrixXd& Q) {
  const Eigen::Index n = Q.rows();
  if (Q.cols() == 0) return Eigen::MatrixXd::Identity(n, n);
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(Q);
  Eigen::MatrixXd full = qr.householderQ() * Eigen::MatrixXd::Identity(n, n);
  return full.rightCols(n - Q.cols());
}

// The modes of A on the invariant space spanned by `basis` (its eigenvalues, each with its
// eigenvector mapped back into A's coordinates): a mode there has eigenvalue λ when one of them
// lies within the cluster tolerance of λ (A on a scale of one).
struct ModesOn {
  std::vector<std::complex<double>> values;
  std::vector<Eigen::VectorXcd> vectors;
  ModesOn(const Eigen::MatrixXd& A, const Eigen::MatrixXd& basis) {
    if (basis.cols() == 0) return;
    Eigen::EigenSolver<Eigen::MatrixXd> solver(basis.transpose() * A * basis, true);
    for (Eigen::Index k = 0; k < basis.cols(); ++k) {
      values.push_back(solver.eigenvalues()(k));
      vectors.push_back(basis.cast<std::complex<double>>() * solver.eigenvectors().col(k));
    }
  }
  std::optional<Eigen::VectorXcd> at(std::complex<double> lambda) const {
    for (std::size_t k = 0; k < values.size(); ++k)
      if (std::abs(values[k] - lambda) <= relative_cluster_tolerance) return vectors[k];
    return std::nullopt;
  }
};

}  // namespace

Reach controllability_and_observability(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& C) {
  Reach r;
  UnitFreeSystem u(A, B, C);
  Eigen::MatrixXd reachable = reachable_space(u.A, u.B), observable = reachable_space(u.A.transpose(), u.C.transpose());
  r.kalman_controllability_rank = static_cast<int>(reachable.cols());
  r.kalman_observability_rank = static_cast<int>(observable.cols());
  // PBH: λ is uncontrollable iff some w ≠ 0 has w*(A − λI) = 0 and w*B = 0, unobservable iff some
  // v ≠ 0 has (A − λI) v = 0 and C v = 0. In the basis [R, R⊥] of the reachable space R, A is
  // [[A11, A12], [0, A22]], and those w are R⊥ times A22's left eigenvectors; the unobservable space
  // N = O⊥ is invariant, and those v are N times the eigenvectors of A on it. So the modes PBH finds
  // are the eigenvalues of A22 and of A on N: the same decision as the ranks, with no tolerance of
  // its own on A − λI, whose smallest singular value depends on how the states are scaled.
  ModesOn unreachable(u.A.transpose(), complement(reachable)), unseen(u.A, complement(observable));
  for (const EigenvalueStructure& e : jordan_structure(A).eigenvalues) {
    ModeReach m;
    m.eigenvalue = e.value;
    std::complex<double> lambda = e.value / u.scale;
    // w* A22 = λ w* is A22ᵀ w̄ = λ w̄: the conjugate of A22ᵀ's eigenvector for λ
    if (auto w = unreachable.at(lambda)) m.controllable = false, m.unreachable = w->conjugate();
    if (auto v = unseen.at(lambda)) m.observable = false, m.unseen = *v;
    r.controllable = r.controllable && m.controllable;
    r.observable = r.observable && m.observable;
    r.modes.push_back(m);
  }
  return r;
}

}  // namespace eomgen::runtime
