#include "analyse/equilibrium.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "analyse/constrained_equilibrium.hpp"
#include "analyse/constrained_first_order.hpp"
#include "analyse/first_order_equilibrium.hpp"
#include "analyse/first_order_form.hpp"
#include "analyse/newton_steps.hpp"
#include "analyse/rate_balance.hpp"
#include "analyse/state_check.hpp"
#include "analyse/system_scales.hpp"
#include "integrate/coordinate_sizes.hpp"
#include "integrate/quaternion_norms.hpp"

namespace eomgen::runtime {

namespace {

struct Derivatives {
  Eigen::VectorXd f;
  Eigen::MatrixXd P, Q;  // −∂f/∂q', −∂f/∂q
};

Derivatives evaluate(const Problem& p, const std::vector<double>& x) {
  const eomgen_model_abi& m = *p.model;
  std::size_t n = m.num_coordinates;
  const double* u = p.held_inputs();
  std::vector<double> f(n), P(n * n), Q(n * n), B(n * m.num_inputs + 1);
  m.forcing(0.0, x.data(), u, p.parameters.data(), f.data());
  m.linearization(0.0, x.data(), u, p.parameters.data(), P.data(), Q.data(), B.data());
  Derivatives d{Eigen::Map<Eigen::VectorXd>(f.data(), n),
                Eigen::Map<Eigen::Matrix<double, -1, -1, Eigen::RowMajor>>(P.data(), n, n),
                Eigen::Map<Eigen::Matrix<double, -1, -1, Eigen::RowMajor>>(Q.data(), n, n)};
  return d;
}

// f at x
Eigen::VectorXd forcing_at(const Problem& p, const std::vector<double>& x) {
  const eomgen_model_abi& m = *p.model;
  Eigen::VectorXd f(long(m.num_coordinates));
  m.forcing(0.0, x.data(), p.held_inputs(), p.parameters.data(), f.data());
  return f;
}

// the largest |f| at x
double forcing_residual(const Problem& p, const std::vector<double>& x) {
  double largest = 0;
  for (double v : forcing_at(p, x)) largest = std::isfinite(v) ? std::max(largest, std::abs(v)) : INFINITY;
  return largest;
}

// Each coordinate's size (coordinate_sizes.hpp), here or in the model's default state. No floor of
// one unit: a mass of 1e-12 kg on a spring of 1 N/m hangs 9.81e-12 m down, and z = 0, within 1e-9
// of a metre of it, had passed for its equilibrium.
std::vector<double> configuration_sizes(const eomgen_model_abi& m, const std::vector<double>& x) {
  return coordinate_sizes(m, x.data(), true, 0.0);
}

// the model's default state with its non-cyclic coordinates at rest
std::vector<double> default_at_rest(const eomgen_model_abi& m) {
  std::vector<double> x(m.default_state, m.default_state + m.num_states);
  for (std::size_t i = 0; i < m.num_coordinates && m.num_coordinates + i < m.num_states; ++i)
    if (!m.is_cyclic[i]) x[m.num_coordinates + i] = 0;
  return x;
}

// Zero for row i of f: 1e-9 of the forces it balances. They are the generalized stiffness times
// each coordinate's size (f over the stiffness is the displacement to the equilibrium: below 1e-9
// of the coordinate's size), Σ_j |Q_ij| s_j, with the velocity terms Σ_j |P_ij| |q'_j| of a steady
// motion, or |f_i| in the default configuration at rest (the hanging mass's m g, where the
// configuration's size is 0), whichever is larger; 1e6 of the row's rounding noise where terms
// cancel exactly (rate_balance.hpp). No floor in the units of f: one of 1 took a pendulum of
// 1e-12 kg at 0.5 rad for an equilibrium. Only where these are all zero (a default that balances
// exactly at q = 0, and q = 0) is the size one unit. Row by row, since the rows differ in units
// (a force, a moment): against the largest |Q| times the largest |q|, a spring pendulum of 1e12 m
// had passed at 0.5 rad.
Eigen::VectorXd force_tolerances(const Problem& p, const Derivatives& d, const std::vector<double>& x,
                                 const Eigen::VectorXd& default_forces) {
  const eomgen_model_abi& m = *p.model;
  std::size_t n = m.num_coordinates;
  std::vector<double> size = configuration_sizes(m, x);
  Eigen::VectorXd noise = rounding_noise(forcing_at, p, x);
  Eigen::VectorXd tolerances(static_cast<Eigen::Index>(n));
  for (long i = 0; i < long(n); ++i) {
    double forces = 0, stiffness = 0;
    for (long j = 0; j < long(n); ++j) {
      forces += std::abs(d.Q(i, j)) * size[std::size_t(j)] + std::abs(d.P(i, j) * x[n + std::size_t(j)]);
      stiffness += std::abs(d.Q(i, j));
    }
    if (std::isfinite(default_forces[i])) forces = std::max(forces, std::abs(default_forces[i]));
    double noisy = std::isfinite(noise[i]) ? 1e6 * noise[i] : 0.0;
    tolerances[i] = std::max(1e-9 * (forces > 0 ? forces : stiffness), noisy);
  }
  return tolerances;
}

}  // namespace

std::string moving_coordinates(const eomgen_model_abi& m, const std::vector<double>& x) {
  std::string moving;
  for (std::size_t i = 0; i < m.num_coordinates; ++i)
    if (!m.is_cyclic[i] && x[m.num_coordinates + i] != 0)
      moving += fmt::format("{}{} = {:.6g}", moving.empty() ? "" : ", ", m.state_names[m.num_coordinates + i],
                            x[m.num_coordinates + i]);
  return moving;
}

Equilibrium check_equilibrium(const Problem& problem, std::vector<double> state) {
  if (has_multipliers(*problem.model)) return check_constrained_equilibrium(problem, std::move(state));
  if (has_pseudo_velocities(*problem.model)) return check_first_order(problem, std::move(state));
  Derivatives d = evaluate(problem, state);
  Equilibrium e;
  e.moving = moving_coordinates(*problem.model, state);
  e.state = std::move(state);
  Eigen::VectorXd default_forces = forcing_at(problem, default_at_rest(*problem.model));
  RateBalance b = worst_row(d.f, force_tolerances(problem, d, e.state, default_forces));
  e.residual = b.residual, e.tolerance = b.tolerance;
  e.converged = b.balanced && e.moving.empty();
  return e;
}

namespace {

// The Newton step on the states `unknowns` (indices into x) that takes f, or r = f − const, to
// zero: ∂f/∂q = −Q, ∂f/∂q' = −P (least squares when rank deficient), solved with each row divided by
// its `weight` and each unknown in its `unit`: the rank is decided against the largest entry, and
// a spring pendulum of 1e12 m has a stiffness of 1e2 N/m beside a pendulum's 1e25 N m, which left r
// out of every step
Eigen::VectorXd newton_step(const Derivatives& d, const std::vector<int>& unknowns, std::size_t n,
                            const Eigen::VectorXd& r, const Eigen::VectorXd& weight, const Eigen::VectorXd& unit) {
  Eigen::MatrixXd J(n, unknowns.size());
  for (std::size_t k = 0; k < unknowns.size(); ++k) {
    int i = unknowns[k];
    J.col(static_cast<long>(k)) = i < static_cast<int>(n) ? Eigen::VectorXd(-d.Q.col(i)) : Eigen::VectorXd(-d.P.col(i - n));
  }
  Eigen::MatrixXd scaled = weight.cwiseInverse().asDiagonal() * J * unit.asDiagonal();
  return unit.asDiagonal() * scaled.completeOrthogonalDecomposition().solve(-r.cwiseQuotient(weight));
}

// Newton on f = 0 from x in the states `unknowns` (indices into x), the others held; steps of at
// most half a unit (step_fraction) where `near_start`, else backtracked
Equilibrium balance_by_newton(const Problem& problem, std::vector<double> x, const std::vector<int>& unknowns,
                              bool near_start) {
  const eomgen_model_abi& m = *problem.model;
  std::size_t n = m.num_coordinates;
  int iterations = 0;
  const Eigen::VectorXd default_forces = forcing_at(problem, default_at_rest(m));
  // below the tolerance, up to three more whole steps while they still move the state against its
  // own size: the tolerance's displacement may be 1e-9 of the default configuration, and springs
  // of 1e12 N/m hold their masses 3e-13 m away, which the first step reached to 7e-6 of it (the
  // best of them kept: a step from within rounding may land no nearer)
  int polished = 0;
  std::vector<double> best;
  double best_merit = INFINITY;
  // the velocities' unit: the largest of them at the start (a steady motion's rates in their own
  // scale, alike for all so that a least-squares step keeps their proportions), else 1. In units of
  // 1 rad/s, gimbal_cardan's search from 0.2 rad/s halved der(alpha) toward the double root of a free
  // body's f ~ ω² and stopped at 2.6e-8, whose split Jordan blocks read as "marginally stable", while
  // from rates times 1e12 it found the steady spin about the minor axis
  double rate_unit = 0;
  for (int i : unknowns)
    if (std::size_t(i) >= n) rate_unit = std::max(rate_unit, std::abs(x[std::size_t(i)]));
  if (!(rate_unit > 0) || !std::isfinite(rate_unit)) rate_unit = 1.0;
  for (; iterations < 100; ++iterations) {
    Derivatives d = evaluate(problem, x);
    if (!d.f.allFinite()) break;
    // each row in its tolerance, each unknown in its coordinate's size (a velocity in its units)
    Eigen::VectorXd weight = force_tolerances(problem, d, x, default_forces);
    bool within = worst_row(d.f, 1e-3 * weight).balanced;
    for (double& w : weight) w = w > 0 && std::isfinite(w) ? w : 1.0;
    // the largest |f_i| over its row's weight: the rows differ in units (a force, a moment)
    auto merit = [&weight](const Eigen::VectorXd& f) {
      return f.allFinite() ? f.cwiseQuotient(weight).cwiseAbs().maxCoeff() : INFINITY;
    };
    double residual = merit(d.f);
    if (within && residual < best_merit) best = x, best_merit = residual;
    if (within && ++polished > 3) break;
    std::vector<double> size = configuration_sizes(m, x);
    Eigen::VectorXd unit(static_cast<Eigen::Index>(unknowns.size()));
    for (std::size_t k = 0; k < unknowns.size(); ++k) {
      std::size_t i = std::size_t(unknowns[k]);
      unit[static_cast<long>(k)] = i < n ? (size[i] > 0 ? size[i] : 1.0) : rate_unit;
    }
    Eigen::VectorXd step = newton_step(d, unknowns, n, d.f, weight, unit);
    auto moved = [&](double fraction) {
      std::vector<double> y = x;
      for (std::size_t k = 0; k < unknowns.size(); ++k) y[unknowns[k]] += fraction * step[static_cast<long>(k)];
      return y;
    };
    auto merit_after = [&](double fraction) { return merit(forcing_at(problem, moved(fraction))); };
    // the step's largest part in those units: half a radian and half of a length beside it are both
    // large
    double largest = step.cwiseQuotient(unit).cwiseAbs().maxCoeff();
    // a step within rounding of each unknown's own value (a largest |x| mixes units: a conical
    // pendulum's φ' of 4e-12 rad/s beside θ = 0.8 stopped three steps short)
    bool negligible = true;
    for (std::size_t k = 0; k < unknowns.size(); ++k)
      negligible = negligible && std::abs(step[static_cast<long>(k)]) <= 1e-14 * std::abs(x[unknowns[k]]);
    if (within && negligible) break;
    double scale = within       ? 1.0
                   : near_start ? step_fraction(largest, residual, [&] { return merit_after(1.0); })
                                : backtracked_fraction(residual, merit_after);
    x = moved(scale);
    if (scale == 1.0 && negligible) break;
  }
  Equilibrium checked = check_equilibrium(problem, x);
  if (!best.empty() && best != x) {
    // the best of the polishing steps, in how far each row is within its own tolerance
    Equilibrium at_best = check_equilibrium(problem, best);
    if (!(how_far_past(checked.residual, checked.tolerance) <= how_far_past(at_best.residual, at_best.tolerance)))
      checked = at_best;
  }
  checked.iterations = iterations;
  return checked;
}

// Dynamic relaxation: the motion from the start at rest with a damping c q' added, polished by
// Newton's method once its forces have fallen to a thousandth: the stable equilibrium where the
// model released at its initial state comes to rest. Symplectic Euler in steps of 0.2 over the
// fastest rate of the linearization at the start (stable to 2), c twice the slowest (critical for
// that mode); at most 200000 steps.
Equilibrium come_to_rest(const Problem& problem, std::vector<double> x, const std::vector<int>& unknowns) {
  const eomgen_model_abi& m = *problem.model;
  std::size_t n = m.num_coordinates;
  const RateRange range = rate_range(state_jacobian(problem, 0.0, x));
  const double fastest = range.fastest, slowest = range.slowest;
  Equilibrium rest;
  if (!(fastest > 0) || !std::isfinite(fastest)) return rest;
  const double h = 0.2 / fastest, c = 2 * slowest, start = forcing_residual(problem, x);
  std::vector<double> rate(m.num_states);
  for (long step = 1; step <= 200000; ++step) {
    m.rhs(0.0, x.data(), problem.held_inputs(), problem.parameters.data(), rate.data());
    for (std::size_t i = 0; i < n; ++i) {
      x[n + i] += h * (rate[n + i] - c * x[n + i]);
      x[i] += h * x[n + i];
    }
    if (step % 500 != 0) continue;
    std::vector<double> at_rest = x;
    for (std::size_t i = 0; i < n; ++i)
      if (!m.is_cyclic[i]) at_rest[n + i] = 0;
    double residual = forcing_residual(problem, at_rest);
    if (!std::isfinite(residual)) return rest;
    if (residual > 1e-3 * start) continue;
    rest = balance_by_newton(problem, at_rest, unknowns, true);
    if (rest.converged) return rest;
  }
  return rest;
}

// Newton toward a double root of f in a cyclic velocity (air drag's f ~ v²) halves the rate at every
// step and stops, within tolerance, short of rest: car_braking's der(x) ended at 2.4e-6 m/s from 20. A
// cyclic rate below a millionth of its start, where rest balances too, is rest.
Equilibrium rest_where_it_balances(const Problem& problem, Equilibrium found, const std::vector<double>& start,
                                   const std::vector<int>& cyclic_velocities) {
  if (!found.converged) return found;
  std::vector<double> rest = found.state;
  bool crept = false;
  for (int i : cyclic_velocities) {
    auto k = static_cast<std::size_t>(i);
    if (rest[k] != 0 && std::abs(rest[k]) < 1e-6 * std::abs(start[k])) rest[k] = 0, crept = true;
  }
  if (!crept) return found;
  Equilibrium at_rest = check_equilibrium(problem, rest);
  if (!at_rest.converged) return found;
  at_rest.iterations = found.iterations;
  at_rest.note = found.note;
  return at_rest;
}

}  // namespace

std::string search_end_text(const Problem& p, const Equilibrium& e) {
  if (std::isfinite(e.residual)) return fmt::format("largest residual {:.3g}", e.residual);
  std::string why = e.state.size() == p.model->num_states ? unfit_state(p, 0.0, e.state) : std::string();
  return "its last step reached a state where the equations of motion are not finite" +
         (why.empty() ? std::string() : ": " + why);
}

Equilibrium find_equilibrium(const Problem& problem, const std::vector<double>& start) {
  const eomgen_model_abi& m = *problem.model;
  if (has_pseudo_velocities(m)) {
    std::vector<std::size_t> coordinates = unheld_unknowns(m, std::vector<bool>(m.num_states));
    return find_first_order_equilibrium(problem, start, std::vector<int>(coordinates.begin(), coordinates.end()));
  }
  if (has_multipliers(m)) return find_constrained_equilibrium(problem, start);
  std::size_t n = m.num_coordinates;
  std::vector<double> at_rest = start;
  std::vector<int> unknowns, cyclic_velocities;  // indices into the state
  for (std::size_t i = 0; i < n; ++i) {
    if (m.is_cyclic[i]) unknowns.push_back(static_cast<int>(n + i)), cyclic_velocities.push_back(static_cast<int>(n + i));
    else {
      unknowns.push_back(static_cast<int>(i));
      at_rest[n + i] = 0;
    }
  }
  Equilibrium found = balance_by_newton(problem, at_rest, unknowns, true);
  if (!found.converged) {
    if (Equilibrium rest = come_to_rest(problem, at_rest, unknowns); rest.converged) {
      rest.note = fmt::format("Newton's method from the initial state found no equilibrium in {} steps; this is where "
                              "the model, released at its initial state with damping added, comes to rest",
                              found.iterations);
      found = rest;
    }
  }
  found = rest_where_it_balances(problem, found, start, cyclic_velocities);
  bool singular = found.converged && !unfit_state(problem, 0.0, found.state).empty();
  if ((found.converged && !singular) || cyclic_velocities.empty()) return found;
  // The search found nothing, or slid onto a singularity of the coordinates, where the equations
  // balance for any cyclic velocity (a spherical pendulum at θ = 0, its azimuth undefined). The
  // steady motion at the initial configuration instead, the cyclic velocities alone free: a
  // spherical pendulum's conical motion at its initial θ, a heavy top's steady precession.
  Equilibrium held = balance_by_newton(problem, at_rest, cyclic_velocities, false);
  if (!held.converged || !unfit_state(problem, 0.0, held.state).empty()) return found;
  held.note = singular ? fmt::format("the search from the initial state ended at {}, where the mass matrix is singular (so "
                                     "are the coordinates there); this is the steady motion at the initial configuration "
                                     "instead, its cyclic velocities solved for", state_text(m, found.state))
                       : "the search from the initial state found no equilibrium; this is the steady motion at the initial "
                         "configuration, its cyclic velocities solved for";
  return held;
}

std::vector<std::size_t> unheld_unknowns(const eomgen_model_abi& m, const std::vector<bool>& held) {
  std::vector<std::size_t> unknowns;
  if (has_pseudo_velocities(m) || has_multipliers(m)) {
    // the non-cyclic coordinates (Appell, Lagrange I), a quaternion's four held together (kept
    // unit, none of them may move alone)
    std::vector<bool> fixed(held.begin(), held.begin() + long(m.num_coordinates));
    for (std::size_t q = 0; q < m.num_quaternions; ++q) {
      const std::size_t* c = m.quaternion_coordinates + 4 * q;
      bool any = held[c[0]] || held[c[1]] || held[c[2]] || held[c[3]];
      for (int k = 0; k < 4; ++k) fixed[c[k]] = fixed[c[k]] || any;
    }
    for (std::size_t i = 0; i < m.num_coordinates; ++i)
      if (!m.is_cyclic[i] && !fixed[i]) unknowns.push_back(i);
    return unknowns;
  }
  for (std::size_t i = 0; i < m.num_coordinates; ++i) {
    std::size_t own = m.is_cyclic[i] ? m.num_coordinates + i : i;
    if (!held[own]) unknowns.push_back(own);
  }
  return unknowns;
}

Equilibrium complete_equilibrium(const Problem& problem, std::vector<double> state, const std::vector<bool>& held) {
  const eomgen_model_abi& m = *problem.model;
  std::vector<std::size_t> free = unheld_unknowns(m, held);
  if (free.empty()) return check_equilibrium(problem, std::move(state));
  std::vector<int> unknowns(free.begin(), free.end());
  // Appell's pseudo-velocities as given (those not named are zero): the coordinates alone free
  if (has_pseudo_velocities(m)) return solve_first_order(problem, std::move(state), unknowns);
  // Lagrange I: the other coordinates close the constraints around the held ones, at rest
  if (has_multipliers(m)) return find_constrained_equilibrium(problem, state, held);
  std::size_t n = m.num_coordinates;
  for (std::size_t i = 0; i < n; ++i)
    if (!m.is_cyclic[i] && !held[n + i]) state[n + i] = 0;
  return balance_by_newton(problem, std::move(state), unknowns, false);
}

}  // namespace eomgen::runtime
