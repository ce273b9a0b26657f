#include "analyse/state_tolerances.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "analyse/first_order_form.hpp"
#include "analyse/system_scales.hpp"

namespace eomgen::runtime {

std::vector<double> state_sizes(const Problem& p, const std::vector<double>& x0) {
  const eomgen_model_abi& m = *p.model;
  std::size_t nq = m.num_coordinates, nv = m.num_velocities;
  std::vector<double> size(m.num_states, 0.0);
  for (std::size_t i = 0; i < m.num_states && i < x0.size(); ++i) {
    double given = std::isfinite(x0[i]) ? std::abs(x0[i]) : 0.0, usual = std::abs(m.default_state[i]);
    size[i] = given > 0 ? given : std::isfinite(usual) ? usual : 0.0;
  }
  if (nq == nv) {
    // the system's rate: the balanced Jacobian's scale at the start (0 where it is not finite)
    Eigen::MatrixXd J = state_jacobian(p, 0.0, x0);
    double rate = J.allFinite() ? spectral_scale(J) : 0.0;
    for (std::size_t k = 0; k < nv; ++k) size[nq + k] = std::max(size[nq + k], rate * size[k]);
  }
  for (double& s : size)
    if (!std::isfinite(s)) s = 0;
  return size;
}

std::vector<double> state_absolute_tolerances(const Problem& p, const std::vector<double>& x0, double rtol, double atol) {
  std::vector<double> size = state_sizes(p, x0), tolerance(size.size(), atol);
  for (std::size_t i = 0; i < size.size(); ++i)
    if (size[i] > 0) tolerance[i] = std::min(atol, 1e-2 * rtol * size[i]);
  return tolerance;
}

}  // namespace eomgen::runtime
