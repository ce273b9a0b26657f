#include "integrate/projection.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <Eigen/Dense>

#include "integrate/coordinate_sizes.hpp"
#include "integrate/quaternion_norms.hpp"

namespace eomgen::runtime {

namespace {

using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

Matrix constraint_jacobian(const Problem& p, double t, const double* x) {
  const eomgen_model_abi& m = *p.model;
  Matrix C(m.num_constraints, m.num_coordinates);
  m.constraint_jacobian(t, x, p.parameters.data(), C.data());
  return C;
}

// columns of C, from the end, that have full rank together, each weighed in its coordinate's `size`
// (a slider-crank of 1e-13 m has its angles' columns of 1e-13 beside its slider's 1): the dependent
// coordinates; the columns the user gave values for (`given`, may be empty) are taken only when the
// others do not do
std::vector<long> dependent_columns(const Matrix& C, const std::vector<double>& size,
                                    const std::vector<bool>& given = {}) {
  std::vector<long> order;
  for (int pass = 0; pass < 2; ++pass)
    for (long j = C.cols() - 1; j >= 0; --j)
      if ((static_cast<std::size_t>(j) < given.size() && given[static_cast<std::size_t>(j)]) == (pass == 1)) order.push_back(j);
  std::vector<long> chosen;
  for (long j : order) {
    if (static_cast<long>(chosen.size()) >= C.rows()) break;
    Eigen::MatrixXd block(C.rows(), static_cast<long>(chosen.size()) + 1);
    for (std::size_t k = 0; k < chosen.size(); ++k)
      block.col(static_cast<long>(k)) = C.col(chosen[k]) * size[std::size_t(chosen[k])];
    block.col(static_cast<long>(chosen.size())) = C.col(j) * size[std::size_t(j)];
    Eigen::FullPivLU<Eigen::MatrixXd> lu(block);
    lu.setThreshold(1e-10);
    if (lu.rank() == block.cols()) chosen.push_back(j);
  }
  return chosen;
}

// g counts as met below 1e-14 of its own scale, Σ_j |C_rj| s_j with s_j each coordinate's size
// (integrate/coordinate_sizes.hpp): a loop in micrometres is closed to 1e-14 of its size, not to
// 1e-14 m (an absolute 1e-14 left a pendulum of 1 µm off its rod by 0.15 %), and a crank's angle
// counts in radians beside a slider's metres
bool constraints_met(const Eigen::VectorXd& g, const Matrix& Ch, const std::vector<double>& size) {
  Eigen::Map<const Eigen::VectorXd> s(size.data(), static_cast<long>(size.size()));
  for (long r = 0; r < g.size(); ++r)
    if (!(std::abs(g[r]) <= 1e-14 * Ch.row(r).cwiseAbs().dot(s.transpose()))) return false;
  return true;
}

}  // namespace

bool ConstraintProjection::make_consistent(double t, double* x, const std::vector<bool>& given) {
  const eomgen_model_abi& m = *p_.model;
  std::vector<bool> given_positions, given_velocities;
  if (given.size() == m.num_states) {
    given_positions.assign(given.begin(), given.begin() + static_cast<long>(m.num_coordinates));
    given_velocities.assign(given.begin() + static_cast<long>(m.num_coordinates), given.end());
  }
  std::size_t mc = m.num_constraints, n = m.num_coordinates;
  std::vector<double> position(mc), velocity(mc);
  std::vector<long> holonomic;
  for (std::size_t i = 0; i < mc; ++i)
    if (m.constraint_is_holonomic[i]) holonomic.push_back(static_cast<long>(i));
  // Newton on g(q) = 0 in the dependent coordinates only
  for (int iteration = 0; !holonomic.empty(); ++iteration) {
    m.constraint_residuals(t, x, p_.parameters.data(), position.data(), velocity.data());
    Eigen::VectorXd g(holonomic.size());
    for (std::size_t r = 0; r < holonomic.size(); ++r) g[static_cast<long>(r)] = position[static_cast<std::size_t>(holonomic[r])];
    if (!g.allFinite() || iteration == 50) return false;
    Matrix C = constraint_jacobian(p_, t, x), Ch(holonomic.size(), n);
    for (std::size_t r = 0; r < holonomic.size(); ++r) Ch.row(static_cast<long>(r)) = C.row(holonomic[r]);
    std::vector<double> size = coordinate_sizes(m, x, false, 1.0);
    if (constraints_met(g, Ch, size)) break;
    std::vector<long> dependent = dependent_columns(Ch, size, given_positions);
    if (dependent.size() != holonomic.size()) return project_positions(t, x);  // dependent constraints here
    Eigen::MatrixXd block(Ch.rows(), Ch.rows());
    for (std::size_t k = 0; k < dependent.size(); ++k) block.col(static_cast<long>(k)) = Ch.col(dependent[k]);
    Eigen::VectorXd step = block.partialPivLu().solve(g);
    for (std::size_t k = 0; k < dependent.size(); ++k) x[dependent[k]] -= step[static_cast<long>(k)];
  }
  if (m.num_multipliers == 0) return true;
  // the dependent velocities from C v + b = 0 with the others as given
  m.constraint_residuals(t, x, p_.parameters.data(), position.data(), velocity.data());
  Matrix C = constraint_jacobian(p_, t, x);
  std::vector<long> dependent = dependent_columns(C, coordinate_sizes(m, x, false, 1.0), given_velocities);
  if (dependent.size() != mc) return project_velocities(t, x);
  Eigen::MatrixXd block(mc, mc);
  for (std::size_t k = 0; k < mc; ++k) block.col(static_cast<long>(k)) = C.col(dependent[k]);
  Eigen::VectorXd step = block.partialPivLu().solve(Eigen::Map<Eigen::VectorXd>(velocity.data(), static_cast<long>(mc)));
  for (std::size_t k = 0; k < mc; ++k) x[n + static_cast<std::size_t>(dependent[k])] -= step[static_cast<long>(k)];
  return true;
}

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

// Gauss–Newton with the smallest correction in each coordinate's size D (a radian beside the
// configuration's length): Δq = −D (Cₕ D)ᵀ (Cₕ D² Cₕᵀ)⁻¹ g
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
    Matrix C = constraint_jacobian(p_, t, x), Ch(rows.size(), n);
    for (std::size_t r = 0; r < rows.size(); ++r) Ch.row(r) = C.row(rows[r]);
    std::vector<double> size = coordinate_sizes(m, x, false, 1.0);
    if (constraints_met(g, Ch, size)) return true;
    Eigen::Map<const Eigen::VectorXd> D(size.data(), static_cast<long>(n));
    Matrix scaled = Ch * D.asDiagonal();
    Eigen::LDLT<Eigen::MatrixXd> normal(scaled * scaled.transpose());
    if (normal.info() != Eigen::Success || normal.vectorD().cwiseAbs().minCoeff() < 1e-14 * normal.vectorD().cwiseAbs().maxCoeff())
      return false;
    Eigen::VectorXd step = D.asDiagonal() * (scaled.transpose() * normal.solve(g));
    for (std::size_t j = 0; j < n; ++j) x[j] -= step[j];
    // a step within rounding of each coordinate's size (one unit only where all are zero): with a
    // floor of one unit, a rod of 1e-12 m stopped after its first step, 7e-10 of its length off
    if (step.cwiseQuotient(D).lpNorm<Eigen::Infinity>() < 1e-15) return true;
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
  if (m.num_constraints == 0 && m.num_quaternions == 0) return true;
  ++projections_;
  // g is the same at q and at q/|q| (the rotation is that of q/|q|), so the order does not matter
  largest_quaternion_correction_ = std::max(largest_quaternion_correction_, normalize_quaternions(m, x));
  if (m.num_constraints == 0) return true;
  if (!project_positions(t, x)) return false;
  // Appell's pseudo-velocities meet the velocity constraints by construction
  if (m.num_multipliers == 0) return true;
  return project_velocities(t, x);
}

}  // namespace eomgen::runtime
