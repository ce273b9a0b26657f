/// @file What counts as zero for the rates x' = F(x) of a first-order form (Appell's equations,
/// Lagrange I on its manifold) at a state that is meant to be a steady motion: each rate against
/// the terms it sums, not against the Jacobian's largest entry. The rows of F differ in their
/// units of time: q' = W s is of order 1/T, s' and q'' of 1/T². Against one scale for all, the q'
/// rows' entries of 1 had let a Cartesian pendulum at 0.5 rad pass for an equilibrium at a time
/// scale of 1e12 s, where its q'' is 5e-24.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Dense>

#include "analyse/first_order_form.hpp"
#include "simulation.hpp"

namespace eomgen::runtime {

/// The rates' balance at a state: the row whose rate is largest against what counts as zero for
/// it, that rate and that tolerance, and whether every row is within its own.
struct RateBalance {
  long row = -1;
  double residual = 0, tolerance = 0;
  bool balanced = true;
};

/// Zero for row i: 1e-9 of the size of the terms x'_i sums. In the linear approximation they are
/// Σ_j |J_ij| s_j, with s_j the `sizes` of the components: a coordinate's own (coordinate_sizes.hpp),
/// a velocity's |x_j|; a component of size |x_i| changes at about ρ |x_i| in a system whose rate is ρ
/// (J's spectral scale, system_scales.hpp). Where terms cancel exactly in J, the row's rounding
/// `noise` (below) tells their size: 1e6 of it, as 1e-9 is about 1e7 rounding errors. The Whipple
/// bicycle's lateral acceleration in its straight run at 4.6 m/s is rounding alone (4e-17) in a
/// row of J that is zero. A row with none of these (q' = v at rest) must be zero exactly. J and x are
/// those of the components the rates are checked on (J square); `margin` scales every tolerance
/// (1e-3 for a search that should land well within it).
RateBalance rate_balance(const Eigen::VectorXd& rates, const Eigen::MatrixXd& J, const Eigen::VectorXd& x,
                         const Eigen::VectorXd& sizes, const Eigen::VectorXd& noise, double margin = 1.0);

/// How far past its tolerance a residual is (residual / tolerance): a residual that is not finite,
/// or not zero where its tolerance is, is past any.
double how_far_past(double residual, double tolerance);

/// The rates' balance against per-row tolerances: the row farthest past its own (a rate that is
/// not finite, or not zero where its tolerance is, past any).
RateBalance worst_row(const Eigen::VectorXd& rates, const Eigen::VectorXd& tolerances);

/// Each rate's rounding noise at the state x: its largest change when every parameter, input and
/// component of x is moved by a few units in its last place, three times (the linear change is
/// 4e-16 of the terms, far below what rate_balance counts as zero). Parameters too: the Whipple
/// bicycle's upright configuration is all zeros, and its rounding comes from g and the lengths.
/// `rates(problem, y)` gives the rates checked, at a whole state y.
template <class Rates>
Eigen::VectorXd rounding_noise(const Rates& rates, const Problem& problem, const std::vector<double>& x) {
  Eigen::VectorXd at_x = rates(problem, x), noise = Eigen::VectorXd::Zero(at_x.size());
  auto nudged = [](std::vector<double> v, double nudge) {
    for (std::size_t k = 0; k < v.size(); ++k) v[k] *= 1 + (k % 2 ? -nudge : nudge);
    return v;
  };
  for (double nudge : {0x1p-50, -0x1p-50, 0x1p-49}) {
    Problem moved = problem;
    moved.parameters = nudged(problem.parameters, nudge), moved.inputs = nudged(problem.inputs, nudge);
    Eigen::VectorXd there = rates(moved, nudged(x, nudge));
    for (long i = 0; i < noise.size(); ++i) noise[i] = std::max(noise[i], std::abs(there[i] - at_x[i]));
  }
  return noise;
}

/// rate_balance on the reduced state (first_order_form.hpp: the non-cyclic coordinates and the
/// velocities) at x: `rates(problem, y)` gives x' of the whole state at y, J is ∂x'/∂x of the whole
/// state at x, and `coordinate_size` each coordinate's (coordinate_sizes.hpp).
template <class Rates>
RateBalance reduced_rate_balance(const Problem& problem, const std::vector<double>& x, const Rates& rates,
                                 const Eigen::MatrixXd& J, const std::vector<double>& coordinate_size, double margin) {
  const eomgen_model_abi& m = *problem.model;
  std::vector<int> kept = reduced_state(m);
  auto reduced = [&](const Problem& at, const std::vector<double>& y) {
    Eigen::VectorXd all = rates(at, y), out(long(kept.size()));
    for (std::size_t i = 0; i < kept.size(); ++i) out[long(i)] = all[kept[i]];
    return out;
  };
  Eigen::VectorXd values(long(kept.size())), sizes(long(kept.size()));
  Eigen::MatrixXd reduced_J(long(kept.size()), long(kept.size()));
  for (std::size_t i = 0; i < kept.size(); ++i) {
    values[long(i)] = x[std::size_t(kept[i])];
    bool coordinate = kept[i] < int(m.num_coordinates);
    sizes[long(i)] = coordinate ? coordinate_size[std::size_t(kept[i])] : std::abs(values[long(i)]);
    for (std::size_t j = 0; j < kept.size(); ++j) reduced_J(long(i), long(j)) = J(kept[i], kept[j]);
  }
  return rate_balance(reduced(problem, x), reduced_J, values, sizes, rounding_noise(reduced, problem, x), margin);
}

}  // namespace eomgen::runtime
