#include "analyse/state_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <Eigen/Dense>
#include <fmt/format.h>

namespace eomgen::runtime {

std::string state_text(const eomgen_model_abi& m, const std::vector<double>& x) {
  std::string s;
  for (std::size_t i = 0; i < m.num_states && i < x.size(); ++i)
    s += fmt::format("{}{} = {:.6g}", i ? ", " : "", m.state_names[i], x[i]);
  return s;
}

std::string non_finite_quantities(const Problem& p, double t, const std::vector<double>& x) {
  const eomgen_model_abi& m = *p.model;
  std::size_t k = m.num_velocities;
  std::vector<double> M(k * k), f(k);
  m.mass_matrix(t, x.data(), p.parameters.data(), M.data());
  m.forcing(t, x.data(), p.held_inputs(), p.parameters.data(), f.data());
  std::string out;
  auto add = [&out](const std::string& name) { out += (out.empty() ? "" : ", ") + name; };
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = i; j < k; ++j)
      if (!std::isfinite(M[i * k + j])) add(fmt::format("M[{}][{}]", i, j));
  for (std::size_t i = 0; i < k; ++i)
    if (!std::isfinite(f[i])) add(fmt::format("f[{}] (the equation of {})", i, m.state_names[m.num_coordinates + i]));
  if (!std::isfinite(m.kinetic_energy(t, x.data(), p.parameters.data()))) add("T");
  if (!std::isfinite(m.potential_energy(t, x.data(), p.parameters.data()))) add("V");
  return out;
}

// At zero velocities, where the terms of T are those of the steps alone: at a momentum of 2e12
// (a governor on a time scale of 1e-12 s) the steps of 1 of another momentum changed T, of 1e24,
// below its rounding, and the Hessian's eigenvalues came out ±2e7. The cross terms are taken with
// each step rescaled to change T by the same amount (δ_a² H_aa, the largest the given steps make),
// so that neither is lost beside the other's square (momenta of a length and of an angle differ by
// orders of magnitude).
Eigen::MatrixXd kinetic_metric(const eomgen_model_abi& m, double t, const std::vector<double>& x,
                               const double* parameters, std::vector<double> steps) {
  std::size_t n = m.num_coordinates, k = m.num_velocities;
  std::vector<double> at_rest = x;
  std::fill(at_rest.begin() + long(n), at_rest.begin() + long(n + k), 0.0);
  auto energy = [&](std::size_t a, std::size_t b) {
    std::vector<double> y = at_rest;
    if (a < k) y[n + a] += steps[a];
    if (b < k) y[n + b] += steps[b];
    return m.kinetic_energy(t, y.data(), parameters);
  };
  auto second_difference = [&](std::size_t a, std::size_t b) {
    return (energy(a, b) - energy(a, k) - energy(b, k) + energy(k, k)) / (steps[a] * steps[b]);
  };
  Eigen::MatrixXd H(static_cast<long>(k), static_cast<long>(k));
  for (std::size_t a = 0; a < k; ++a) H(long(a), long(a)) = second_difference(a, a);
  double energy_of_step = 0;  // the largest change of T the given steps make
  for (std::size_t a = 0; a < k; ++a)
    if (std::isfinite(H(long(a), long(a)))) energy_of_step = std::max(energy_of_step, steps[a] * steps[a] * H(long(a), long(a)));
  for (std::size_t a = 0; a < k; ++a)
    if (H(long(a), long(a)) > 0 && std::isfinite(H(long(a), long(a))))
      steps[a] = std::sqrt(energy_of_step / H(long(a), long(a)));
  for (std::size_t a = 0; a < k; ++a)
    for (std::size_t b = 0; b < a; ++b) H(long(a), long(b)) = H(long(b), long(a)) = second_difference(a, b);
  return H;
}

