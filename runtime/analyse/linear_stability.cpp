#include "analyse/linear_stability.hpp"

#include "analyse/constrained_first_order.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "analyse/first_order_form.hpp"
#include "analyse/system_scales.hpp"
#include "analyse/turning_symmetries.hpp"

namespace eomgen::runtime {

namespace {

using RowMajor = Eigen::Matrix<double, -1, -1, Eigen::RowMajor>;

struct SecondOrder {
  Eigen::MatrixXd M, P, Q, B;
};

SecondOrder linearize(const Problem& p, const std::vector<double>& x) {
  const eomgen_model_abi& m = *p.model;
  std::size_t n = m.num_coordinates, k = m.num_inputs;
  const double* u = p.held_inputs();
  std::vector<double> M(n * n), P(n * n), Q(n * n), B(n * k + 1);
  m.mass_matrix(0.0, x.data(), p.parameters.data(), M.data());
  m.linearization(0.0, x.data(), u, p.parameters.data(), P.data(), Q.data(), B.data());
  return {Eigen::Map<RowMajor>(M.data(), n, n), Eigen::Map<RowMajor>(P.data(), n, n),
          Eigen::Map<RowMajor>(Q.data(), n, n), Eigen::Map<RowMajor>(B.data(), n, k)};
}

// reduced state: the non-cyclic coordinates, then all velocities
// A = [[0, S], [−M⁻¹Q_r, −M⁻¹P]], with S picking the non-cyclic velocities
void first_order(const eomgen_model_abi& m, const SecondOrder& s, Eigen::MatrixXd& A, Eigen::MatrixXd& B,
                 std::vector<std::string>* names) {
  std::size_t n = m.num_coordinates;
  std::vector<int> kept;
  for (std::size_t i = 0; i < n; ++i)
    if (!m.is_cyclic[i]) kept.push_back(static_cast<int>(i));
  std::size_t r = kept.size(), N = r + n;
  A = Eigen::MatrixXd::Zero(N, N);
  B = Eigen::MatrixXd::Zero(N, s.B.cols());
  Eigen::LDLT<Eigen::MatrixXd> mass(s.M);
  Eigen::MatrixXd Qr(n, r);
  for (std::size_t k = 0; k < r; ++k) {
    A(k, r + kept[k]) = 1;
    Qr.col(k) = s.Q.col(kept[k]);
  }
  A.block(r, 0, n, r) = -mass.solve(Qr);
  A.block(r, r, n, n) = -mass.solve(s.P);
  if (s.B.cols()) B.block(r, 0, n, s.B.cols()) = mass.solve(s.B);
  if (names) {
    names->clear();
    for (int k : kept) names->push_back(m.coordinate_names[k]);
    for (std::size_t i = 0; i < n; ++i) names->push_back(m.state_names[n + i]);
  }
}

// the eigenvalues of A, computed from its balanced form, with the tolerances relative to its
// spectral scale within which a real part is zero and two eigenvalues are one, and each
// eigenvalue's own rounding error ε |B| κ (κ its condition number, from the left and right
// eigenvectors): a nearly defective pair (a Jordan block, split by rounding by about √ε |B|)
// has a large κ and stays one cluster, a triangular B's distinct eigenvalues do not
struct Spectrum {
  std::vector<std::complex<double>> eigenvalues;
  std::vector<double> errors;
  double tolerance, cluster;
  double rounding;  // n ε of the spectral scale: below it, no eigenvalue is told from zero
  Eigen::MatrixXd balanced;
  bool on_axis(std::size_t i) const { return std::abs(eigenvalues[i].real()) <= std::max(tolerance, errors[i]); }
  bool same(std::size_t i, std::size_t j) const {
    return std::abs(eigenvalues[i] - eigenvalues[j]) <= std::max(cluster, 4 * (errors[i] + errors[j]));
  }
};

Spectrum spectrum(const Eigen::MatrixXd& A) {
  Eigen::MatrixXd B = balanced(A);
  Eigen::EigenSolver<Eigen::MatrixXd> solver(B, true);
  Spectrum s{{}, {}, 0, 0, 0, B};
  const Eigen::Index n = A.rows();
  Eigen::MatrixXcd X = solver.eigenvectors(), Y = X.fullPivLu().inverse();
  double size = n ? B.norm() : 0.0;
  std::vector<std::pair<std::complex<double>, double>> pairs;
  for (Eigen::Index i = 0; i < n; ++i) {
    double kappa = X.col(i).norm() * Y.row(i).norm(), error = std::numeric_limits<double>::epsilon() * size * kappa;
    pairs.push_back({solver.eigenvalues()[i], std::isfinite(error) ? std::min(error, size) : size});
  }
  std::sort(pairs.begin(), pairs.end(), [](const auto& a, const auto& b) {
    return a.first.real() != b.first.real() ? a.first.real() > b.first.real() : a.first.imag() > b.first.imag();
  });
  for (const auto& [value, error] : pairs) s.eigenvalues.push_back(value), s.errors.push_back(error);
  double scale = eigenvalue_scale(B, s.eigenvalues);
  s.tolerance = relative_axis_tolerance * scale, s.cluster = relative_cluster_tolerance * scale;
  s.rounding = double(n) * std::numeric_limits<double>::epsilon() * scale;
  return s;
}

// geometric multiplicity of λ: the dimension of the null space of A − λI (A balanced; a pivot
// below the cluster tolerance of the largest is zero)
int null_space_dimension(const Eigen::MatrixXd& A, std::complex<double> lambda) {
  Eigen::MatrixXcd shifted = A.cast<std::complex<double>>();
  shifted.diagonal().array() -= lambda;
  Eigen::FullPivLU<Eigen::MatrixXcd> lu(shifted);
  lu.setThreshold(relative_cluster_tolerance);
  return static_cast<int>(A.rows() - lu.rank());
}

struct Verdict {
  std::string verdict;
  double degree;
  int cyclic_zeros;
  std::vector<std::complex<double>> counted;  // the eigenvalues without the cyclic zeros
  std::vector<double> errors;                 // their own rounding
};

Verdict judge(const Spectrum& s, int cyclic) {
  Verdict v{"asymptotically_stable", -INFINITY, 0, {}, {}};
  std::vector<std::size_t> on_axis;
  for (std::size_t i = 0; i < s.eigenvalues.size(); ++i) {
    std::complex<double> l = s.eigenvalues[i];
    bool zero = std::abs(l) <= std::max(s.cluster, s.errors[i]);
    if (zero && v.cyclic_zeros < cyclic) {  // a conserved cyclic momentum
      ++v.cyclic_zeros;
      continue;
    }
    v.counted.push_back(l);
    v.errors.push_back(s.errors[i]);
    // on the axis within rounding: exactly 0, so an undamped point never counts as decaying
    v.degree = std::max(v.degree, s.on_axis(i) ? 0.0 : l.real());
    if (s.on_axis(i)) on_axis.push_back(i);
    else if (l.real() > 0) v.verdict = "unstable";
  }
  if (v.degree == -INFINITY) v.degree = 0;
  if (v.verdict == "unstable") return v;
  // nothing but conserved momenta (a free mass): a perturbation of them neither grows nor decays
  if (v.counted.empty() && v.cyclic_zeros > 0) v.verdict = "marginally_stable";
  for (std::size_t i : on_axis) {
    int algebraic = 0;
    for (std::size_t k = 0; k < s.eigenvalues.size(); ++k) algebraic += s.same(i, k);
    if (null_space_dimension(s.balanced, s.eigenvalues[i]) < algebraic) {
      v.verdict = "unstable";
      return v;
    }
  }
  if (!on_axis.empty()) v.verdict = "marginally_stable";
  return v;
}

bool positive_definite(const Eigen::MatrixXd& S, double tolerance) {
  return S.rows() == 0 || Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(S).eigenvalues().minCoeff() > tolerance;
}

int negative_eigenvalues(const Eigen::MatrixXd& S, double tolerance) {
  auto values = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(S).eigenvalues();
  return static_cast<int>((values.array() < -tolerance).count());
}

// Hiller §8.2: what the structure M q'' + (D+G) q' + (K+N) q = 0 decides by itself
std::vector<std::string> theorems(const StabilityReport& r, bool has_cyclic) {
  if (has_cyclic)
    return {"force-structure theorems not applied: the reduced system has cyclic coordinates (their velocities stay "
            "in the state)"};
  // in mass-normalized coordinates, rates against the system's rate and stiffnesses against its
  // square: the same decisions in any units and on any time scale
  MassNormalized x = mass_normalized(r.M, r.K, r.D, r.G, r.N);
  double rate_zero = 1e-10 * x.rate, stiffness_zero = 1e-10 * x.rate * x.rate;
  auto largest = [](const Eigen::MatrixXd& X) { return X.size() ? X.cwiseAbs().maxCoeff() : 0.0; };
  bool d0 = largest(x.D) <= rate_zero, g0 = largest(x.G) <= rate_zero, n0 = largest(x.N) <= stiffness_zero;
  bool k_pd = positive_definite(x.K, stiffness_zero), d_pd = positive_definite(x.D, rate_zero);
  int unstable_dof = negative_eigenvalues(x.K, stiffness_zero);
  std::vector<std::string> out;
  if (!n0) {
    if (d0 && g0)
      out.push_back("Merkin: potential and circulatory forces alone cannot make an equilibrium asymptotically stable");
    out.push_back("circulatory forces (N != 0) present: the force structure does not decide, the eigenvalues do "
                  "(divergence or flutter possible)");
    return out;
  }
  if (d0 && g0) {
    if (k_pd) out.push_back("Lagrange-Dirichlet: K positive definite with only potential forces: stable");
    else if (unstable_dof > 0)
      out.push_back(fmt::format("Lyapunov-Chetaev: conservative system with {} negative eigenvalue(s) of K: unstable", unstable_dof));
    return out;
  }
  if (k_pd && d_pd)
    out.push_back("Thomson-Tait-Chetaev: complete damping added to a positive definite K makes the equilibrium "
                  "asymptotically stable, gyroscopic forces or not");
  else if (k_pd)
    out.push_back("Kelvin-Tait: damping and gyroscopic forces cannot destroy the stability of a positive definite K");
  if (!k_pd && unstable_dof > 0 && !g0 && d0) {
    if (unstable_dof % 2 == 1)
      out.push_back(fmt::format("Kelvin-Thomson-Tait: gyroscopic forces cannot stabilize an odd number ({}) of unstable "
                                "degrees of freedom: unstable", unstable_dof));
    else
      out.push_back(fmt::format("Kelvin-Thomson-Tait: gyroscopic stabilization of an even number ({}) of unstable "
                                "degrees of freedom is possible; the eigenvalues decide", unstable_dof));
  }
  if (!k_pd && unstable_dof > 0 && d_pd)
    out.push_back("Thomson-Tait-Chetaev: with complete damping, an equilibrium with K not positive definite is "
                  "unstable (damping destroys gyroscopic stabilization)");
  return out;
}

}  // namespace

std::vector<double> polynomial_from_roots(const std::vector<std::complex<double>>& roots) {
  std::vector<std::complex<double>> c{1.0};
  for (auto r : roots) {
    c.push_back(0.0);
    for (std::size_t k = c.size() - 1; k > 0; --k) c[k] -= r * c[k - 1];
  }
  // a coefficient below the rounding of the roots' elementary symmetric functions is 0
  double size = 0;
  for (auto r : roots) size = std::max(size, std::abs(r));
  std::vector<double> real;
  double bound = 1;  // binomial(n, k) size^k
  for (std::size_t k = 0; k < c.size(); ++k) {
    if (k) bound *= size * static_cast<double>(roots.size() - k + 1) / static_cast<double>(k);
    real.push_back(std::abs(c[k].real()) <= 1e-13 * bound ? 0.0 : c[k].real());
  }
  return real;
}

std::vector<double> hurwitz_determinants(const std::vector<double>& c) {
  int n = static_cast<int>(c.size()) - 1;
  auto at = [&](int k) { return k >= 0 && k <= n ? c[k] : 0.0; };
  Eigen::MatrixXd H(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) H(i, j) = at(2 * j - i + 1);
  std::vector<double> minors;
  for (int k = 1; k <= n; ++k) minors.push_back(H.topLeftCorner(k, k).determinant());
  return minors;
}

ScaledHurwitz scaled_hurwitz_determinants(const std::vector<double>& c) {
  ScaledHurwitz out;
  int n = static_cast<int>(c.size()) - 1;
  if (n <= 0) return out;
  // λ = s μ: a_k λ^(n−k) becomes a_k s^(n−k) μ^(n−k); divided by s^n the polynomial in μ is
  // monic with constant term a_n / s^n = ±1 when s = |a_n|^(1/n)
  double last = std::abs(c[static_cast<std::size_t>(n)]);
  out.scale = last > 0 && std::isfinite(last) ? std::pow(last, 1.0 / n) : 1.0;
  std::vector<double> b(c.size());
  for (int k = 0; k <= n; ++k) b[static_cast<std::size_t>(k)] = c[static_cast<std::size_t>(k)] / std::pow(out.scale, k);
  auto at = [&](int k) { return k >= 0 && k <= n ? b[static_cast<std::size_t>(k)] : 0.0; };
  Eigen::MatrixXd H(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) H(i, j) = at(2 * j - i + 1);
  // the coefficients carry the rounding of the eigenvalues they came from: relative 1e-12 or so
  const double relative_error = 1e-11;
  for (int k = 1; k <= n; ++k) {
    Eigen::MatrixXd block = H.topLeftCorner(k, k);
    double det = block.determinant(), hadamard = 1;
    for (int i = 0; i < k; ++i) hadamard *= std::max(block.row(i).norm(), 1e-300);
    bool lost = std::abs(det) <= relative_error * k * hadamard;
    out.minors.push_back(lost ? 0.0 : det);
    out.ill_conditioned = out.ill_conditioned || lost;
  }
  return out;
}

// zero against the spectral scale, as the verdict decides: a real part within the axis tolerance,
// a determinant (a product of eigenvalues) within it times the scale
std::string phase_plane_type(const Eigen::Matrix2d& A) {
  double tr = A.trace(), det = A.determinant(), scale = spectral_scale(A);
  double tr_zero = 2 * relative_axis_tolerance * scale, eps = relative_axis_tolerance * scale * scale,
         disc = tr * tr - 4 * det;
  auto sense = [&](const char* stable, const char* unstable) { return tr < 0 ? stable : unstable; };
  if (std::abs(det) <= eps)
    return std::abs(tr) <= tr_zero ? "degenerate: zero matrix or uniform motion (double zero eigenvalue)"
                                         : "degenerate: a line of equilibria (one zero eigenvalue)";
  if (det < 0) return "saddle";
  if (std::abs(disc) <= eps)
    return (A - 0.5 * tr * Eigen::Matrix2d::Identity()).cwiseAbs().maxCoeff() <= tr_zero
               ? sense("stable star (proper node)", "unstable star (proper node)")
               : sense("stable degenerate node", "unstable degenerate node");
  if (disc > 0) return sense("stable node", "unstable node");
  if (std::abs(tr) <= tr_zero) return "centre";
  return sense("stable focus", "unstable focus");
}

static bool has_opposite_pair(const std::vector<std::complex<double>>& roots, double tolerance) {
  double scale = 0;
  for (auto l : roots) scale = std::max(scale, std::abs(l));
  for (std::size_t i = 0; i < roots.size(); ++i)
    for (std::size_t j = i; j < roots.size(); ++j)
      if ((i != j || std::abs(roots[i]) <= tolerance * scale) && std::abs(roots[i] + roots[j]) <= tolerance * scale) return true;
  return false;
}

// A modulo the turns that are symmetries (turning_symmetries.hpp): A maps each turn's direction at
// the equilibrium to zero (every turned equilibrium is one), so that on an orthonormal complement W
// of those directions Wᵀ A W is the map A induces on the state modulo them. Its spectrum is A's
// without one zero per turn, and the turn's momentum, whose zero headed a Jordan block with the
// turn's, is left with a zero of its own, like a cyclic coordinate's momentum.
struct ModuloTurns {
  Eigen::MatrixXd A;
  std::vector<TurningSymmetry> symmetries;
  int turns = 0;
};

ModuloTurns modulo_turning_symmetries(const Problem& problem, const std::vector<double>& x, const Eigen::MatrixXd& A) {
  const eomgen_model_abi& m = *problem.model;
  // the sampled states' speed: the balanced A's largest entry, the system's rate (system_scales.hpp)
  ModuloTurns out{A, turning_symmetries(problem, x, spectral_scale(A)), 0};
  std::vector<int> kept = reduced_state(m);
  std::vector<Eigen::VectorXd> directions;
  for (const TurningSymmetry& s : out.symmetries)
    for (const Eigen::Vector3d& a : s.axes) {
      Eigen::VectorXd full = turning_direction(m, x, s.quaternion, a), reduced(long(kept.size()));
      for (std::size_t i = 0; i < kept.size(); ++i) reduced[long(i)] = full[kept[i]];
      directions.push_back(reduced);
    }
  if (directions.empty()) return out;
  Eigen::MatrixXd V(A.rows(), long(directions.size()));
  for (std::size_t j = 0; j < directions.size(); ++j) V.col(long(j)) = directions[j];
  Eigen::MatrixXd Q = Eigen::HouseholderQR<Eigen::MatrixXd>(V).householderQ();
  Eigen::MatrixXd W = Q.rightCols(A.rows() - V.cols());
  out.A = W.transpose() * A * W;
  out.turns = int(directions.size());
  return out;
}

// eigenvalues, verdict, modes, characteristic polynomial and Hurwitz determinants of r.A; the
// verdict from `judged` (r.A modulo the symmetries' turns) where given
void describe_spectrum(StabilityReport& r, int cyclic, const Eigen::MatrixXd* judged = nullptr) {
  Spectrum sp = spectrum(r.A);
  r.eigenvalues = sp.eigenvalues;
  // an eigenvalue within rounding of zero (its own error ε |B| κ, or n ε of the spectral scale) is
  // reported as 0: a car's row of A that is exactly zero had shown a mode of −1.8e-16 rad/s, and the
  // rounding in A of a pendulum's Euler angles at their singularity modes of ±3.5e-32 rad/s
  for (std::size_t i = 0; i < sp.eigenvalues.size(); ++i)
    if (std::abs(sp.eigenvalues[i]) <= std::max(sp.errors[i], sp.rounding)) r.eigenvalues[i] = 0;
  Spectrum reduced = judged ? spectrum(*judged) : sp;
  Verdict v = judge(reduced, cyclic);
  r.verdict = v.verdict, r.stability_degree = v.degree, r.cyclic_zero_eigenvalues = v.cyclic_zeros;
  r.counted_eigenvalues = v.counted;
  r.axis_tolerance = reduced.tolerance;
  for (std::size_t i = 0; i < r.eigenvalues.size(); ++i)
    if (std::complex<double> l = r.eigenvalues[i]; l.imag() >= 0) {
      double size = std::abs(l);
      bool on_axis = sp.on_axis(i);
      r.modes.push_back({l, std::abs(l.imag()), size, size > 0 && !on_axis ? -l.real() / size : 0.0});
    }
  std::stable_sort(r.modes.begin(), r.modes.end(), [](const Mode& a, const Mode& b) {
    return a.undamped_frequency != b.undamped_frequency ? a.undamped_frequency < b.undamped_frequency
                                                        : a.frequency < b.frequency;
  });
  r.characteristic_polynomial = polynomial_from_roots(r.eigenvalues);
  ScaledHurwitz h = scaled_hurwitz_determinants(r.characteristic_polynomial);
  r.hurwitz = h.minors, r.hurwitz_scale = h.scale;
  // a minor vanishes exactly when two roots add up to zero (λ and −λ: a pair on the imaginary
  // axis, a saddle, a zero root); one within rounding without such a pair is lost to rounding
  r.hurwitz_ill_conditioned = h.ill_conditioned && !has_opposite_pair(r.eigenvalues, relative_cluster_tolerance);
  if (r.hurwitz_ill_conditioned)
    for (double& minor : r.hurwitz)
      if (minor == 0) minor = NAN;  // its sign is lost, not zero
}

// Appell's equations: A is the Jacobian of the first-order form on the reduced state;
// zero eigenvalues (families of steady motions) count as on the imaginary axis
StabilityReport analyse_first_order(const Problem& problem, const std::vector<double>& x) {
  const eomgen_model_abi& m = *problem.model;
  StabilityReport r;
  r.A = reduced_jacobian(problem, x);
  r.B_state = reduced_input_jacobian(problem, x);
  for (int i : reduced_state(m)) r.state_names.push_back(m.state_names[i]);
  // a quaternion's length is constant by construction: its zero eigenvalue (eigenvector (q, 0), semisimple
  // since q' = ½ q ⊗ (0, ω) is orthogonal to q) says nothing about the system; nor do a symmetric
  // turn's two (its orbit's, taken out by the quotient, and its momentum's)
  ModuloTurns quotient = modulo_turning_symmetries(problem, x, r.A);
  int quaternions = non_cyclic_quaternions(m);
  describe_spectrum(r, quaternions + quotient.turns, quotient.turns ? &quotient.A : nullptr);
  r.quaternion_zero_eigenvalues = std::min(r.cyclic_zero_eigenvalues, quaternions);
  r.symmetry_zero_eigenvalues = r.cyclic_zero_eigenvalues - r.quaternion_zero_eigenvalues + quotient.turns;
  r.cyclic_zero_eigenvalues = 0;
  r.symmetries = quotient.symmetries;
  for (const TurningSymmetry& s : quotient.symmetries) r.symmetry_names.push_back(describe(m, s));
  r.theorems.push_back("the force classification (D, G, K, N) needs M q'' + P q' + Q q = 0; Appell's equations are of "
                       "first order in the pseudo-velocities, so A is analysed directly");
  if (r.A.rows() == 2) r.phase_plane = phase_plane_type(r.A);
  return r;
}

// Lagrange I: A restricted to the tangent space of the constraint manifold, in the state
// components that parametrize it
StabilityReport analyse_on_manifold(const Problem& problem, const std::vector<double>& x) {
  const eomgen_model_abi& m = *problem.model;
  ManifoldLinearization l = manifold_linearization(problem, x);
  StabilityReport r;
  r.A = l.A, r.B_state = l.B;
  for (int i : l.kept) r.state_names.push_back(m.state_names[i]);
  describe_spectrum(r, 0);
  std::string dependent;
  for (int i : l.dependent) dependent += (dependent.empty() ? "" : ", ") + std::string(m.state_names[i]);
  r.theorems.push_back("the constraints tie " + dependent + " to the others: A is the linearization on the constraint "
                       "manifold, in the remaining state components, and the force classification (D, G, K, N) of the "
                       "unconstrained coordinates does not apply");
  std::string neutral;
  for (int i : l.neutral) neutral += (neutral.empty() ? "" : ", ") + std::string(m.state_names[i]);
  if (!neutral.empty())
    r.theorems.push_back("no rate depends on " + neutral + ": each is a family of steady motions with one zero "
                         "eigenvalue, left out like a cyclic coordinate (stability with respect to the rest)");
  if (r.A.rows() == 2) r.phase_plane = phase_plane_type(r.A);
  return r;
}

void reconcile_with_theorems(StabilityReport& r) {
  // the theorems' first words and what each says about the linearized system
  static const std::vector<std::pair<std::string, std::string>> claims = {
      {"Lagrange-Dirichlet:", "marginally_stable"},
      {"Lyapunov-Chetaev:", "unstable"},
      {"Thomson-Tait-Chetaev: complete damping added", "asymptotically_stable"},
      {"Thomson-Tait-Chetaev: with complete damping", "unstable"},
      {"Kelvin-Thomson-Tait: gyroscopic forces cannot stabilize", "unstable"},
  };
  for (const std::string& theorem : r.theorems)
    for (const auto& [opening, says] : claims)
      if (theorem.rfind(opening, 0) == 0 && says != r.verdict) {
        r.disagreement = fmt::format("the eigenvalues say {} but {} says {}: the rounding of one or the other "
                                     "decides it; neither is reported as the verdict", r.verdict, opening.substr(0, opening.find(':')), says);
        r.verdict = "undecided";
        return;
      }
}

StabilityReport analyse_stability(const Problem& problem, const std::vector<double>& x) {
  const eomgen_model_abi& m = *problem.model;
  if (has_pseudo_velocities(m)) return analyse_first_order(problem, x);
  if (has_multipliers(m)) return analyse_on_manifold(problem, x);
  StabilityReport r;
  SecondOrder s = linearize(problem, x);
  r.M = s.M, r.P = s.P, r.Q = s.Q, r.B = s.B;
  r.D = (s.P + s.P.transpose()) / 2, r.G = (s.P - s.P.transpose()) / 2;
  r.K = (s.Q + s.Q.transpose()) / 2, r.N = (s.Q - s.Q.transpose()) / 2;
  first_order(m, s, r.A, r.B_state, &r.state_names);
  describe_spectrum(r, conserved_cyclic_momenta(m));
  r.theorems = theorems(r, std::count(m.is_cyclic, m.is_cyclic + m.num_coordinates, true) > 0);
  reconcile_with_theorems(r);
  if (r.A.rows() == 2) r.phase_plane = phase_plane_type(r.A);
  return r;
}

CountedSpectrum counted_spectrum(const Problem& problem, const std::vector<double>& x) {
  const eomgen_model_abi& m = *problem.model;
  Eigen::MatrixXd A, B;
  int cyclic = 0;
  if (has_pseudo_velocities(m)) {
    ModuloTurns quotient = modulo_turning_symmetries(problem, x, reduced_jacobian(problem, x));
    A = quotient.A;
    cyclic = non_cyclic_quaternions(m) + quotient.turns;
  } else if (has_multipliers(m)) {
    A = manifold_linearization(problem, x).A;
  } else {
    first_order(m, linearize(problem, x), A, B, nullptr);
    cyclic = conserved_cyclic_momenta(m);
  }
  return counted_spectrum(A, cyclic);
}

CountedSpectrum counted_spectrum(const Eigen::MatrixXd& A, int cyclic) {
  Spectrum sp = spectrum(A);
  Verdict v = judge(sp, cyclic);
  return {v.counted, v.verdict, v.degree, sp.tolerance, v.errors};
}

double stability_degree(const Problem& problem, const std::vector<double>& x) { return counted_spectrum(problem, x).degree; }

}  // namespace eomgen::runtime
