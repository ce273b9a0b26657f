#include "analyse/rate_balance.hpp"

#include <cmath>

#include "analyse/system_scales.hpp"

namespace eomgen::runtime {

RateBalance rate_balance(const Eigen::VectorXd& rates, const Eigen::MatrixXd& J, const Eigen::VectorXd& x,
                         const std::vector<bool>& is_coordinate, double size, const Eigen::VectorXd& noise,
                         double margin) {
  RateBalance b;
  double worst = -1, rate = J.allFinite() ? spectral_scale(J) : 0.0;
  for (long i = 0; i < rates.size(); ++i) {
    double terms = rate * std::abs(x[i]);
    for (long j = 0; j < J.cols(); ++j) terms += std::abs(J(i, j)) * (is_coordinate[std::size_t(j)] ? size : std::abs(x[j]));
    double noisy = i < noise.size() && std::isfinite(noise[i]) ? 1e6 * noise[i] : 0.0;
    double tolerance = margin * std::max(1e-9 * terms, noisy), residual = std::abs(rates[i]);
    // how far past its tolerance the row is: a rate that is not finite, or not zero where it
    // must be, is past any
    double past = !std::isfinite(residual) || !std::isfinite(tolerance) ? INFINITY
                  : tolerance > 0                                       ? residual / tolerance
                  : residual > 0                                        ? INFINITY
                                                                        : 0.0;
    if (past > worst) worst = past, b.row = i, b.residual = residual, b.tolerance = tolerance;
  }
  b.balanced = worst <= 1;
  return b;
}

}  // namespace eomgen::runtime