Eigen::MatrixXd mass_matrix_at(const Problem& p, double t, const std::vector<double>& x) {
  const eomgen_model_abi& m = *p.model;
  auto k = static_cast<Eigen::Index>(m.num_velocities);
  if (std::strcmp(m.method, "hamilton") == 0 && m.kinetic_energy) {
    std::vector<double> steps(m.num_velocities);
    for (std::size_t a = 0; a < steps.size(); ++a) steps[a] = std::max(1.0, std::abs(x[m.num_coordinates + a]));
    Eigen::MatrixXd inverse_mass = kinetic_metric(m, t, x, p.parameters.data(), steps);
    if (!inverse_mass.allFinite()) return inverse_mass;
    return inverse_mass.ldlt().solve(Eigen::MatrixXd::Identity(k, k));
  }
  Eigen::Matrix<double, -1, -1, Eigen::RowMajor> rows(k, k);
  m.mass_matrix(t, x.data(), p.parameters.data(), rows.data());
  return rows;
}

Eigen::MatrixXd unit_free_mass_matrix(const Problem& p, double t, const std::vector<double>& x) {
  const eomgen_model_abi& m = *p.model;
  Eigen::MatrixXd M = mass_matrix_at(p, t, x);
  std::vector<double> at_default(m.default_state, m.default_state + m.num_states);
  Eigen::MatrixXd reference = mass_matrix_at(p, t, at_default);
  Eigen::VectorXd d(M.rows());
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    double inertia = std::max(M(i, i), std::isfinite(reference(i, i)) ? reference(i, i) : 0.0);
    d[i] = inertia > 0 ? 1 / std::sqrt(inertia) : 1.0;
  }
  return d.asDiagonal() * M * d.asDiagonal();
}

MassMatrixRank mass_matrix_rank(const Problem& p, double t, const std::vector<double>& x) {
  const eomgen_model_abi& m = *p.model;
  std::size_t k = m.num_velocities;
  Eigen::MatrixXd M = unit_free_mass_matrix(p, t, x);
  MassMatrixRank r;
  r.size = r.rank = k;
  if (k == 0 || !M.allFinite()) return r;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(M);
  const Eigen::VectorXd& values = eigen.eigenvalues();
  r.smallest = values.minCoeff(), r.largest = values.cwiseAbs().maxCoeff();
  double zero = 1e-12 * std::max(r.largest, 1e-300);
  r.rank = 0;
  Eigen::VectorXd weight = Eigen::VectorXd::Zero(static_cast<long>(k));
  for (long i = 0; i < values.size(); ++i) {
    if (values[i] > zero) ++r.rank;
    else weight += eigen.eigenvectors().col(i).cwiseAbs2();
  }
  for (std::size_t i = 0; i < k; ++i)
    if (weight[static_cast<long>(i)] > 0.04)
      r.null_velocities += (r.null_velocities.empty() ? "" : ", ") + std::string(m.state_names[m.num_coordinates + i]);
  return r;
}

std::string unfit_state(const Problem& p, double t, const std::vector<double>& x) {
  const eomgen_model_abi& m = *p.model;
  if (std::string bad = non_finite_quantities(p, t, x); !bad.empty())
    return fmt::format("{} {} not finite at t = {:g}, {} (a division by zero, or a function outside its domain)", bad,
                       bad.find(',') == std::string::npos ? "is" : "are", t, state_text(m, x));
  MassMatrixRank r = mass_matrix_rank(p, t, x);
  // a kinetic energy that is negative in some direction: a negative mass or moment of inertia
  if (r.size > 0 && r.smallest < -1e-12 * std::max(r.largest, 1e-300))
    return fmt::format("the mass matrix is not positive definite at {}: without its velocities' units, its eigenvalues run "
                       "from {:.3g} to {:.3g}, so the "
                       "kinetic energy is negative in some direction; a negative mass or moment of inertia (check the "
                       "--set values and the model's inertias)",
                       state_text(m, x), r.smallest, r.largest);
  if (r.singular())
    return fmt::format("the mass matrix is singular at {}: rank {} of {} (without its velocities' units, eigenvalues from "
                       "{:.3g} to {:.3g}); no inertia "
                       "resists {}: a coordinate that appears in no kinetic energy, or a singularity of the coordinates "
                       "at this configuration",
                       state_text(m, x), r.rank, r.size, r.smallest, r.largest, r.null_velocities);
  return {};
}

}  // namespace eomgen::runtime
