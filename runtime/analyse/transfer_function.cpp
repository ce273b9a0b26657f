#include "analyse/transfer_function.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

#include "analyse/system_scales.hpp"

namespace eomgen::runtime {

namespace {

// what counts as zero against the size of the quantity it is computed from (rounding of a
// balanced system is about 1e-16 of its scale; eigenvalue clusters split by its square root)
constexpr double relative_zero = 1e-9;

// an orthonormal basis of the Krylov space span{v, A v, A² v, …}: the states v reaches under A
Eigen::MatrixXd krylov_basis(const Eigen::MatrixXd& A, const Eigen::VectorXd& v) {
  const Eigen::Index n = A.rows();
  Eigen::MatrixXd Q(n, 0);
  double size = v.norm(), scale = A.size() ? A.norm() : 0.0;
  if (n == 0 || size == 0) return Q;
  Eigen::VectorXd next = v / size;
  for (Eigen::Index k = 0; k < n; ++k) {
    Q.conservativeResize(n, k + 1);
    Q.col(k) = next;
    Eigen::VectorXd w = A * Q.col(k);
    for (int twice = 0; twice < 2; ++twice) w -= Q * (Q.transpose() * w);  // Gram–Schmidt, repeated for orthogonality
    if (w.norm() <= relative_zero * scale) break;
    next = w / w.norm();
  }
  return Q;
}

std::vector<std::complex<double>> eigenvalues_of(const Eigen::MatrixXd& A) {
  std::vector<std::complex<double>> out;
  if (A.rows() == 0) return out;
  Eigen::EigenSolver<Eigen::MatrixXd> solver(A, false);
  for (Eigen::Index k = 0; k < A.rows(); ++k) out.push_back(solver.eigenvalues()(k));
  return out;
}

// the null space of the r rows of R, which are independent (their sizes differ by powers of
// the system's rate: each is scaled to one first), orthonormal
Eigen::MatrixXd null_space(Eigen::MatrixXd R) {
  for (Eigen::Index k = 0; k < R.rows(); ++k) R.row(k).normalize();
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(R, Eigen::ComputeFullV);
  return svd.matrixV().rightCols(R.cols() - R.rows());
}

// c A^k b, k = 0 … n − 1, of the balanced system, each beside the bound |c| |A|^k |b| (entries'
// absolute values) on its rounding: above 1e4 n ε of that bound it is nonzero, whatever the basis.
// The bound scales as the value does under any diagonal change of units and any time scale. Read
// off c in the Krylov basis alone, a Markov parameter of a basis whose states differ by 1e13 in
// size (a free cart of 1e-9 kg on a time scale of 1e-12 s) fell within the rounding allowed there.
struct MarkovParameters {
  std::vector<double> value, bound;
  MarkovParameters(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const Eigen::VectorXd& c) {
    Eigen::VectorXd power = b, size = b.cwiseAbs();
    for (Eigen::Index k = 0; k < A.rows(); ++k) {
      value.push_back(c.dot(power)), bound.push_back(c.cwiseAbs().dot(size));
      power = A * power, size = A.cwiseAbs() * size;
    }
  }
  bool nonzero(Eigen::Index k) const {
    auto i = static_cast<std::size_t>(k);
    double n = double(value.size());
    return i < value.size() && std::abs(value[i]) > 1e4 * n * std::numeric_limits<double>::epsilon() * bound[i];
  }
};

// zeros and gain with d = 0: the relative degree r is the first k with c A^(k−1) b ≠ 0, the gain
// that Markov parameter; y ≡ 0 keeps x in the null space N of [c; c A; …; c A^(r−1)], where the
// input u = −(c A^(r−1) b)⁻¹ c A^r x leaves x' = (A − b (c A^(r−1) b)⁻¹ c A^r) x: its n − r
// eigenvalues on N are the zeros
void zero_dynamics(TransferFunction& g, double c_before_reduction, const MarkovParameters& markov) {
  const Eigen::Index n = g.A.rows();
  // in the Krylov basis of b (A Hessenberg): c A^k b = 0 for k < r exactly when c's first r
  // components are 0. The k-th basis vector is A times the one before less its projections;
  // when that remainder, A's subdiagonal h_k, is small against |A| the vector carries rounding
  // of ε |A|/h_k, and so does c's k-th component, against c's size before the modes the input
  // does not reach were dropped: below 1e4 times that it is zero
  const double epsilon = std::numeric_limits<double>::epsilon(), size = g.A.norm();
  auto rounding = [&](Eigen::Index k) {
    double h = k == 0 ? size : std::abs(g.A(k, k - 1));
    return 1e4 * epsilon * c_before_reduction * (h > 0 ? std::max(1.0, size / h) : 1.0);
  };
  Eigen::Index r = 0;
  while (r < n && std::abs(g.c(r)) <= rounding(r) && !markov.nonzero(r)) ++r;
  ++r;
  Eigen::MatrixXd rows(r, n);
  Eigen::RowVectorXd cAk = g.c.transpose();
  for (Eigen::Index k = 0; k < r; ++k) {
    rows.row(k) = cAk;
    if (k + 1 < r) cAk = cAk * g.A;
  }
  g.gain = cAk.dot(g.b);
  if (r >= n) return;  // no finite zeros
  Eigen::MatrixXd N = null_space(rows);
  Eigen::MatrixXd closed = g.A - g.b * (cAk * g.A) / g.gain;
  g.zeros = eigenvalues_of(N.transpose() * closed * N);
}

// A multiple root splits in rounding by about ε^(1/k) of the roots' scale (a free cart's double
// pole at 0 into ±4e-11 beside its pendulum's 5e-3, which made G(0) finite): roots within the
// cluster tolerance of each other are one, at their mean, and a root within rounding of zero or of
// the real axis is there exactly.
void merge_multiple_roots(std::vector<std::complex<double>>& roots, double scale) {
  const double near = relative_cluster_tolerance * scale, zero = relative_zero * scale;
  std::vector<int> cluster(roots.size(), -1);
  for (std::size_t i = 0; i < roots.size(); ++i) {
    if (cluster[i] >= 0) continue;
    cluster[i] = int(i);
    for (bool grew = true; grew;) {  // single linkage: a chain of near roots is one cluster
      grew = false;
      for (std::size_t j = 0; j < roots.size(); ++j)
        for (std::size_t k = 0; k < roots.size() && cluster[j] < 0; ++k)
          if (cluster[k] == int(i) && std::abs(roots[j] - roots[k]) <= near) cluster[j] = int(i), grew = true;
    }
  }
  std::vector<std::complex<double>> merged(roots.size());
  for (std::size_t i = 0; i < roots.size(); ++i) {
    std::complex<double> sum = 0;
    int members = 0;
    for (std::size_t j = 0; j < roots.size(); ++j)
      if (cluster[j] == cluster[i]) sum += roots[j], ++members;
    std::complex<double> mean = sum / double(members);
    merged[i] = {std::abs(mean.real()) <= zero ? 0.0 : mean.real(), std::abs(mean.imag()) <= zero ? 0.0 : mean.imag()};
  }
  roots = merged;
}

}  // namespace

std::complex<double> TransferFunction::at(std::complex<double> s) const {
  Eigen::Index n = A.rows();
  if (n == 0) return d;
  Eigen::MatrixXcd resolvent = s * Eigen::MatrixXcd::Identity(n, n) - A.cast<std::complex<double>>();
  Eigen::VectorXcd x = resolvent.partialPivLu().solve(b.cast<std::complex<double>>());
  return c.cast<std::complex<double>>().dot(x) + d;  // dot conjugates its first argument: c is real
}

std::complex<double> TransferFunction::dc_gain() const {
  double scale = 0;
  for (const auto& p : poles) scale = std::max(scale, std::abs(p));
  for (const auto& z : zeros) scale = std::max(scale, std::abs(z));
  std::complex<double> value = gain;
  for (const auto& p : poles) {
    if (std::abs(p) <= relative_zero * scale) return {INFINITY, 0};
    value /= -p;
  }
  for (const auto& z : zeros) value *= -z;
  return value;
}

TransferFunction transfer_function(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& C,
                                   const Eigen::MatrixXd& D, Eigen::Index i, Eigen::Index j) {
  TransferFunction g;
  g.d = D(i, j);
  // balanced coordinates x = T x̃: the same G(s), every state on the eigenvalues' scale
  Eigen::VectorXd t = balancing_scales(A);
  Eigen::MatrixXd At = t.cwiseInverse().asDiagonal() * A * t.asDiagonal();
  Eigen::VectorXd bt = B.col(j).cwiseQuotient(t), ct = C.row(i).transpose().cwiseProduct(t);
  // the states the output sees, then, among them, those the input reaches: the last basis is
  // the Krylov basis of b, in which A is Hessenberg and c A^k b vanishes exactly as c's first
  // k + 1 components do (the relative degree is read off c, not off Markov parameters)
  Eigen::MatrixXd W = krylov_basis(At.transpose(), ct);
  Eigen::MatrixXd A1 = W.transpose() * At * W;
  Eigen::VectorXd b1 = W.transpose() * bt, c1 = W.transpose() * ct;
  Eigen::MatrixXd V = krylov_basis(A1, b1);
  g.A = V.transpose() * A1 * V, g.b = V.transpose() * b1, g.c = V.transpose() * c1;
  g.removed_modes = static_cast<int>(A.rows() - g.A.rows());
  g.poles = eigenvalues_of(g.A);
  if (g.A.rows() == 0) {
    g.gain = g.d;
  } else if (g.d != 0) {
    // relative degree 0: y ≡ 0 needs u = −c x / d
    g.gain = g.d;
    g.zeros = eigenvalues_of(g.A - g.b * g.c.transpose() / g.d);
  } else {
    zero_dynamics(g, c1.norm(), MarkovParameters(At, bt, ct));
  }
  double scale = g.A.rows() ? spectral_scale(g.A) : 0.0;
  for (const auto& root : g.poles) scale = std::max(scale, std::abs(root));
  for (const auto& root : g.zeros) scale = std::max(scale, std::abs(root));
  merge_multiple_roots(g.poles, scale);
  merge_multiple_roots(g.zeros, scale);
  return g;
}

}  // namespace eomgen::runtime
