#include "analyse/first_order_equilibrium.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "analyse/first_order_form.hpp"
#include "analyse/newton_steps.hpp"
#include "analyse/rate_balance.hpp"
#include "analyse/state_check.hpp"
#include "analyse/system_scales.hpp"
#include "integrate/coordinate_sizes.hpp"
#include "integrate/quaternion_norms.hpp"

namespace eomgen::runtime {

namespace {

// x' = 0 on the reduced state (the non-cyclic coordinates stand still, the pseudo-velocities or
// momenta are constant), each rate against the terms it sums (rate_balance.hpp), times `margin`
RateBalance first_order_balance(const Problem& problem, const std::vector<double>& state, double margin) {
  auto rates = [](const Problem& at, const std::vector<double>& y) {
    const eomgen_model_abi& m = *at.model;
    Eigen::VectorXd rate(m.num_states);
    m.rhs(0.0, y.data(), at.held_inputs(), at.parameters.data(), rate.data());
    return rate;
  };
  // one unit where all sizes are zero: a steady motion's default state is that motion, its rate
  // zero to rounding alone (the Whipple bicycle's upright run, 1e-14 at q = 0), which sets no scale
  return reduced_rate_balance(problem, state, rates, state_jacobian(problem, 0.0, state),
                              coordinate_sizes(*problem.model, state.data(), true, 1.0), margin);
}

bool fit(const Problem& problem, const Equilibrium& e) {
  return e.converged && unfit_state(problem, 0.0, e.state).empty();
}

std::vector<int> with_velocities(const eomgen_model_abi& m, std::vector<int> unknowns) {
  for (std::size_t i = m.num_coordinates; i < m.num_states; ++i) unknowns.push_back(int(i));
  return unknowns;
}

std::string velocities_text(const eomgen_model_abi& m, const std::vector<double>& x) {
  std::string text;
  for (std::size_t i = m.num_coordinates; i < m.num_states; ++i)
    text += fmt::format("{}{} = {:.6g}", text.empty() ? "" : ", ", m.state_names[i], x[i]);
  return text;
}

// The start with its non-cyclic coordinates standing still and its cyclic ones moving as they do
// there, the velocities that make q' so: s = C⁻¹ (q'_target − q'(q, 0)) with C = ∂q'/∂s (q' is
// affine in the velocities: Appell's W s, Hamilton's M⁻¹ (p − a)). Lagrange II's search starts so,
// with the non-cyclic rates zero: a free body written for Hamilton, its momenta (1, 0, 6) at
// Cardan angles 0, starts spinning about its first axis, as Lagrange II finds it, where Newton on
// all three momenta had gone to rest. None where the velocities are not one per coordinate (a
// quaternion, a nonholonomic constraint) or C is singular.
std::optional<std::vector<double>> standing_start(const Problem& problem, const std::vector<double>& start) {
  const eomgen_model_abi& m = *problem.model;
  const std::size_t n = m.num_coordinates;
  if (m.num_velocities != n || m.num_quaternions > 0) return std::nullopt;
  std::vector<double> rate(m.num_states), at_rest = start;
  std::fill(at_rest.begin() + long(n), at_rest.end(), 0.0);
  m.rhs(0.0, start.data(), problem.held_inputs(), problem.parameters.data(), rate.data());
  Eigen::VectorXd target = Eigen::Map<Eigen::VectorXd>(rate.data(), long(n));
  for (std::size_t i = 0; i < n; ++i)
    if (!m.is_cyclic[i]) target[long(i)] = 0;
  m.rhs(0.0, at_rest.data(), problem.held_inputs(), problem.parameters.data(), rate.data());
  target -= Eigen::Map<Eigen::VectorXd>(rate.data(), long(n));
  Eigen::MatrixXd C = state_jacobian(problem, 0.0, start).block(0, long(n), long(n), long(n));
  Eigen::FullPivLU<Eigen::MatrixXd> lu(C);
  if (!C.allFinite() || !lu.isInvertible()) return std::nullopt;
  Eigen::VectorXd s = lu.solve(target);
  if (!s.allFinite()) return std::nullopt;
  std::vector<double> standing = start;
  for (std::size_t i = 0; i < n; ++i) standing[n + i] = s[long(i)];
  return standing;
}

// What the first search (the velocities held) did, for the note of the one whose state is analysed
std::string first_search_text(const Problem& problem, const std::vector<double>& start, const Equilibrium& moving,
                              bool all_cyclic) {
  const eomgen_model_abi& m = *problem.model;
  std::string given = velocities_text(m, start);
  bool moves = std::any_of(start.begin() + long(m.num_coordinates), start.end(), [](double v) { return v != 0; });
  if (!moves)
    return fmt::format("Newton's method from the initial state, at rest, found no equilibrium in {} steps ({})",
                       moving.iterations, search_end_text(problem, moving));
  if (all_cyclic)
    return fmt::format("the initial velocities ({}) make no steady motion ({}) and every coordinate is cyclic", given,
                       search_end_text(problem, moving));
  if (moving.converged)
    return fmt::format("Newton's method on the coordinates, the initial velocities ({}) held, ended at {}, where the mass "
                       "matrix is singular (so are the coordinates there)",
                       given, state_text(m, moving.state));
  return fmt::format("Newton's method on the coordinates, the initial velocities ({}) held, found none in {} steps ({})",
                     given, moving.iterations, search_end_text(problem, moving));
}

// Dynamic relaxation as Lagrange II's search has it (equilibrium.cpp, come_to_rest), on the
// first-order form: each velocity (pseudo-velocity, momentum) damped by c s, which takes energy
// out (c sᵀ M s in Appell's T = ½ sᵀ M s, c q'ᵀ M q' in Hamilton's), then the coordinates moved at
// their rates with the damped velocities; rest where the rates at zero velocity have fallen to a
// thousandth of the start's, polished by Newton on the coordinates.
Equilibrium first_order_come_to_rest(const Problem& problem, std::vector<double> x, const std::vector<int>& coordinates) {
  const eomgen_model_abi& m = *problem.model;
  std::size_t n = m.num_coordinates;
  const RateRange range = rate_range(state_jacobian(problem, 0.0, x));
  const double fastest = range.fastest, slowest = range.slowest;
  Equilibrium rest;
  if (!(fastest > 0) || !std::isfinite(fastest)) return rest;
  auto at_rest = [&](std::vector<double> y) {
    std::fill(y.begin() + long(n), y.end(), 0.0);
    return y;
  };
  auto largest_rate = [&](const std::vector<double>& y) {
    Eigen::VectorXd r = reduced_rate(problem, y);
    return r.allFinite() ? r.cwiseAbs().maxCoeff() : INFINITY;
  };
  const double h = 0.2 / fastest, c = 2 * slowest, start = largest_rate(at_rest(x));
  std::vector<double> rate(m.num_states);
  for (long step = 1; step <= 200000; ++step) {
    m.rhs(0.0, x.data(), problem.held_inputs(), problem.parameters.data(), rate.data());
    for (std::size_t i = n; i < m.num_states; ++i) x[i] += h * (rate[i] - c * x[i]);
    m.rhs(0.0, x.data(), problem.held_inputs(), problem.parameters.data(), rate.data());
    for (std::size_t i = 0; i < n; ++i) x[i] += h * rate[i];
    normalize_quaternions(m, x.data());
    if (step % 500 != 0) continue;
    double residual = largest_rate(at_rest(x));
    if (!std::isfinite(residual)) return rest;
    if (residual > 1e-3 * start) continue;
    rest = solve_first_order(problem, at_rest(x), coordinates);
    if (rest.converged) return rest;
  }
  return rest;
}

}  // namespace

Equilibrium check_first_order(const Problem& problem, std::vector<double> state) {
  RateBalance b = first_order_balance(problem, state, 1.0);
  Equilibrium e;
  e.residual = b.residual, e.tolerance = b.tolerance, e.converged = b.balanced;
  e.state = std::move(state);
  return e;
}

// Each coordinate in its size (coordinate_sizes.hpp), so that the rank is decided, and a step
// limited, alike for angles and lengths; the velocities solved for in one unit, the largest of them
// at the start (a steady motion's rates in their own scale, alike for all so that a least-squares
// step keeps their proportions, as Lagrange II's search has its cyclic velocities), and limited in
// it too: unlimited, a falling humanoid's base was driven to 3e14 m/s, where gravity's 9.81 is
// below the rounding of its velocities' terms. Without that unit (all zero at the start, where
// find_first_order_equilibrium does not solve for them) each velocity is in the unit that makes
// its column of the Jacobian of unit length. Each rate in its row's scale, the system's
// rate ρ (system_scales.hpp) times its component's unit, so that the least-squares step is the same
// at every time scale (q' = W s is of order 1/T, s' of 1/T²).
Equilibrium solve_first_order(const Problem& problem, std::vector<double> x, const std::vector<int>& unknowns) {
  const eomgen_model_abi& m = *problem.model;
  const std::size_t n = m.num_coordinates;
  std::vector<int> kept = reduced_state(m);
  std::vector<long> column;  // each unknown's place in the reduced state
  for (int i : unknowns) column.push_back(long(std::find(kept.begin(), kept.end(), i) - kept.begin()));
  double rate_unit = 0;
  for (int i : unknowns)
    if (std::size_t(i) >= n) rate_unit = std::max(rate_unit, std::abs(x[std::size_t(i)]));
  if (!std::isfinite(rate_unit)) rate_unit = 0;
  int iterations = 0;
  Eigen::VectorXd last_unit;
  for (; iterations < 100 && !unknowns.empty(); ++iterations) {
    Eigen::VectorXd r = reduced_rate(problem, x);
    Eigen::MatrixXd jacobian = reduced_jacobian(problem, x);
    // done at a thousandth of what counts as zero, in the model's scales (not 1e-15 in its units)
    if (!r.allFinite() || first_order_balance(problem, x, 1e-3).balanced) break;
    std::vector<double> size = coordinate_sizes(m, x.data(), true, 1.0);
    Eigen::MatrixXd J(jacobian.rows(), long(unknowns.size()));
    Eigen::VectorXd unit(long(unknowns.size()));
    for (std::size_t k = 0; k < unknowns.size(); ++k) {
      auto i = std::size_t(unknowns[k]);
      double length = jacobian.col(column[k]).norm();
      unit[long(k)] = i < n                              ? size[i]
                      : rate_unit > 0                    ? rate_unit
                      : length > 0 && std::isfinite(length) ? 1 / length
                                                         : 1.0;
      J.col(long(k)) = jacobian.col(column[k]) * unit[long(k)];
    }
    double rate = jacobian.allFinite() ? spectral_scale(jacobian) : 0.0;
    Eigen::VectorXd row_scale(jacobian.rows());
    for (std::size_t k = 0; k < kept.size(); ++k) {
      auto i = std::size_t(kept[k]);
      double own = i < n ? size[i] : rate_unit > 0 ? rate_unit : 1.0;
      row_scale[long(k)] = rate > 0 && std::isfinite(rate) ? rate * own : 1.0;
    }
    Eigen::MatrixXd scaled = row_scale.cwiseInverse().asDiagonal() * J;
    Eigen::VectorXd step =
        unit.asDiagonal() * scaled.completeOrthogonalDecomposition().solve(-r.cwiseQuotient(row_scale));
    last_unit = unit;
    double largest = 0;  // the step's largest part in the units of the coordinates and of the start's rates
    for (std::size_t k = 0; k < unknowns.size(); ++k)
      if (std::size_t(unknowns[k]) < n || rate_unit > 0) largest = std::max(largest, std::abs(step[long(k)] / unit[long(k)]));
    auto moved = [&](double fraction) {
      std::vector<double> y = x;
      for (std::size_t k = 0; k < unknowns.size(); ++k) y[unknowns[k]] += fraction * step[static_cast<long>(k)];
      normalize_quaternions(m, y.data());
      return y;
    };
    auto residual = [&](const Eigen::VectorXd& rates) { return rates.cwiseQuotient(row_scale).cwiseAbs().maxCoeff(); };
    double scale = step_fraction(largest, residual(r), [&] { return residual(reduced_rate(problem, moved(1.0))); });
    // moved() keeps quaternions unit: Newton moves their four coordinates freely, and off the unit
    // sphere a falling body's shrank to 1e-30 in 13 steps and its Jacobian, which the tolerance
    // follows, grew to 1e13
    x = moved(scale);
    bool negligible = true;
    for (std::size_t k = 0; k < unknowns.size(); ++k)
      negligible = negligible && std::abs(step[long(k)]) <= 1e-14 * std::max(unit[long(k)], std::abs(x[unknowns[k]]));
    if (scale == 1.0 && negligible) break;
  }
  Equilibrium e = check_first_order(problem, x);
  e.iterations = iterations;
  if (e.converged || last_unit.size() == 0) return e;
  // A velocity whose steady value is zero (a governor's der(theta), a body's rate about an axis it
  // does not spin about) ends within the solve's rounding of it, 1e-31 beside 1, and its own row,
  // q_i' = s_i, balances nothing but zero: those within rounding of the unknowns' largest (each
  // in its unit) are set to zero.
  double largest = 0;
  for (std::size_t k = 0; k < unknowns.size(); ++k) largest = std::max(largest, std::abs(x[unknowns[k]] / last_unit[long(k)]));
  for (std::size_t k = 0; k < unknowns.size(); ++k)
    if (std::size_t(unknowns[k]) >= m.num_coordinates && std::abs(x[unknowns[k]] / last_unit[long(k)]) <= 1e-13 * largest)
      x[unknowns[k]] = 0;
  Equilibrium zeroed = check_first_order(problem, std::move(x));
  zeroed.iterations = iterations;
  return zeroed.converged ? zeroed : e;
}

Equilibrium find_first_order_equilibrium(const Problem& problem, const std::vector<double>& start,
                                         const std::vector<int>& coordinates) {
  const eomgen_model_abi& m = *problem.model;
  Equilibrium moving = solve_first_order(problem, start, coordinates);
  if (fit(problem, moving)) return moving;
  const std::string first = first_search_text(problem, start, moving, coordinates.empty());
  int iterations = moving.iterations;
  // the first that converged where the mass matrix is singular, returned where none converges
  // elsewhere: refused as such (state_check.hpp), as Lagrange II's search refuses a crane hook's
  // hanging load, whose azimuth is undefined, not "no equilibrium found"
  std::optional<Equilibrium> singular;
  if (moving.converged) singular = moving;
  // A steady search whose velocities all crept below a millionth of the start's found rest, which
  // the search at rest below finds from the initial configuration: a spinning top on its ball joint
  // came to rest turned about the vertical, where `--at wz=0` names it unturned.
  double fastest_start = 0;
  for (std::size_t i = m.num_coordinates; i < m.num_states; ++i) fastest_start = std::max(fastest_start, std::abs(start[i]));
  auto steady = [&](Equilibrium e) {
    bool crept = true;
    for (std::size_t i = m.num_coordinates; i < m.num_states; ++i)
      crept = crept && std::abs(e.state[i]) <= 1e-6 * fastest_start;
    if (crept) e.converged = false;
    return e;
  };
  auto taken = [&](Equilibrium e, const std::string& also, const std::string& what) -> std::optional<Equilibrium> {
    int own = e.iterations;
    e.iterations += iterations, iterations += own;
    bool rests = std::all_of(e.state.begin() + long(m.num_coordinates), e.state.end(), [](double v) { return v == 0; });
    e.note = fmt::format("{}{}; this is {}", first, also,
                         fmt::format(fmt::runtime(what), rests ? "the equilibrium at rest" : "the steady motion"));
    if (fit(problem, e)) return e;
    if (e.converged && !singular) singular = e;
    return std::nullopt;
  };
  // from rest no velocity sets the unit of steady rates, and rest is what the first search sought
  bool moves = std::any_of(start.begin() + long(m.num_coordinates), start.end(), [](double v) { return v != 0; });
  const std::string no_steady = moves ? ", and with the velocities solved for too found no steady motion" : "";
  if (moves) {
    std::optional<std::vector<double>> standing = standing_start(problem, start);
    if (standing && *standing != start) {
      if (auto found = taken(steady(solve_first_order(problem, *standing, with_velocities(m, coordinates))), "",
                             "{} nearest the initial state with its non-cyclic coordinates standing still, its "
                             "velocities solved for"))
        return *found;
    }
    if (auto found = taken(steady(solve_first_order(problem, start, with_velocities(m, coordinates))), "",
                           "{} nearest the initial state, its velocities solved for"))
      return *found;
    if (auto found = taken(steady(solve_first_order(problem, start, with_velocities(m, {}))), no_steady,
                           "{} at the initial configuration, its velocities alone solved for"))
      return *found;
    std::vector<double> at_rest = start;
    std::fill(at_rest.begin() + long(m.num_coordinates), at_rest.end(), 0.0);
    if (auto found = taken(solve_first_order(problem, at_rest, coordinates), no_steady,
                           "{} from the initial configuration"))
      return *found;
  }
  if (auto found = taken(first_order_come_to_rest(problem, start, coordinates),
                         moves ? no_steady + " nor rest from the initial configuration" : "",
                         "where the model, released at its initial state with damping added, comes to rest"))
    return *found;
  return singular ? *singular : moving;
}

}  // namespace eomgen::runtime
