#include "analyse/state_space.hpp"

#include <algorithm>
#include <cmath>

namespace eomgen::runtime {

namespace {

int name_index(const char* const* names, std::size_t count, const std::string& name) {
  for (std::size_t i = 0; i < count; ++i)
    if (name == names[i]) return static_cast<int>(i);
  return -1;
}

}  // namespace

StateSpace state_space_at(const Problem& problem, const std::vector<double>& x) {
  const eomgen_model_abi& m = *problem.model;
  std::size_t N = m.num_states, k = m.num_inputs;
  Eigen::Matrix<double, -1, -1, Eigen::RowMajor> J(N, N), B(N, std::max<std::size_t>(k, 1));
  const double* u = problem.inputs.empty() ? nullptr : problem.inputs.data();
  m.jacobian_state(0.0, x.data(), u, problem.parameters.data(), J.data());
  m.jacobian_input(0.0, x.data(), u, problem.parameters.data(), B.data());
  return {J, Eigen::MatrixXd(B).leftCols(static_cast<Eigen::Index>(k))};
}

void output_matrices(const Problem& p, const std::vector<double>& x, const std::vector<std::string>& names,
                     Eigen::MatrixXd& C, Eigen::MatrixXd& D) {
  const eomgen_model_abi& m = *p.model;
  std::size_t N = m.num_states, k = m.num_inputs;
  C = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(names.size()), static_cast<Eigen::Index>(N));
  D = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(names.size()), static_cast<Eigen::Index>(k));
  std::vector<double> y_plus(m.num_outputs + 1), y_minus(m.num_outputs + 1);
  auto outputs_at = [&](const std::vector<double>& xs, const std::vector<double>& us, std::vector<double>& y) {
    m.outputs(0.0, xs.data(), us.empty() ? nullptr : us.data(), p.parameters.data(), y.data());
  };
  for (std::size_t i = 0; i < names.size(); ++i) {
    Eigen::Index row = static_cast<Eigen::Index>(i);
    if (int s = name_index(m.state_names, N, names[i]); s >= 0) {
      C(row, s) = 1;
      continue;
    }
    int o = name_index(m.output_names, m.num_outputs, names[i]);
    for (std::size_t j = 0; j < N + k; ++j) {
      std::vector<double> xp = x, xm = x, up = p.inputs, um = p.inputs;
      double& plus = j < N ? xp[j] : up[j - N];
      double& minus = j < N ? xm[j] : um[j - N];
      double h = 1e-6 * std::max(1.0, std::abs(plus));
      plus += h, minus -= h;
      outputs_at(xp, up, y_plus), outputs_at(xm, um, y_minus);
      double slope = (y_plus[o] - y_minus[o]) / (2 * h);
      (j < N ? C(row, static_cast<Eigen::Index>(j)) : D(row, static_cast<Eigen::Index>(j - N))) = slope;
    }
  }
}

}  // namespace eomgen::runtime
