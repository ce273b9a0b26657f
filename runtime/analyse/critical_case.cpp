#include "analyse/critical_case.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>

#include <fmt/format.h>

#include "analyse/constrained_first_order.hpp"
#include "analyse/deviation_norms.hpp"
#include "analyse/first_order_form.hpp"
#include "analyse/local_power_law.hpp"
#include "analyse/turning_symmetries.hpp"
#include "integrate/quaternion_norms.hpp"

namespace eomgen::runtime {

namespace {


// Whether coordinate i is a quaternion's component
bool in_quaternion(const eomgen_model_abi& m, std::size_t i) {
  return std::find(m.quaternion_coordinates, m.quaternion_coordinates + 4 * m.num_quaternions, i) !=
         m.quaternion_coordinates + 4 * m.num_quaternions;
}

// The directions V is probed along: each coordinate that is neither cyclic nor a quaternion's
// component, and each quaternion's turns about the world axes that are not symmetries (the
// quaternion's tangent space modulo its symmetric turns), both ways; then random combinations
std::vector<std::vector<double>> probe_directions(const eomgen_model_abi& m, const std::vector<double>& x,
                                                  const std::vector<TurningSymmetry>& symmetries) {
  std::size_t n = m.num_coordinates;
  std::vector<std::vector<double>> basis;
  for (std::size_t i = 0; i < n; ++i) {
    if (m.is_cyclic[i] || in_quaternion(m, i)) continue;
    std::vector<double> d(n, 0.0);
    d[i] = 1;
    basis.push_back(d);
  }
  for (std::size_t k = 0; k < m.num_quaternions; ++k) {
    if (quaternion_is_cyclic(m, k)) continue;
    std::vector<Eigen::Vector3d> symmetric;
    for (const TurningSymmetry& s : symmetries)
      if (s.quaternion == k) symmetric = s.axes;
    for (const Eigen::Vector3d& a : other_axes(symmetric)) {
      Eigen::VectorXd turn = turning_direction(m, x, k, a);
      basis.push_back(std::vector<double>(turn.data(), turn.data() + n));
    }
  }
  std::vector<std::vector<double>> directions;
  for (const auto& d : basis) {
    directions.push_back(d);
    std::vector<double> opposite = d;
    for (double& v : opposite) v = -v;
    directions.push_back(opposite);
  }
  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  for (int k = 0; k < 20 && !basis.empty(); ++k) {
    std::vector<double> d(n, 0.0);
    double size = 0;
    for (const auto& b : basis) {
      double weight = normal(random);
      for (std::size_t i = 0; i < n; ++i) d[i] += weight * b[i];
    }
    for (double v : d) size += v * v;
    if (size > 0) {
      for (double& v : d) v /= std::sqrt(size);
      directions.push_back(d);
    }
  }
  return directions;
}

// x + r d with each quaternion brought back to unit length: a point of the configuration manifold
std::vector<double> probed(const eomgen_model_abi& m, const std::vector<double>& x, const std::vector<double>& d,
                           double radius) {
  std::vector<double> y = x;
  for (std::size_t i = 0; i < d.size(); ++i) y[i] += radius * d[i];
  normalize_quaternions(m, y.data());
  return y;
}

// V(q + r d) − V(q) rises by its leading power law along every coordinate direction and random
// ones: its sign at the smallest radii where it rises above rounding is the sign near the
// equilibrium, in whatever units q is written (radii fixed in units, 1e-2 and 1e-3, had stepped
// over the rim of a well 1e-3 wide). With no coordinate but cyclic ones there is no minimum. A
// quaternion is probed along its turns on the unit sphere, those that are symmetries left out:
// there V is constant, and the minimum is strict modulo them (Lagrange–Dirichlet on the quotient,
// where T + V, conserved and unchanged by the turns, has a strict minimum).
bool strict_minimum_of_potential(const Problem& p, const std::vector<double>& x, const std::vector<TurningSymmetry>& symmetries,
                                 std::string& where) {
  const eomgen_model_abi& m = *p.model;
  std::size_t n = m.num_coordinates;
  std::vector<std::vector<double>> directions = probe_directions(m, x, symmetries);
  if (directions.empty()) {
    where = m.num_quaternions ? "every coordinate is cyclic or turns as a symmetry: V depends on none of them"
                              : "every coordinate is cyclic: V depends on none of them";
    return false;
  }
  double v0 = m.potential_energy(0.0, x.data(), p.parameters.data());
  for (const auto& d : directions) {
    std::vector<double> changes;
    for (double radius : probe_radii()) {
      std::vector<double> y = probed(m, x, d, radius);
      changes.push_back(m.potential_energy(0.0, y.data(), p.parameters.data()) - v0);
    }
    PowerLaw law = leading_power_law(changes);
    if (law.found && law.sign > 0) continue;
    std::string along;
    for (std::size_t i = 0; i < n; ++i)
      if (d[i] != 0) along += fmt::format("{}{} {:+.3g}", along.empty() ? "" : ", ", m.coordinate_names[i], d[i]);
    where = law.found ? fmt::format("V decreases along ({}): as the {:.2g}th power of the distance, from {:.0e} out to {}",
                                    along, law.exponent, law.from,
                                    std::isfinite(law.extent) ? fmt::format("{:.0e}", law.extent) : std::string("1e+40 and beyond"))
                      : fmt::format("V changes by no steady power of the distance along ({}) from 1e-40 to 1e+40", along);
    return false;
  }
  return true;
}

// The size of a perturbation of each state: 1/100 of the length over which the rhs keeps, along
// it, the law it follows at the equilibrium (local_power_law.hpp), in whatever units the state is
// written; 1e-3 of a unit where it keeps it throughout (linear along it, or one power law at every
// size, as x'' = −x³). A velocity without a length of its own moves by its coordinate's size times
// the system's rate ρ (an oscillator of frequency ρ has that amplitude in its velocity); comparing
// velocities with displacements directly had called an undamped 22 Hz oscillator unstable.
std::vector<double> perturbation_sizes(const eomgen_model_abi& m, const std::vector<double>& x,
                                       const std::vector<double>& lengths, double rate) {
  std::size_t nq = m.num_coordinates, nv = m.num_velocities;
  std::vector<double> size(m.num_states);
  for (std::size_t k = 0; k < nq; ++k)
    size[k] = std::isfinite(lengths[k]) ? 1e-2 * lengths[k] : 1e-3 * std::max(1.0, std::abs(x[k]));
  double smallest = nq > 0 ? *std::min_element(size.begin(), size.begin() + long(nq)) : 1e-3;
  for (std::size_t k = nq; k < m.num_states; ++k) {
    double paired = nq == nv ? size[k - nq] : smallest;
    size[k] = std::min(rate * paired, 1e-2 * lengths[k]);
  }
  return size;
}

// Pseudo-velocities and a free joint's velocities are not the rates of single coordinates, and their
// units differ: a Chaplygin sleigh's forward speed v in m/s beside its turning rate w in rad/s.
// Pushes of 1e-3 of each weighed them in those units: with the centre a = 2e5 m ahead of the edge a
// push of w turned into a forward speed about a w, 2e5 times v's push, and the sleigh at rest was
// called unstable, where with a = 0.2 m it was stable. Each push is cut to the kinetic energy
// ½ M_kk s_k² of the smallest, so that none carries more energy than another in any units.
// Says whether it cut any.
bool equal_energy_pushes(const Problem& p, const std::vector<double>& x, std::vector<double>& size) {
  const eomgen_model_abi& m = *p.model;
  std::size_t nq = m.num_coordinates, nv = m.num_velocities;
  if (nq == nv || has_multipliers(m) || !m.mass_matrix) return false;
  std::vector<double> M(nv * nv);
  m.mass_matrix(0.0, x.data(), p.parameters.data(), M.data());
  double least = INFINITY;
  for (std::size_t k = 0; k < nv; ++k) {
    double energy = M[k * nv + k] * size[nq + k] * size[nq + k];
    if (!(M[k * nv + k] > 0) || !std::isfinite(energy)) return false;
    least = std::min(least, energy);
  }
  bool cut = false;
  for (std::size_t k = 0; k < nv; ++k) {
    double equal = std::sqrt(least / M[k * nv + k]);
    if (equal < size[nq + k]) size[nq + k] = equal, cut = true;
  }
  return cut;
}

// The push of coordinate i's own velocity at its own rate, in the units of that velocity: √(K_ii/M_ii)
// times its push on Lagrange II; on a first-order form q' = C s, s' = A_sq q + … (Appell, Hamilton,
// every coordinate in the reduced state), the velocity s_i of an oscillation of q_i alone, at
// ω² = −C_ii (A_sq)_ii: its push times √(−(A_sq)_ii / C_ii) (Hamilton's p_i: M ω times it). NaN where
// the coordinate has no restoring rate of its own.
double own_rate_push(const eomgen_model_abi& m, const StabilityReport& r, std::size_t i, double push) {
  long n = long(m.num_coordinates), k = long(i);
  if (r.M.rows() == n && r.K.rows() == n) {
    double stiffness = r.K(k, k), mass = r.M(k, k);
    return stiffness > 0 && mass > 0 ? push * std::sqrt(stiffness / mass) : NAN;
  }
  if (r.A.rows() != 2 * n) return NAN;
  double carries = r.A(k, n + k), restores = r.A(n + k, k);
  return carries * restores < 0 ? push * std::sqrt(-restores / carries) : NAN;
}

// A velocity's push at the system's (fastest) rate is, for a slow coordinate, a swing far beyond its
// own push: beside a stiff spring of 1e4 N/m a pendulum's der(theta) was pushed by 1 rad/s, a swing of
// a radian. Where the runs are measured in the linearization's energy (K positive definite), a
// velocity's push is at most its coordinate's at that coordinate's own rate, the two of one energy.
// Says whether it cut any.
bool own_rate_pushes(const eomgen_model_abi& m, const StabilityReport& r, std::vector<double>& size) {
  std::size_t n = m.num_coordinates;
  bool cut = false;
  if (m.num_velocities != n || has_multipliers(m)) return cut;
  for (std::size_t i = 0; i < n; ++i) {
    if (m.is_cyclic[i]) continue;
    double own = own_rate_push(m, r, i, size[i]);
    if (std::isfinite(own) && own > 0 && own < size[n + i]) size[n + i] = own, cut = true;
  }
  return cut;
}

// The runs' rate (it sizes the velocities' pushes) and length, from the eigenvalues that count: the
// fastest is the rate; the length is 200 periods of the slowest oscillation, or 200 time constants of
// the slowest rate when nothing oscillates.
struct RunScale {
  double rate = 0, horizon = 0;
  std::string span;  // what the length is, for the report
};

// Where every eigenvalue that counts is within rounding of zero (a free body at rest, x'' = −x³), none
// sets a time scale: the rate is that of the forces a displacement meets, √(max_j |Δq''_j| / s_j) over
// the coordinates' pushes s (√k s for x'' = −k x³), against 200/rate; where no force meets one (a
// free body), 1 against 1000, so that a velocity's push drifts its coordinate by 1000 times its size.
// A run of 100 s at 0.01 1/s had drifted it by once its size and called a free body at rest stable.
double restoring_rate(const Problem& p, const std::vector<double>& x, const std::vector<double>& size) {
  const eomgen_model_abi& m = *p.model;
  std::size_t n = m.num_coordinates;
  if (has_pseudo_velocities(m) || has_multipliers(m) || m.num_velocities != n) return 0;
  std::vector<double> at_x(m.num_states), moved(m.num_states);
  m.rhs(0.0, x.data(), p.held_inputs(), p.parameters.data(), at_x.data());
  double largest = 0;
  for (int i : reduced_state(m)) {
    if (std::size_t(i) >= n) continue;
    std::vector<double> y = x;
    y[std::size_t(i)] += size[std::size_t(i)];
    m.rhs(0.0, y.data(), p.held_inputs(), p.parameters.data(), moved.data());
    for (std::size_t j = 0; j < n; ++j)
      if (size[j] > 0) largest = std::max(largest, std::abs(moved[n + j] - at_x[n + j]) / size[j]);
  }
  return std::isfinite(largest) ? std::sqrt(largest) : 0;
}

// Where neither eigenvalues nor forces set a time scale, a steady motion sets its own: the fastest
// of its angles' speeds (rad/s in any units) and its other coordinates' speeds over the lengths over
// which the rhs keeps its law along them. A rolling ball spun at 2e6 rad/s, run for 1000 s at a rate
// of 1 1/s, had broken off at CVODE's step limit after 0.29 s and been called unstable, as had a
// knife edge turning at 5e11 rad/s; at 2 rad/s both had been stable.
double steady_motion_rate(const Problem& p, const std::vector<double>& x, const std::vector<double>& lengths) {
  const eomgen_model_abi& m = *p.model;
  std::vector<double> xdot(m.num_states);
  m.rhs(0.0, x.data(), p.held_inputs(), p.parameters.data(), xdot.data());
  double rate = 0;
  for (std::size_t k = 0; k < m.num_coordinates; ++k) {
    double speed = std::abs(xdot[k]);
    if (m.is_angle[k]) rate = std::max(rate, speed);
    else if (std::isfinite(lengths[k]) && lengths[k] > 0) rate = std::max(rate, speed / lengths[k]);
  }
  return std::isfinite(rate) ? rate : 0;
}

RunScale run_scale(const Problem& p, const std::vector<double>& x, const StabilityReport& r,
                   const std::vector<double>& lengths) {
  RunScale scale;
  double slowest = INFINITY, smallest = INFINITY;
  for (auto l : r.counted_eigenvalues) {
    if (std::abs(l) > r.axis_tolerance) scale.rate = std::max(scale.rate, std::abs(l));
    if (std::abs(l.imag()) > r.axis_tolerance) slowest = std::min(slowest, std::abs(l.imag()));
    if (std::abs(l) > r.axis_tolerance) smallest = std::min(smallest, std::abs(l));
  }
  if (std::isfinite(slowest)) {
    scale.horizon = 200 * 2 * M_PI / slowest;
    scale.span = "about 200 periods of the slowest mode";
  } else if (std::isfinite(smallest)) {
    scale.horizon = 200 / smallest;
    scale.span = "200 time constants of the slowest mode";
  } else if (double rate = restoring_rate(p, x, perturbation_sizes(*p.model, x, lengths, 0)); rate > 0) {
    scale.rate = rate;
    scale.horizon = 200 / rate;
    scale.span = "no eigenvalue sets a time scale: 200 over the rate of the forces the pushes meet";
  } else if (double steady = steady_motion_rate(p, x, lengths); steady > 0) {
    scale.rate = steady;
    scale.horizon = 200 / steady;
    scale.span = "no eigenvalue or force sets a time scale: 200 over the steady motion's rate, its angles' speed or "
                 "its coordinates' over their lengths";
  } else {
    scale.rate = 1;
    scale.horizon = 1000;
    scale.span = "no eigenvalue or force sets a time scale: 1000 times a push's own, its coordinate's size over its "
                 "velocity's";
  }
  return scale;
}

std::string sizes_text(const eomgen_model_abi& m, const std::vector<double>& size) {
  std::string text;
  std::vector<int> shown = reduced_state(m);
  for (std::size_t k = 0; k < shown.size() && k < 6; ++k)
    text += fmt::format("{}{} ±{:.2g}", k == 0 ? "" : ", ", m.state_names[shown[k]], size[std::size_t(shown[k])]);
  return shown.size() > 6 ? text + ", …" : text;
}

// A perturbed run that broke off (CVODE's step limit, a failed convergence) before its deviation grew
// a hundredfold: neither growth nor the run's whole length. Two undamped oscillators at 1 and 1e6
// rad/s, their runs 200 slow periods long, had stopped at CVODE's step limit after 0.02 s and been
// called unstable.
struct BrokenRun {
  std::string start, failure;
  double time = 0, grown = 0;
};

std::string perturbed_runs(const Problem& p, const std::vector<double>& x, const StabilityReport& r, std::string& verdict,
                           const std::function<void(long, long)>& progress) {
  const eomgen_model_abi& m = *p.model;
  std::vector<double> lengths = nonlinearity_lengths(p, x);
  RunScale scale = run_scale(p, x, r, lengths);
  double rate = scale.rate, horizon = scale.horizon;
  SimulationSettings s;
  s.t_end = horizon;
  s.dt_out = horizon / 2000;
  s.rtol = 1e-10;
  s.max_steps = 1'000'000;
  // 50000 evaluations per slow period: a run that needs more follows a fast undamped mode step by
  // step (a pendulum beside a spring of 1e6 N/m: 2e5 fast periods in 200 slow ones, 17 minutes for
  // its eight runs) and breaks off as undecided instead
  s.max_rhs_evaluations = 10'000'000;
  // constraints kept by projection alone: Baumgarte's gains are the model's rates in 1/s (10 unless
  // set), and against a Cartesian pendulum's period of 2e12 s they made the runs so stiff that
  // BDF gave up, and the hanging pendulum was called unstable
  s.baumgarte = false;
  std::vector<double> size = perturbation_sizes(m, x, lengths, rate);
  bool equal_energies = equal_energy_pushes(p, x, size);
  DeviationNorm deviation(m, r, x, size, p.parameters.data());
  // in the linearization's energy, which no push's size enters (measured per state, a velocity's
  // push cut at a rate of rounding, a singular Euler angle's, made any motion of it a "growth")
  bool own_rates = deviation.kind() == DeviationNorm::Kind::linear_energy && own_rate_pushes(m, r, size);
  // each state's absolute tolerance 1e-12 of its push: the runs resolve their growth in any units
  s.atol = 1e-12 * *std::max_element(size.begin(), size.end());
  for (double push : size) s.state_atol.push_back(1e-12 * push);
  double worst = 0, when = 0;
  std::string worst_start;
  std::optional<BrokenRun> broken;
  // each coordinate that is not cyclic, and each velocity, pushed both ways
  std::vector<int> pushed = reduced_state(m);
  long done = 0, total = 2 * long(pushed.size());
  for (int component : pushed) {
    auto i = static_cast<std::size_t>(component);
    for (double sign : {1.0, -1.0}) {
      std::vector<double> y = x;
      y[i] += sign * size[i];
      SimulationResult run = simulate(p, y, s);
      double grown = 0, passed = 0, push = deviation(y);
      // the rows up to the break, the state where it broke off among them
      for (std::size_t k = 0; k < run.trajectory.times.size(); ++k) {
        double d = deviation(run.trajectory.states[k]) / push;
        if (d > grown || !std::isfinite(d)) grown = std::isfinite(d) ? d : INFINITY;
        if (d > 100 && passed == 0) passed = run.trajectory.times[k];
      }
      if (run.failed && grown > 100 && passed == 0) passed = run.failure_time;
      std::string start = fmt::format("{} {:+.1e}", m.state_names[i], y[i] - x[i]);
      if (run.failed && grown <= 100 && !broken) broken = BrokenRun{start, run.failure, run.failure_time, grown};
      // the time said is that of the run whose growth is said
      if (grown > worst) worst = grown, when = passed, worst_start = start;
      if (progress) progress(++done, total);
    }
  }
  if (worst > 100) {
    verdict = "unstable";
    return fmt::format("a perturbation of {} grew more than a hundredfold{} (by t = {:.4g} s of a {:.4g} s run): unstable",
                       worst_start,
                       !std::isfinite(worst) ? " (the run broke off)"
                                             : fmt::format(", to {:.3g} times its size{}", worst, deviation.measure()),
                       when, horizon);
  }
  if (broken) {
    verdict = "undecided";
    return fmt::format("the run from a perturbation of {} broke off at t = {:.4g} s of a {:.4g} s run, its deviation within "
                       "{:.3g} times its size{} up to there: the simulation decides nothing ({})",
                       broken->start, broken->time, horizon, broken->grown, deviation.measure(), broken->failure);
  }
  verdict = "stable";
  return fmt::format("perturbations of each coordinate and velocity by 1/100 of the length over which the rhs keeps "
                     "the law it follows at the equilibrium (a velocity's, at most its coordinate's times the system's "
                     "rate {:.3g} 1/s{}; {}) stayed within {:.3g} times their size{} over {:.4g} s ({}{}): stable as "
                     "far as a simulation can tell",
                     rate,
                     std::string(!own_rates ? "" : r.K.rows() > 0 ? ", or its own rate √(K_ii/M_ii) where that is slower"
                                                                : ", or its coordinate's own rate √(−(∂q_i'/∂s_i)(∂s_i'/∂q_i)) where that is slower") +
                         (equal_energies ? ", and at most the kinetic energy of the least of them" : ""),
                     sizes_text(m, size), worst, deviation.measure(), horizon, scale.span,
                     r.symmetries.empty() ? "" : "; orientations measured modulo the turns the equations do not see");
}

}  // namespace

CriticalCase check_critical_case(const Problem& p, const std::vector<double>& x, const StabilityReport& r,
                                 const std::function<void(long, long)>& progress) {
  CriticalCase c;
  // the eigenvalues that count for the verdict: a cyclic momentum's or a quaternion length's zero does not
  c.critical = !r.eigenvalues.empty() && std::abs(r.stability_degree) <= r.axis_tolerance;
  if (!c.critical) return c;
  const eomgen_model_abi& m = *p.model;
  bool at_rest = true;
  for (std::size_t i = m.num_coordinates; i < m.num_states; ++i) at_rest = at_rest && x[i] == 0;
  bool unforced = true;
  for (double u : p.inputs) unforced = unforced && u == 0;
  std::string where;
  if (has_multipliers(m)) {
    // V's minimum would be searched off the constraint manifold, where it means nothing
    c.energy = "not applicable: the coordinates of a Lagrange I model are not independent";
  } else if (!m.conserves_energy_without_inputs || !unforced || !at_rest) {
    c.energy = "not applicable: Lagrange–Dirichlet needs a conservative system at rest";
  } else if (strict_minimum_of_potential(p, x, r.symmetries, where)) {
    c.energy = r.symmetries.empty()
                   ? "T + V is a Lyapunov function: V has a strict minimum at the equilibrium and T is positive definite, "
                     "so the equilibrium is stable (Lagrange–Dirichlet)"
                   : "T + V is a Lyapunov function modulo the turns the equations do not see: V has a strict minimum at "
                     "the equilibrium but along them, where it is constant, and T is positive definite, so the "
                     "equilibrium is stable with respect to all but those turns (Lagrange–Dirichlet)";
    c.nonlinear_verdict = "stable";
    return c;
  } else {
    c.energy = "decides nothing: " + where;
  }
  c.simulation = perturbed_runs(p, x, r, c.nonlinear_verdict, progress);
  return c;
}

}  // namespace eomgen::runtime
