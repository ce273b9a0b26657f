#include "analyse/output_interval.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

#include <fmt/format.h>

#include "analyse/first_order_form.hpp"
#include "analyse/system_scales.hpp"

namespace eomgen::runtime {

double fastest_period(const Eigen::MatrixXd& A) {
  const Eigen::Index n = A.rows();
  if (n == 0 || !A.allFinite()) return INFINITY;
  double scale = spectral_scale(A), fastest = 0;
  for (std::complex<double> lambda : balanced_eigenvalues(A))
    if (std::abs(lambda.imag()) > relative_cluster_tolerance * scale) fastest = std::max(fastest, std::abs(lambda.imag()));
  return fastest > 0 ? 2 * M_PI / fastest : INFINITY;
}

double fastest_period(const Problem& p, double t, const std::vector<double>& x) {
  return fastest_period(state_jacobian(p, t, x));
}

std::optional<std::string> aliasing_warning(double period, double dt_out, const std::string& what) {
  if (!(dt_out > period / 2)) return std::nullopt;
  return fmt::format("the output interval {:g} s is longer than half the period of {}, {:.3g} s ({:.3g} Hz): its rows are "
                     "{:.3g} periods apart and cannot show it; --dt-out {:.2g} gives twenty rows a period",
                     dt_out, what, period, 1 / period, dt_out / period, period / 20);
}

std::optional<std::string> aliasing_warning(const Problem& p, double t, const std::vector<double>& x, double dt_out) {
  return aliasing_warning(fastest_period(p, t, x), dt_out, "the fastest oscillation at the start");
}

double slowest_time(const Eigen::MatrixXd& A) {
  if (A.rows() == 0 || !A.allFinite()) return 0;
  std::vector<std::complex<double>> values = balanced_eigenvalues(A);
  double zero = relative_cluster_tolerance * eigenvalue_scale(balanced(A), values), smallest = INFINITY;
  for (std::complex<double> lambda : values)
    if (std::abs(lambda) > zero) smallest = std::min(smallest, std::abs(lambda));
  return std::isfinite(smallest) ? 1 / smallest : 0;
}

std::optional<std::string> span_warning(double slowest, double t_end, double dt_out) {
  if (!(t_end < slowest)) return std::nullopt;
  double end = 10 * slowest;
  std::string interval = end / dt_out > 1e5 ? fmt::format(" (with --dt-out {:.2g}, a thousand rows)", end / 1000) : "";
  return fmt::format("the response ends at t = {:g} s, {:.2g} of the slowest mode's time constant 1/|λ| = {:.3g} s, "
                     "which it cannot show; --t-end {:.2g} shows ten of them{}", t_end, t_end / slowest, slowest, end, interval);
}

}  // namespace eomgen::runtime
