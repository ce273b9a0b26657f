#include "analyse/floquet.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analyse/first_order_form.hpp"
#include "analyse/system_scales.hpp"

namespace eomgen::runtime {

namespace {

using RowMajor = Eigen::Matrix<double, -1, -1, Eigen::RowMajor>;

// A(t) = ∂F/∂x on the reduced state
class VariationalEquations {
 public:
  VariationalEquations(const Problem& p, const std::vector<double>& x) : p_(p), x_(x), kept_(reduced_state(*p.model)) {}
  Eigen::MatrixXd at(double t) const {
    const eomgen_model_abi& m = *p_.model;
    RowMajor J(m.num_states, m.num_states);
    m.jacobian_state(t, x_.data(), p_.held_inputs(), p_.parameters.data(), J.data());
    Eigen::MatrixXd A(kept_.size(), kept_.size());
    for (std::size_t i = 0; i < kept_.size(); ++i)
      for (std::size_t j = 0; j < kept_.size(); ++j) A(static_cast<long>(i), static_cast<long>(j)) = J(kept_[i], kept_[j]);
    return A;
  }
  std::size_t size() const { return kept_.size(); }

 private:
  const Problem& p_;
  const std::vector<double>& x_;
  std::vector<int> kept_;
};

// Φ(T) by the classical Runge–Kutta method with N steps
Eigen::MatrixXd monodromy(const VariationalEquations& a, double period, long steps) {
  long n = static_cast<long>(a.size());
  Eigen::MatrixXd phi = Eigen::MatrixXd::Identity(n, n);
  double h = period / static_cast<double>(steps);
  for (long k = 0; k < steps; ++k) {
    double t = period * static_cast<double>(k) / static_cast<double>(steps);
    Eigen::MatrixXd A0 = a.at(t), Ah = a.at(t + h / 2), A1 = a.at(t + h);
    Eigen::MatrixXd k1 = A0 * phi, k2 = Ah * (phi + h / 2 * k1), k3 = Ah * (phi + h / 2 * k2), k4 = A1 * (phi + h * k3);
    phi += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return phi;
}

// the number of μ within `tolerance` of z, and the dimension of the null space of Φ − z I
std::pair<int, int> multiplicities(const Eigen::MatrixXd& phi, const std::vector<std::complex<double>>& mu,
                                   std::complex<double> z, double tolerance) {
  int algebraic = 0;
  for (auto m : mu) algebraic += std::abs(m - z) <= tolerance;
  Eigen::MatrixXcd shifted = phi.cast<std::complex<double>>();
  shifted.diagonal().array() -= z;
  Eigen::FullPivLU<Eigen::MatrixXcd> lu(shifted);
  lu.setThreshold(std::sqrt(tolerance));
  return {algebraic, static_cast<int>(phi.rows() - lu.rank())};
}

void judge(FloquetReport& r, int cyclic) {
  double delta = 1e-7 + 100 * r.error_estimate;  // what |μ| = 1 means at this accuracy
  std::vector<std::complex<double>> counted, on_circle;
  int left_out = 0;
  for (auto m : r.multipliers) {
    if (left_out < cyclic && std::abs(m - 1.0) <= std::sqrt(delta)) {
      ++left_out;
      continue;
    }
    counted.push_back(m);
  }
  r.cyclic_unit_multipliers = left_out;
  double largest = 0;
  for (auto m : counted) largest = std::max(largest, std::abs(m));
  if (largest > 1 + delta) {
    r.verdict = "unstable";
    r.reason = fmt::format("a Floquet multiplier of modulus {:.9g} > 1: a perturbation grows by that factor every period",
                           largest);
    return;
  }
  for (auto m : counted)
    if (std::abs(std::abs(m) - 1) <= delta) on_circle.push_back(m);
  if (on_circle.empty()) {
    r.verdict = "asymptotically_stable";
    r.reason = fmt::format("every Floquet multiplier lies inside the unit circle (largest modulus {:.9g})", largest);
    return;
  }
  // on the circle: a double multiplier at +1 or −1 is a boundary of the stability region (a
  // transition curve of Mathieu's chart), where rounding decides the side: say so
  for (auto m : on_circle) {
    auto [algebraic, geometric] = multiplicities(r.monodromy, counted, m, std::sqrt(delta));
    if (algebraic > 1 && std::abs(std::abs(m.real()) - 1) <= std::sqrt(delta)) {
      r.verdict = "undecided";
      r.reason = fmt::format("a double Floquet multiplier at {:+.0f}: the parameters lie on a boundary of the stability "
                             "region (within the accuracy {:.1e} of the monodromy matrix), where the first approximation "
                             "cannot decide", m.real(), r.error_estimate);
      return;
    }
    if (geometric < algebraic) {
      r.verdict = "unstable";
      r.reason = "a repeated Floquet multiplier on the unit circle without a full set of eigenvectors: perturbations grow linearly";
      return;
    }
  }
  r.verdict = "marginally_stable";
  r.reason = fmt::format("{} Floquet multiplier(s) on the unit circle, semisimple, the rest inside: bounded oscillations "
                         "of the linearization (the nonlinear terms may still decide otherwise)", on_circle.size());
}

}  // namespace

double periodic_equilibrium_residual(const Problem& p, const std::vector<double>& x, double period) {
  const eomgen_model_abi& m = *p.model;
  std::vector<double> xdot(m.num_states);
  std::vector<int> kept = reduced_state(m);
  double worst = 0;
  for (int k = 0; k < 64; ++k) {
    m.rhs(period * k / 64.0, x.data(), p.held_inputs(), p.parameters.data(), xdot.data());
    for (int i : kept) worst = std::max(worst, std::isfinite(xdot[static_cast<std::size_t>(i)]) ? std::abs(xdot[static_cast<std::size_t>(i)]) : INFINITY);
  }
  return worst;
}

double periodicity_defect(const Problem& p, const std::vector<double>& x, double period) {
  VariationalEquations a(p, x);
  // compared balanced (one diagonal scaling for all times): A's entries have the units of its
  // states, and against q' = v's ones a slow system's stiffness changing by all of itself, 1e-12,
  // was periodic to 1e-12 "relative to |A|"
  Eigen::VectorXd scales = balancing_scales(a.at(0.0123 * period));
  auto balanced_at = [&](double t) { return Eigen::MatrixXd(scales.cwiseInverse().asDiagonal() * a.at(t) * scales.asDiagonal()); };
  double difference = 0, size = 0;
  for (int k = 0; k < 16; ++k) {
    double t = period * k / 16.0 + 0.0123 * period;
    Eigen::MatrixXd now = balanced_at(t);
    difference = std::max(difference, (balanced_at(t + period) - now).lpNorm<Eigen::Infinity>());
    size = std::max(size, now.lpNorm<Eigen::Infinity>());
  }
  return size > 0 ? difference / size : 0.0;
}

FloquetReport floquet_analysis(const Problem& p, const std::vector<double>& x, double period) {
  const eomgen_model_abi& m = *p.model;
  VariationalEquations a(p, x);
  FloquetReport r;
  r.period = period;
  for (int i : reduced_state(m)) r.state_names.push_back(m.state_names[i]);
  // a step resolving the fastest rate of A(t) (sampled over the period), then halved until
  // two monodromy matrices agree; Richardson's estimate for a fourth-order method. Both in the
  // system's own scales: the rate is the balanced A's (|A| itself mixes the states' units: Mathieu's
  // equation at 1e6 rad/s took 5.7e8 steps a period where 256 resolve it), and Φ is compared in the
  // coordinates that balance A, where its entries are on the multipliers' scale.
  double fastest = 0;
  for (int k = 0; k < 64; ++k) fastest = std::max(fastest, spectral_scale(a.at(period * k / 64.0)));
  long steps = std::max(256L, static_cast<long>(std::ceil(period * fastest * 20)));
  Eigen::VectorXd scales = balancing_scales(a.at(0.0123 * period));
  auto in_balancing_coordinates = [&](const Eigen::MatrixXd& phi) {
    return Eigen::MatrixXd(scales.cwiseInverse().asDiagonal() * phi * scales.asDiagonal());
  };
  Eigen::MatrixXd coarse = monodromy(a, period, steps), fine;
  for (;;) {
    fine = monodromy(a, period, 2 * steps);
    steps *= 2;
    double size = std::max(1.0, in_balancing_coordinates(fine).lpNorm<Eigen::Infinity>());
    r.error_estimate = in_balancing_coordinates(fine - coarse).lpNorm<Eigen::Infinity>() / 15 / size;
    if (r.error_estimate <= 1e-11 || steps >= (1L << 18) || !fine.allFinite()) break;
    coarse = fine;
  }
  r.monodromy = fine + (fine - coarse) / 15;
  r.steps_per_period = steps;
  r.multipliers = balanced_eigenvalues(r.monodromy);
  std::sort(r.multipliers.begin(), r.multipliers.end(), [](auto u, auto v) {
    return std::abs(u) != std::abs(v) ? std::abs(u) > std::abs(v) : u.imag() > v.imag();
  });
  judge(r, conserved_cyclic_momenta(m));
  return r;
}

}  // namespace eomgen::runtime
