#include "analyse/linear_response.hpp"

#include <cmath>

#include "analyse/linear_system.hpp"

namespace eomgen::runtime {

LinearResponse linear_response(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const ResponseRequest& r) {
  Eigen::Index n = A.rows();
  Eigen::Index extra = r.kind == Excitation::step ? 1 : r.kind == Excitation::harmonic ? 2 : 0;
  // the forced part from rest at `start`: z = [x; w] with w' = S w generating u = amplitude·w_1
  Eigen::MatrixXd augmented = Eigen::MatrixXd::Zero(n + extra, n + extra);
  Eigen::VectorXd z = Eigen::VectorXd::Zero(n + extra);
  augmented.topLeftCorner(n, n) = A;
  if (r.kind == Excitation::impulse) z.head(n) = r.amplitude * B.col(r.input);
  if (extra) augmented.block(0, n, n, 1) = r.amplitude * B.col(r.input);
  if (r.kind == Excitation::step) z(n) = 1;
  if (r.kind == Excitation::harmonic) {
    augmented(n, n + 1) = r.omega, augmented(n + 1, n) = -r.omega;  // w = (sin(ωt + φ), cos(ωt + φ))
    z(n) = std::sin(r.phase), z(n + 1) = std::cos(r.phase);
  }
  bool forced = r.kind != Excitation::initial;
  LinearResponse out;
  long steps = static_cast<long>(std::floor(r.t_end / r.dt_out * (1 + 1e-12)));
  for (long k = 0; k <= steps; ++k) out.times.push_back(static_cast<double>(k) * r.dt_out);
  if (out.times.back() < r.t_end * (1 - 1e-12)) out.times.push_back(r.t_end);
  // each time from the start, so that rounding does not accumulate over the steps
  for (double t : out.times) {
    Eigen::VectorXd x = fundamental_matrix(A, t) * r.x0;
    if (forced && t >= r.start) x += (fundamental_matrix(augmented, t - r.start) * z).head(n);
    out.states.push_back(x);
  }
  return out;
}

}  // namespace eomgen::runtime
