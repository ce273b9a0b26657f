#include "integrate/projection.hpp"

#include <cmath>
#include <cstring>

#include <Eigen/Dense>

namespace eomgen::runtime {

namespace {

using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

Matrix constraint_jacobian(const Problem& p, double t, const double* x) {
  const eomgen_model_abi& m = *p.model;
  Matrix C(m.num_constraints, m.num_coordinates);
  m.constraint_jacobian(t, x, p.parameters.data(), C.data());
  return C;
}

}  // namespace

std::pair<double, double> ConstraintProjection::residuals(double t, const double* x) const {
  const eomgen_model_abi& m = *p_.model;
  std::vector<double> position(m.num_constraints), velocity(m.num_constraints);
  if (m.num_constraints) m.constraint_residuals(t, x, p_.parameters.data(), position.data(), velocity.data());
  double g = 0, v = 0;
  for (std::size_t i = 0; i < m.num_constraints; ++i) {
    g = std::max(g, std::abs(position[i]));
    v = std::max(v, std::abs(velocity[i]));
  }
  return {g, v};
}

// Gauss–Newton with the smallest correction: Δq = −Cₕᵀ (Cₕ Cₕᵀ)⁻¹ g
bool ConstraintProjection::project_positions(double t, double* x) {
  const eomgen_model_abi& m = *p_.model;
  std::size_t mc = m.num_constraints, n = m.num_coordinates;
  std::vector<std::size_t> rows;
  for (std::size_t i = 0; i < mc; ++i)
    if (m.constraint_is_holonomic[i]) rows.push_back(i);
  if (rows.empty()) return true;
  std::vector<double> position(mc), velocity(mc);
  for (int iteration = 0; iteration < 20; ++iteration) {
    m.constraint_residuals(t, x, p_.parameters.data(), position.data(), velocity.data());
    Eigen::VectorXd g(rows.size());
    for (std::size_t r = 0; r < rows.size(); ++r) g[r] = position[rows[r]];
    if (!g.allFinite()) return false;
    if (g.lpNorm<Eigen::Infinity>() < 1e-14) return true;
    Matrix C = constraint_jacobian(p_, t, x), Ch(rows.size(), n);
    for (std::size_t r = 0; r < rows.size(); ++r) Ch.row(r) = C.row(rows[r]);
    Eigen::LDLT<Eigen::MatrixXd> normal(Ch * Ch.transpose());
    if (normal.info() != Eigen::Success || normal.vectorD().cwiseAbs().minCoeff() < 1e-14 * normal.vectorD().cwiseAbs().maxCoeff())
      return false;
    Eigen::VectorXd step = Ch.transpose() * normal.solve(g);
    for (std::size_t j = 0; j < n; ++j) x[j] -= step[j];
    if (step.lpNorm<Eigen::Infinity>() < 1e-15 * (1 + Eigen::Map<Eigen::VectorXd>(x, n).lpNorm<Eigen::Infinity>()))
      return true;
  }
  return false;
}

// the kinetic-energy metric: Δv = −M⁻¹Cᵀ (C M⁻¹ Cᵀ)⁻¹ (C v + b), an impulsive constraint force
bool ConstraintProjection::project_velocities(double t, double* x) {
  const eomgen_model_abi& m = *p_.model;
  std::size_t mc = m.num_constraints, n = m.num_coordinates;
  std::vector<double> position(mc), velocity(mc);
  m.constraint_residuals(t, x, p_.parameters.data(), position.data(), velocity.data());
  Eigen::Map<Eigen::VectorXd> r(velocity.data(), static_cast<long>(mc));
  Matrix M(n, n);
  m.mass_matrix(t, x, p_.parameters.data(), M.data());
  Matrix C = constraint_jacobian(p_, t, x);
  Eigen::LDLT<Eigen::MatrixXd> mass(M);
  Eigen::MatrixXd Y = mass.solve(C.transpose());
  Eigen::LDLT<Eigen::MatrixXd> schur(C * Y);
  if (mass.info() != Eigen::Success || schur.info() != Eigen::Success) return false;
  Eigen::VectorXd step = Y * schur.solve(r);
  if (!step.allFinite()) return false;
  for (std::size_t j = 0; j < n; ++j) x[n + j] -= step[j];
  return true;
}

bool ConstraintProjection::project(double t, double* x) {
  const eomgen_model_abi& m = *p_.model;
  if (m.num_constraints == 0) return true;
  ++projections_;
  if (!project_positions(t, x)) return false;
  // Appell's pseudo-velocities meet the velocity constraints by construction
  if (m.num_multipliers == 0) return true;
  return project_velocities(t, x);
}

}  // namespace eomgen::runtime
