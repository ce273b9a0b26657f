/// @file K v = ω² M v by Eigen's GeneralizedSelfAdjointEigenSolver (Cholesky of M,
/// then a symmetric eigenproblem): real ω² and M-orthonormal modes by construction,
/// so frequencies of a conservative system have no spurious real parts. Rayleigh
/// damping is detected by fitting D = αM + βK in the least-squares sense.
#include "analyse/modal_analysis.hpp"

#include <cmath>
#include <limits>

#include "analyse/system_scales.hpp"

namespace eomgen::runtime {

namespace {

double largest(const Eigen::MatrixXd& A) { return A.size() ? A.cwiseAbs().maxCoeff() : 0; }

// D = αM + βK over all entries; α, β by least squares, the fit's residual relative to |D|
void fit_rayleigh(const Eigen::MatrixXd& M, const Eigen::MatrixXd& D, const Eigen::MatrixXd& K, ModalAnalysis& out) {
  Eigen::Index n2 = M.size();
  Eigen::MatrixXd basis(n2, 2);
  // each column in units of its largest entry: at a time scale of 1e12 s, K (1e-20) beside M (1e3)
  // had fallen below the decomposition's rank threshold and a car's D = 0.1 T K been called
  // nonproportional
  double units[2] = {largest(M) > 0 ? largest(M) : 1.0, largest(K) > 0 ? largest(K) : 1.0};
  basis.col(0) = Eigen::Map<const Eigen::VectorXd>(M.data(), n2) / units[0];
  basis.col(1) = Eigen::Map<const Eigen::VectorXd>(K.data(), n2) / units[1];
  Eigen::VectorXd target = Eigen::Map<const Eigen::VectorXd>(D.data(), n2);
  Eigen::VectorXd ab = basis.completeOrthogonalDecomposition().solve(target);
  ab(0) /= units[0], ab(1) /= units[1];
  // a coefficient whose term is below the rounding of D is zero: a braking car's D = 0.1 K had been
  // fitted as 1.46e-15 M + 0.1 K
  double rounding = double(M.rows()) * std::numeric_limits<double>::epsilon() * largest(D);
  if (std::abs(ab(0)) * largest(M) <= rounding) ab(0) = 0;
  if (std::abs(ab(1)) * largest(K) <= rounding) ab(1) = 0;
  double residual = largest(D - ab(0) * M - ab(1) * K);
  if (residual <= 1e-10 * largest(D)) {
    out.damping = "proportional";
    out.rayleigh_alpha = ab(0), out.rayleigh_beta = ab(1);
  } else {
    out.damping = "nonproportional";
  }
}

// the frequencies with the coordinate `fixed` held at zero: its row and column removed
std::vector<double> constrained_frequencies(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, Eigen::Index fixed) {
  Eigen::Index n = M.rows();
  std::vector<Eigen::Index> kept;
  for (Eigen::Index i = 0; i < n; ++i)
    if (i != fixed) kept.push_back(i);
  Eigen::MatrixXd m(n - 1, n - 1), k(n - 1, n - 1);
  for (Eigen::Index a = 0; a < n - 1; ++a)
    for (Eigen::Index b = 0; b < n - 1; ++b) m(a, b) = M(kept[a], kept[b]), k(a, b) = K(kept[a], kept[b]);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(k, m);
  std::vector<double> omegas;
  for (Eigen::Index i = 0; i < n - 1; ++i) omegas.push_back(std::sqrt(std::max(0.0, solver.eigenvalues()(i))));
  return omegas;
}

void check_bounds(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, ModalAnalysis& out) {
  double top = 0;
  for (const NaturalMode& mode : out.modes) top = std::max(top, mode.omega * mode.omega);
  for (const NaturalMode& mode : out.modes)
    out.rayleigh_error = std::max(out.rayleigh_error, std::abs(rayleigh_quotient(M, K, mode.shape) - mode.omega * mode.omega) /
                                                          std::max(top, 1e-300));
  Eigen::Index n = M.rows();
  for (Eigen::Index j = 0; n >= 2 && j < n; ++j) {
    ModalAnalysis::Constrained c;
    c.fixed = j;
    c.omegas = constrained_frequencies(M, K, j);
    double slack = 1e-9 * std::sqrt(std::max(top, 1e-300));
    for (std::size_t i = 0; i < c.omegas.size(); ++i)
      c.interlaces = c.interlaces && out.modes[i].omega <= c.omegas[i] + slack && c.omegas[i] <= out.modes[i + 1].omega + slack;
    out.constrained.push_back(c);
  }
}

}  // namespace

std::string symmetric_problem_refusal(const StabilityReport& s) {
  if (s.M.size() == 0) return "the model is in first-order form (Appell or Hamilton): its modes are the eigenvalues of A";
  // G and N against the system's rate in mass-normalized coordinates (1/s and 1/s²), not against
  // |K| + |D| with a floor of 1, which mixed units and took a small system's G for zero
  MassNormalized x = mass_normalized(s.M, s.K, s.D, s.G, s.N);
  if (s.G.size() && x.G.cwiseAbs().maxCoeff() > 1e-12 * x.rate)
    return "gyroscopic forces G couple the coordinates: the modes are the eigenvalues of A";
  if (s.N.size() && x.N.cwiseAbs().maxCoeff() > 1e-12 * x.rate * x.rate)
    return "circulatory forces N are not conservative: the modes are the eigenvalues of A";
  return "";
}

double rayleigh_quotient(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, const Eigen::VectorXd& v) {
  return v.dot(K * v) / v.dot(M * v);
}

ModalAnalysis modal_analysis(const Eigen::MatrixXd& M, const Eigen::MatrixXd& D, const Eigen::MatrixXd& K) {
  ModalAnalysis out;
  double scale_M = largest(M), scale_K = std::max(largest(K), 1e-300);
  if (largest(M - M.transpose()) > 1e-12 * scale_M || largest(K - K.transpose()) > 1e-12 * scale_K) {
    out.refusal = "M or K is not symmetric";
    return out;
  }
  Eigen::LLT<Eigen::MatrixXd> cholesky(M);
  if (cholesky.info() != Eigen::Success) {
    out.refusal = "M is not positive definite";
    return out;
  }
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(K, M);
  const Eigen::VectorXd& squares = solver.eigenvalues();
  const Eigen::MatrixXd& shapes = solver.eigenvectors();  // M-orthonormal
  double zero = 1e-10 * std::max(std::abs(squares.maxCoeff()), 1e-300);
  for (Eigen::Index i = 0; i < squares.size(); ++i) {
    if (squares(i) < -zero) {
      out.refusal = "K is not positive semidefinite: the equilibrium is unstable, it has no natural frequencies";
      return out;
    }
    NaturalMode mode;
    mode.rigid_body = squares(i) <= zero;
    mode.omega = mode.rigid_body ? 0 : std::sqrt(squares(i));
    mode.shape = shapes.col(i);
    Eigen::Index biggest;
    mode.shape.cwiseAbs().maxCoeff(&biggest);
    if (mode.shape(biggest) < 0) mode.shape = -mode.shape;
    out.rigid_body_modes += mode.rigid_body;
    out.modes.push_back(mode);
  }
  Eigen::MatrixXd Phi(M.rows(), static_cast<Eigen::Index>(out.modes.size()));
  for (std::size_t i = 0; i < out.modes.size(); ++i) Phi.col(static_cast<Eigen::Index>(i)) = out.modes[i].shape;
  out.orthonormality_error = largest(Phi.transpose() * M * Phi - Eigen::MatrixXd::Identity(Phi.cols(), Phi.cols()));
  check_bounds(M, K, out);
  if (largest(D) == 0) return out;
  fit_rayleigh(M, D, K, out);
  Eigen::MatrixXd modal = Phi.transpose() * D * Phi;
  double diagonal = modal.diagonal().cwiseAbs().maxCoeff();
  out.coupling = largest(modal - Eigen::MatrixXd(modal.diagonal().asDiagonal())) / std::max(diagonal, 1e-300);
  for (std::size_t i = 0; i < out.modes.size(); ++i)
    if (!out.modes[i].rigid_body) out.modes[i].damping_ratio = modal(Eigen::Index(i), Eigen::Index(i)) / (2 * out.modes[i].omega);
  return out;
}

}  // namespace eomgen::runtime
