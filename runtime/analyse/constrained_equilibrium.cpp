#include "analyse/constrained_equilibrium.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "analyse/constrained_first_order.hpp"
#include "analyse/rate_balance.hpp"
#include "integrate/coordinate_sizes.hpp"
#include "integrate/projection.hpp"

namespace eomgen::runtime {

namespace {

using RowMajor = Eigen::Matrix<double, -1, -1, Eigen::RowMajor>;

// each coordinate's size in the configuration as given, one unit where all are zero (not the
// model's default state, which a changed parameter leaves behind: a rod of 1e-12 m)
std::vector<double> given_sizes(const eomgen_model_abi& m, const std::vector<double>& x) {
  return coordinate_sizes(m, x.data(), false, 1.0);
}

// ∂g/∂q: the holonomic rows of the constraint Jacobian, and g
struct Holonomic {
  RowMajor G;
  Eigen::VectorXd g;
  std::vector<std::size_t> rows;
};

Holonomic holonomic_constraints(const Problem& p, const std::vector<double>& x) {
  const eomgen_model_abi& m = *p.model;
  std::size_t c = m.num_constraints, n = m.num_coordinates;
  RowMajor C(c, n);
  std::vector<double> position(c), velocity(c);
  m.constraint_jacobian(0.0, x.data(), p.parameters.data(), C.data());
  m.constraint_residuals(0.0, x.data(), p.parameters.data(), position.data(), velocity.data());
  Holonomic h;
  for (std::size_t i = 0; i < c; ++i)
    if (m.constraint_is_holonomic[i]) h.rows.push_back(i);
  h.G.resize(long(h.rows.size()), long(n));
  h.g.resize(long(h.rows.size()));
  for (std::size_t k = 0; k < h.rows.size(); ++k) {
    h.G.row(long(k)) = C.row(long(h.rows[k]));
    h.g[long(k)] = position[h.rows[k]];
  }
  return h;
}

// the holonomic constraints x leaves, beyond 1e-9 of Σ_j |∂g_r/∂q_j| s_j (s_j: q_j's size)
std::string unmet_constraints(const Problem& p, const std::vector<double>& x) {
  const eomgen_model_abi& m = *p.model;
  Holonomic h = holonomic_constraints(p, x);
  std::vector<double> size = given_sizes(m, x);
  Eigen::Map<const Eigen::VectorXd> sizes(size.data(), long(size.size()));
  std::string unmet;
  for (std::size_t k = 0; k < h.rows.size(); ++k) {
    double tolerance = 1e-9 * h.G.row(long(k)).cwiseAbs().dot(sizes), g = h.g[long(k)];
    if (!(std::abs(g) <= tolerance))
      unmet += fmt::format("{}{} = {:.3g} (tolerance {:.3g})", unmet.empty() ? "" : ", ", m.constraint_names[h.rows[k]], g,
                           tolerance);
  }
  return unmet;
}

// an orthonormal basis of the directions that keep g(q) = 0 to first order
Eigen::MatrixXd tangent_basis(const RowMajor& G, long n) {
  if (G.rows() == 0) return Eigen::MatrixXd::Identity(n, n);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(G, Eigen::ComputeFullV);
  const Eigen::VectorXd& s = svd.singularValues();
  long rank = 0;
  while (rank < s.size() && s[rank] > 1e-10 * s[0]) ++rank;
  return svd.matrixV().rightCols(n - rank);
}

RateBalance balance_at(const Problem& p, const std::vector<double>& x, double margin) {
  return reduced_rate_balance(p, x, unstabilized_rate, unstabilized_jacobian(p, x), given_sizes(*p.model, x), margin);
}

}  // namespace

Equilibrium check_constrained_equilibrium(const Problem& problem, std::vector<double> state) {
  Equilibrium e;
  e.moving = moving_coordinates(*problem.model, state);
  e.unmet = unmet_constraints(problem, state);
  RateBalance b = balance_at(problem, state, 1.0);
  e.residual = b.residual, e.tolerance = b.tolerance;
  e.converged = b.balanced && e.moving.empty() && e.unmet.empty();
  e.state = std::move(state);
  return e;
}

Equilibrium find_constrained_equilibrium(const Problem& problem, const std::vector<double>& start,
                                         const std::vector<bool>& held) {
  const eomgen_model_abi& m = *problem.model;
  std::size_t n = m.num_coordinates;
  std::vector<double> x = start;
  for (std::size_t i = 0; i < n; ++i)
    if (!m.is_cyclic[i]) x[n + i] = 0;
  std::vector<long> held_coordinates;
  for (std::size_t i = 0; i < n && i < held.size(); ++i)
    if (held[i]) held_coordinates.push_back(long(i));
  ConstraintProjection projection(problem);
  // back onto g = 0: the held coordinates kept where there are any (the dependent ones chosen among
  // the others), else the smallest correction
  auto onto_constraints = [&](std::vector<double>& y) {
    if (held_coordinates.empty()) return projection.project(0.0, y.data());
    return projection.make_consistent(0.0, y.data(), held);
  };
  int iterations = 0;
  if (projection.make_consistent(0.0, x.data(), held)) {
    for (; iterations < 100 && !balance_at(problem, x, 1e-3).balanced; ++iterations) {
      Eigen::VectorXd ddq = unstabilized_rate(problem, x).tail(long(n));
      // the tangent directions in each coordinate's size: against G's largest entry in its own units,
      // a slider-crank of 1e-13 m had its crank's and rod's columns (r of 1e-13 m) taken for zero;
      // a held coordinate's row keeps it
      Eigen::VectorXd size = Eigen::Map<const Eigen::VectorXd>(given_sizes(m, x).data(), long(n));
      RowMajor G = holonomic_constraints(problem, x).G, fixed(G.rows() + long(held_coordinates.size()), long(n));
      fixed << G, RowMajor::Zero(long(held_coordinates.size()), long(n));
      for (std::size_t k = 0; k < held_coordinates.size(); ++k) fixed(G.rows() + long(k), held_coordinates[k]) = 1;
      Eigen::MatrixXd N = size.asDiagonal() * tangent_basis(fixed * size.asDiagonal(), long(n));
      if (N.cols() == 0) break;  // the held coordinates fix the configuration
      Eigen::MatrixXd stiffness = N.transpose() * unstabilized_jacobian(problem, x).bottomLeftCorner(long(n), long(n)) * N;
      Eigen::VectorXd step = N * stiffness.completeOrthogonalDecomposition().solve(-N.transpose() * ddq);
      for (std::size_t i = 0; i < n; ++i)
        if (m.is_cyclic[i]) step[long(i)] = 0;
      double before = ddq.norm(), fraction = 1;
      std::vector<double> y;
      for (int halvings = 0; halvings < 60; ++halvings, fraction /= 2) {
        y = x;
        for (std::size_t i = 0; i < n; ++i) y[i] += fraction * step[long(i)];
        if (onto_constraints(y) && unstabilized_rate(problem, y).tail(long(n)).norm() < before) break;
        y.clear();
      }
      if (y.empty()) break;  // no part of the step lowers q'': a minimum of |q''| that is not zero
      x = std::move(y);
    }
  }
  Equilibrium e = check_constrained_equilibrium(problem, std::move(x));
  e.iterations = iterations;
  return e;
}

}  // namespace eomgen::runtime
