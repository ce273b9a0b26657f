#include "analyse/state_space.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace eomgen::runtime {

namespace {

int name_index(const char* const* names, std::size_t count, const std::string& name) {
  for (std::size_t i = 0; i < count; ++i)
    if (name == names[i]) return static_cast<int>(i);
  return -1;
}

// dy/dv at v by central differences over steps from |v| (or 1) down by factors of ten, each step as
// the doubles take it ((v + h) − v), to the 1e-15th of |v|, or to 1e-40 at v = 0: the slope that
// agrees best, relatively, with both its neighbours, between truncation (a step too long for the
// output's own scale) and rounding (one too short). A fixed step of 1e-6 crossed a MEMS gap of 1e-6 m.
template <class Output>
double plateau_slope(const Output& y_at, double v) {
  double base = v != 0 ? std::abs(v) : 1.0;
  int last = v != 0 ? 15 : 40;
  std::vector<double> slopes;
  bool moved = false;
  for (int k = 1; k <= last; ++k) {
    double h = (v + base * std::pow(10.0, -k)) - v;
    if (h <= 0) break;
    double plus = y_at(v + h), minus = y_at(v - h);
    // steps whose change in y is lost in y's rounding (0 after it was not) are no slopes
    bool lost = std::isfinite(plus) && std::isfinite(minus) &&
                std::abs(plus - minus) <= 64 * std::numeric_limits<double>::epsilon() * std::max(std::abs(plus), std::abs(minus));
    if (lost && moved) break;
    moved = moved || !lost;
    double slope = (plus - minus) / (2 * h);
    if (std::isfinite(slope)) slopes.push_back(slope);
  }
  if (slopes.size() < 3) return slopes.empty() ? NAN : slopes.back();
  std::size_t best = 1;
  double best_spread = INFINITY;
  for (std::size_t k = 1; k + 1 < slopes.size(); ++k) {
    // relative: far outside the output's scale the slopes are tiny and agree in absolute terms
    double change = std::max(std::abs(slopes[k] - slopes[k - 1]), std::abs(slopes[k] - slopes[k + 1]));
    double spread = change == 0 ? 0 : change / std::abs(slopes[k]);
    if (spread < best_spread) best = k, best_spread = spread;
  }
  return slopes[best];
}

}  // namespace

StateSpace state_space_at(const Problem& problem, const std::vector<double>& x) {
  const eomgen_model_abi& m = *problem.model;
  std::size_t N = m.num_states, k = m.num_inputs;
  Eigen::Matrix<double, -1, -1, Eigen::RowMajor> J(N, N), B(N, std::max<std::size_t>(k, 1));
  const double* u = problem.held_inputs();
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
  std::vector<double> y(m.num_outputs + 1);
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
      auto output_at = [&](double value) {
        std::vector<double> xs = x, us = p.inputs;
        (j < N ? xs[j] : us[j - N]) = value;
        outputs_at(xs, us, y);
        return y[o];
      };
      double slope = plateau_slope(output_at, j < N ? x[j] : p.inputs[j - N]);
      (j < N ? C(row, static_cast<Eigen::Index>(j)) : D(row, static_cast<Eigen::Index>(j - N))) = slope;
    }
  }
}

}  // namespace eomgen::runtime
