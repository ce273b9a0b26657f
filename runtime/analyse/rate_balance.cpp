#include "analyse/rate_balance.hpp"

#include <cmath>

#include "analyse/system_scales.hpp"

namespace eomgen::runtime {

double how_far_past(double residual, double tolerance) {
  return !std::isfinite(residual) || !std::isfinite(tolerance) ? INFINITY
         : tolerance > 0                                       ? residual / tolerance
         : residual > 0                                        ? INFINITY
                                                               : 0.0;
}

RateBalance worst_row(const Eigen::VectorXd& rates, const Eigen::VectorXd& tolerances) {
  RateBalance b;
  double worst = -1;
  for (long i = 0; i < rates.size(); ++i) {
    double residual = std::abs(rates[i]), tolerance = tolerances[i], past = how_far_past(residual, tolerance);
    if (past > worst) worst = past, b.row = i, b.residual = residual, b.tolerance = tolerance;
  }
  b.balanced = worst <= 1;
  return b;
}

RateBalance rate_balance(const Eigen::VectorXd& rates, const Eigen::MatrixXd& J, const Eigen::VectorXd& x,
                         const Eigen::VectorXd& sizes, const Eigen::VectorXd& noise, double margin) {
  double rate = J.allFinite() ? spectral_scale(J) : 0.0;
  Eigen::VectorXd tolerances(rates.size());
  for (long i = 0; i < rates.size(); ++i) {
    double terms = rate * std::abs(x[i]);
    for (long j = 0; j < J.cols(); ++j) terms += std::abs(J(i, j)) * sizes[j];
    double noisy = i < noise.size() && std::isfinite(noise[i]) ? 1e6 * noise[i] : 0.0;
    tolerances[i] = margin * std::max(1e-9 * terms, noisy);
  }
  return worst_row(rates, tolerances);
}

}  // namespace eomgen::runtime
