#include "analyse/constrained_first_order.hpp"

#include <algorithm>
#include <cmath>

namespace eomgen::runtime {

namespace {

using RowMajor = Eigen::Matrix<double, -1, -1, Eigen::RowMajor>;

RowMajor jacobian_with_gain(const Problem& p, const std::vector<double>& x, double alpha) {
  const eomgen_model_abi& m = *p.model;
  RowMajor J(m.num_states, m.num_states);
  m.jacobian_state_stabilized(0.0, x.data(), p.held_inputs(), p.parameters.data(), alpha, 0.0, J.data());
  return J;
}

// ∂Φ/∂x: the holonomic rows [G 0] (G their rows of C), then every constraint [∂(Cq'+b)/∂q  C]
Eigen::MatrixXd constraint_gradient(const Problem& p, const std::vector<double>& x) {
  const eomgen_model_abi& m = *p.model;
  long n = static_cast<long>(m.num_coordinates), c = static_cast<long>(m.num_constraints);
  RowMajor C(c, n);
  m.constraint_jacobian(0.0, x.data(), p.parameters.data(), C.data());
  // with C q'' + γ = −2α(Cq' + b): q''(α=1) − q''(α=0) = −2 M⁻¹Cᵀ S⁻¹ (Cq' + b), and C M⁻¹Cᵀ S⁻¹ = I
  RowMajor difference = jacobian_with_gain(p, x, 1.0) - jacobian_with_gain(p, x, 0.0);
  Eigen::MatrixXd velocity_rows = -C * difference.bottomRows(n) / 2;
  std::vector<long> holonomic;
  for (long i = 0; i < c; ++i)
    if (m.constraint_is_holonomic[i]) holonomic.push_back(i);
  Eigen::MatrixXd grad = Eigen::MatrixXd::Zero(static_cast<long>(holonomic.size()) + c, 2 * n);
  for (std::size_t k = 0; k < holonomic.size(); ++k) grad.row(static_cast<long>(k)).head(n) = C.row(holonomic[k]);
  grad.bottomRows(c) = velocity_rows;
  grad.bottomRows(c).rightCols(n) = C;  // exactly, rather than through the difference
  return grad;
}

// the last columns of `block` that raise its rank, going backwards (a greedy basis of its
// column space), numbered from `first`: the dependent components, the same ones the
// consistent initial state solves for
std::vector<int> last_independent_columns(const Eigen::MatrixXd& block, int first) {
  std::vector<int> chosen;
  Eigen::MatrixXd basis(block.rows(), 0);
  // relative to the block alone: a constraint means the same multiplied by any number
  double scale = block.cwiseAbs().maxCoeff();
  for (long j = block.cols() - 1; j >= 0 && basis.cols() < block.rows(); --j) {
    Eigen::VectorXd v = block.col(j);
    for (int pass = 0; pass < 2; ++pass)  // Gram–Schmidt twice is enough
      for (long k = 0; k < basis.cols(); ++k) v -= basis.col(k).dot(v) * basis.col(k);
    if (v.norm() <= 1e-9 * scale) continue;
    basis.conservativeResize(Eigen::NoChange, basis.cols() + 1);
    basis.col(basis.cols() - 1) = v / v.norm();
    chosen.push_back(first + static_cast<int>(j));
  }
  std::sort(chosen.begin(), chosen.end());
  return chosen;
}

// ∂Φ/∂x is block triangular, [G 0; ∂Ψ/∂q C]: the positions g determines come from G,
// the velocities from C
std::vector<int> dependent_components(const Eigen::MatrixXd& grad, long holonomic, long n) {
  std::vector<int> dependent = last_independent_columns(grad.topLeftCorner(holonomic, n), 0);
  std::vector<int> velocities = last_independent_columns(grad.bottomRightCorner(grad.rows() - holonomic, n), static_cast<int>(n));
  dependent.insert(dependent.end(), velocities.begin(), velocities.end());
  return dependent;
}

void remove_index(Eigen::MatrixXd& a, long k, bool row, bool column) {
  if (row) {
    a.middleRows(k, a.rows() - k - 1) = a.bottomRows(a.rows() - k - 1).eval();
    a.conservativeResize(a.rows() - 1, Eigen::NoChange);
  }
  if (column) {
    a.middleCols(k, a.cols() - k - 1) = a.rightCols(a.cols() - k - 1).eval();
    a.conservativeResize(Eigen::NoChange, a.cols() - 1);
  }
}

// A component on which no rate depends (its column of A zero to rounding) adds a zero eigenvalue
// and nothing else: det(λI − A) = λ·det(λI − A without it). It is a family of steady motions
// (the heading of a vehicle, its speed), left out like a cyclic coordinate, repeatedly. Zero
// against the largest entry of A with its velocities measured in the system's rate ρ (ρ² the
// largest ∂q''/∂q), so that every entry scales as 1/T with time: against A's own largest entry, a
// Cartesian pendulum at a time scale of 1e-12 s (the 1 of q' = v beside g/l = 9.81e24) had lost
// its velocities, then its positions, and the eigenvalue solver met an empty A.
void leave_out_neutral_components(ManifoldLinearization& r, std::size_t coordinates) {
  auto is_velocity = [&](long k) { return r.kept[static_cast<std::size_t>(k)] >= static_cast<int>(coordinates); };
  double rate_squared = 0;
  for (long i = 0; i < r.A.rows(); ++i)
    for (long k = 0; k < r.A.cols(); ++k)
      if (is_velocity(i) && !is_velocity(k)) rate_squared = std::max(rate_squared, std::abs(r.A(i, k)));
  double rate = rate_squared > 0 ? std::sqrt(rate_squared) : 1.0;
  // D⁻¹ A D with D = diag(1 for coordinates, ρ for velocities)
  auto timed = [&](long i, long k) { return r.A(i, k) * (is_velocity(k) ? rate : 1.0) / (is_velocity(i) ? rate : 1.0); };
  double scale = 0;
  for (long i = 0; i < r.A.rows(); ++i)
    for (long k = 0; k < r.A.cols(); ++k) scale = std::max(scale, std::abs(timed(i, k)));
  for (bool found = true; found;) {
    found = false;
    for (long k = 0; k < r.A.cols(); ++k) {
      bool zero = true;
      for (long i = 0; i < r.A.rows() && zero; ++i) zero = std::abs(timed(i, k)) <= 1e-13 * scale;
      if (!zero) continue;
      r.neutral.push_back(r.kept[static_cast<std::size_t>(k)]);
      r.kept.erase(r.kept.begin() + k);
      remove_index(r.A, k, true, true);
      remove_index(r.B, k, true, false);
      remove_index(r.basis, k, false, true);
      found = true;
      break;
    }
  }
}

}  // namespace

bool has_multipliers(const eomgen_model_abi& m) { return m.num_multipliers > 0; }

Eigen::VectorXd unstabilized_rate(const Problem& p, const std::vector<double>& x) {
  const eomgen_model_abi& m = *p.model;
  Eigen::VectorXd rate(m.num_states);
  m.rhs_stabilized(0.0, x.data(), p.held_inputs(), p.parameters.data(), 0.0, 0.0, rate.data());
  return rate;
}

Eigen::MatrixXd unstabilized_jacobian(const Problem& p, const std::vector<double>& x) { return jacobian_with_gain(p, x, 0.0); }

ManifoldLinearization manifold_linearization(const Problem& problem, const std::vector<double>& x) {
  const eomgen_model_abi& m = *problem.model;
  long states = static_cast<long>(m.num_states);
  Eigen::MatrixXd grad = constraint_gradient(problem, x);
  ManifoldLinearization r;
  long n = static_cast<long>(m.num_coordinates), holonomic = grad.rows() - static_cast<long>(m.num_constraints);
  r.dependent = dependent_components(grad, holonomic, n);
  std::vector<int> free;
  for (int j = 0; j < states; ++j)
    if (std::find(r.dependent.begin(), r.dependent.end(), j) == r.dependent.end()) free.push_back(j);
  // δx_dependent = −grad_dep⁻¹ grad_free δx_free
  Eigen::MatrixXd dep(grad.rows(), static_cast<long>(r.dependent.size())), fre(grad.rows(), static_cast<long>(free.size()));
  for (std::size_t k = 0; k < r.dependent.size(); ++k) dep.col(static_cast<long>(k)) = grad.col(r.dependent[k]);
  for (std::size_t k = 0; k < free.size(); ++k) fre.col(static_cast<long>(k)) = grad.col(free[k]);
  Eigen::MatrixXd solved = -dep.colPivHouseholderQr().solve(fre);
  // cyclic positions parametrize directions along which nothing changes: left out, as for the other methods
  for (std::size_t k = 0; k < free.size(); ++k)
    if (!(free[k] < static_cast<int>(m.num_coordinates) && m.is_cyclic[free[k]])) r.kept.push_back(static_cast<int>(k));
  r.basis = Eigen::MatrixXd::Zero(states, static_cast<long>(r.kept.size()));
  for (std::size_t c = 0; c < r.kept.size(); ++c) {
    long k = r.kept[c];
    r.basis(free[static_cast<std::size_t>(k)], static_cast<long>(c)) = 1;
    for (std::size_t d = 0; d < r.dependent.size(); ++d) r.basis(r.dependent[d], static_cast<long>(c)) = solved(static_cast<long>(d), k);
  }
  for (int& k : r.kept) k = free[static_cast<std::size_t>(k)];
  Eigen::MatrixXd J = unstabilized_jacobian(problem, x);
  r.A.resize(static_cast<long>(r.kept.size()), static_cast<long>(r.kept.size()));
  for (std::size_t i = 0; i < r.kept.size(); ++i) r.A.row(static_cast<long>(i)) = J.row(r.kept[i]) * r.basis;
  RowMajor B(states, std::max<std::size_t>(m.num_inputs, 1));
  B.setZero();
  if (m.num_inputs) m.jacobian_input(0.0, x.data(), problem.held_inputs(), problem.parameters.data(), B.data());
  r.B.resize(static_cast<long>(r.kept.size()), static_cast<long>(m.num_inputs));
  for (std::size_t i = 0; i < r.kept.size(); ++i)
    r.B.row(static_cast<long>(i)) = B.row(r.kept[i]).head(static_cast<long>(m.num_inputs));
  leave_out_neutral_components(r, m.num_coordinates);
  return r;
}

}  // namespace eomgen::runtime
