#include "analyse/output_interval.hpp"

#include <cmath>

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include "analyse/first_order_form.hpp"
#include "analyse/system_scales.hpp"

namespace eomgen::runtime {

double fastest_period(const Problem& p, double t, const std::vector<double>& x) {
  Eigen::MatrixXd J = state_jacobian(p, t, x);
  const Eigen::Index n = J.rows();
  if (n == 0 || !J.allFinite()) return INFINITY;
  Eigen::MatrixXd B = balanced(J);
  Eigen::EigenSolver<Eigen::MatrixXd> solver(B, false);
  double scale = spectral_scale(B), fastest = 0;
  for (Eigen::Index k = 0; k < n; ++k) {
    double imaginary = std::abs(solver.eigenvalues()[k].imag());
    if (imaginary > relative_cluster_tolerance * scale) fastest = std::max(fastest, imaginary);
  }
  return fastest > 0 ? 2 * M_PI / fastest : INFINITY;
}

std::optional<std::string> aliasing_warning(const Problem& p, double t, const std::vector<double>& x, double dt_out) {
  double period = fastest_period(p, t, x);
  if (!(dt_out > period / 2)) return std::nullopt;
  return fmt::format("the output interval {:g} s is longer than half the period of the fastest oscillation at the start, "
                     "{:.3g} s ({:.3g} Hz): its rows are {:.3g} periods apart and cannot show it; --dt-out {:.2g} gives "
                     "twenty rows a period",
                     dt_out, period, 1 / period, dt_out / period, period / 20);
}

}  // namespace eomgen::runtime
