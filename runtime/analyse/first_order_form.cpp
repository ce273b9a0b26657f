#include "analyse/first_order_form.hpp"

#include <cmath>
#include <cstring>
#include <string>

namespace eomgen::runtime {

namespace {
using RowMajor = Eigen::Matrix<double, -1, -1, Eigen::RowMajor>;
}  // namespace

bool has_pseudo_velocities(const eomgen_model_abi& m) {
  return std::strcmp(m.method, "appell") == 0 || std::strcmp(m.method, "hamilton") == 0;
}

std::vector<int> reduced_state(const eomgen_model_abi& m) {
  std::vector<int> kept;
  for (std::size_t i = 0; i < m.num_coordinates; ++i)
    if (!m.is_cyclic[i]) kept.push_back(static_cast<int>(i));
  for (std::size_t i = m.num_coordinates; i < m.num_states; ++i) kept.push_back(static_cast<int>(i));
  return kept;
}

int conserved_cyclic_momenta(const eomgen_model_abi& m) {
  int conserved = 0;
  for (std::size_t i = 0; i < m.num_coordinates; ++i) {
    if (!m.is_cyclic[i]) continue;
    std::string momentum = std::string("p_") + m.coordinate_names[i];
    for (std::size_t k = 0; k < m.num_first_integrals; ++k)
      if (momentum == m.first_integral_names[k]) ++conserved;
  }
  return conserved;
}

Eigen::VectorXd reduced_rate(const Problem& p, const std::vector<double>& x) {
  const eomgen_model_abi& m = *p.model;
  std::vector<double> xdot(m.num_states);
  m.rhs(0.0, x.data(), p.held_inputs(), p.parameters.data(), xdot.data());
  std::vector<int> kept = reduced_state(m);
  Eigen::VectorXd r(kept.size());
  for (std::size_t k = 0; k < kept.size(); ++k) r[static_cast<long>(k)] = xdot[static_cast<std::size_t>(kept[k])];
  return r;
}

Eigen::MatrixXd state_jacobian(const Problem& p, double t, const std::vector<double>& x) {
  const eomgen_model_abi& m = *p.model;
  RowMajor J(m.num_states, m.num_states);
  std::vector<double> scratch;
  m.jacobian_state(t, x.data(), p.inputs_at(t, scratch), p.parameters.data(), J.data());
  return J;
}

Eigen::MatrixXd reduced_jacobian(const Problem& p, const std::vector<double>& x) {
  const eomgen_model_abi& m = *p.model;
  Eigen::MatrixXd J = state_jacobian(p, 0.0, x);
  std::vector<int> kept = reduced_state(m);
  Eigen::MatrixXd A(kept.size(), kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i)
    for (std::size_t j = 0; j < kept.size(); ++j) A(static_cast<long>(i), static_cast<long>(j)) = J(kept[i], kept[j]);
  return A;
}

Eigen::MatrixXd reduced_input_jacobian(const Problem& p, const std::vector<double>& x) {
  const eomgen_model_abi& m = *p.model;
  RowMajor B(m.num_states, std::max<std::size_t>(m.num_inputs, 1));
  B.setZero();
  if (m.num_inputs) m.jacobian_input(0.0, x.data(), p.held_inputs(), p.parameters.data(), B.data());
  std::vector<int> kept = reduced_state(m);
  Eigen::MatrixXd out(kept.size(), m.num_inputs);
  for (std::size_t i = 0; i < kept.size(); ++i)
    for (std::size_t j = 0; j < m.num_inputs; ++j) out(static_cast<long>(i), static_cast<long>(j)) = B(kept[i], static_cast<long>(j));
  return out;
}

}  // namespace eomgen::runtime
