#include "analyse/baumgarte_scale.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "analyse/constrained_first_order.hpp"
#include "analyse/system_scales.hpp"

namespace eomgen::runtime {

double baumgarte_gain_ratio(const Problem& problem, const std::vector<double>& x, double alpha, double beta) {
  const eomgen_model_abi& m = *problem.model;
  double gain = std::max(alpha, beta);
  if (m.num_multipliers == 0 || !(gain > 0)) return 1.0;
  Eigen::MatrixXd J = unstabilized_jacobian(problem, x);
  double rate = J.allFinite() ? spectral_scale(J) : 0.0;
  return rate > 0 && std::isfinite(rate) ? gain / rate : 1.0;
}

}  // namespace eomgen::runtime
