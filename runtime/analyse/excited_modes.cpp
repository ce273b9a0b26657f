#include "analyse/excited_modes.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace eomgen::runtime {

ExcitedModes excited_modes(const ModalAnalysis& modes, const Eigen::MatrixXd& M, const std::vector<double>& q0,
                           const std::vector<std::vector<double>>& states, const Eigen::MatrixXd& C,
                           const std::vector<double>& ranges, double bound) {
  Eigen::Index n = M.rows();
  ExcitedModes out;
  for (const NaturalMode& mode : modes.modes) {
    Eigen::RowVectorXd project = mode.shape.transpose() * M;
    Eigen::VectorXd x_k(2 * n);
    double share = 0;
    for (const std::vector<double>& x : states) {
      Eigen::Map<const Eigen::VectorXd> q(x.data(), n), v(x.data() + n, n);
      Eigen::Map<const Eigen::VectorXd> at(q0.data(), n);
      x_k << mode.shape * project.dot(q - at), mode.shape * project.dot(v);
      Eigen::VectorXd y = C * x_k;
      for (Eigen::Index o = 0; o < y.size(); ++o) share = std::max(share, std::abs(y(o)) / std::max(ranges[std::size_t(o)], 1e-300));
    }
    out.share.push_back(share);
  }
  std::vector<std::size_t> order(out.share.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return out.share[a] < out.share[b]; });
  std::vector<bool> needed(order.size(), true);
  double left_out = 0;
  for (std::size_t k : order) {
    if (left_out + out.share[k] > bound) break;
    left_out += out.share[k], needed[k] = false;
  }
  for (std::size_t k = 0; k < needed.size(); ++k)
    if (needed[k]) out.kept.push_back(k);
  return out;
}

}  // namespace eomgen::runtime
