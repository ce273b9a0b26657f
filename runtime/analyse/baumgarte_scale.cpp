#include "analyse/baumgarte_scale.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "analyse/system_scales.hpp"

namespace eomgen::runtime {

double baumgarte_gain_ratio(const Problem& problem, const std::vector<double>& x, double alpha, double beta) {
  const eomgen_model_abi& m = *problem.model;
  double gain = std::max(alpha, beta);
  if (m.num_multipliers == 0 || !(gain > 0)) return 1.0;
  Eigen::Matrix<double, -1, -1, Eigen::RowMajor> J(m.num_states, m.num_states);
  m.jacobian_state_stabilized(0.0, x.data(), problem.held_inputs(), problem.parameters.data(), 0.0, 0.0, J.data());
  double rate = J.allFinite() ? spectral_scale(J) : 0.0;
  return rate > 0 && std::isfinite(rate) ? gain / rate : 1.0;
}

}  // namespace eomgen::runtime
