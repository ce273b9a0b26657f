#include "analyse/critical_case.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include <fmt/format.h>

#include "analyse/constrained_first_order.hpp"
#include "analyse/first_order_form.hpp"

namespace eomgen::runtime {

namespace {


// V(q + δ) − V(q) > 0 beyond V's rounding along every coordinate direction and random ones, at
// two radii; with no coordinate but cyclic ones there is no minimum to speak of
bool strict_minimum_of_potential(const Problem& p, const std::vector<double>& x, std::string& where) {
  const eomgen_model_abi& m = *p.model;
  std::size_t n = m.num_coordinates;
  if (std::count(m.is_cyclic, m.is_cyclic + n, false) == 0) {
    where = "every coordinate is cyclic: V depends on none of them";
    return false;
  }
  double v0 = m.potential_energy(0.0, x.data(), p.parameters.data());
  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  std::vector<std::vector<double>> directions;
  for (std::size_t i = 0; i < n; ++i) {
    if (m.is_cyclic[i]) continue;
    std::vector<double> d(n, 0.0);
    d[i] = 1;
    directions.push_back(d);
    d[i] = -1;
    directions.push_back(d);
  }
  for (int k = 0; k < 20; ++k) {
    std::vector<double> d(n, 0.0);
    double size = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (!m.is_cyclic[i]) d[i] = normal(random), size += d[i] * d[i];
    if (size > 0) {
      for (double& v : d) v /= std::sqrt(size);
      directions.push_back(d);
    }
  }
  for (double radius : {1e-2, 1e-3})
    for (const auto& d : directions) {
      std::vector<double> y = x;
      for (std::size_t i = 0; i < n; ++i) y[i] += radius * d[i];
      double v1 = m.potential_energy(0.0, y.data(), p.parameters.data()), dv = v1 - v0;
      if (!(dv > 1e-14 * std::max(std::abs(v0), std::abs(v1)))) {
        std::string moved;
        for (std::size_t i = 0; i < n; ++i)
          if (d[i] != 0) moved += fmt::format("{}{} {:+.3g}", moved.empty() ? "" : ", ", m.coordinate_names[i], radius * d[i]);
        where = fmt::format("V does not increase when moving {} (ΔV = {:.3g})", moved, dv);
        return false;
      }
    }
  return true;
}

// The size of a perturbation of the reduced state: the coordinates' deviations against the
// perturbation's size ε and the velocities' against ε times the system's rate ρ (for an
// oscillator of frequency ρ, its amplitude whether it sits in the position or the velocity);
// comparing velocities with displacements directly called an undamped 22 Hz oscillator unstable.
struct PerturbationNorm {
  const eomgen_model_abi& m;
  double epsilon, rate;
  double operator()(const std::vector<double>& y, const std::vector<double>& x) const {
    double d = 0;
    for (int i : reduced_state(m)) {
      auto k = static_cast<std::size_t>(i);
      double unit = k < m.num_coordinates ? epsilon : epsilon * rate;
      d = std::max(d, std::abs(y[k] - x[k]) / unit);
    }
    return d;
  }
};

// The run's length: 200 periods of the slowest oscillation, or 200 time constants of the
// slowest rate when nothing oscillates; only when every eigenvalue is zero is there no scale
double horizon_of(const StabilityReport& r, double rate) {
  double slowest = INFINITY, smallest = INFINITY;
  for (auto l : r.eigenvalues) {
    if (std::abs(l.imag()) > r.axis_tolerance) slowest = std::min(slowest, std::abs(l.imag()));
    if (std::abs(l) > r.axis_tolerance) smallest = std::min(smallest, std::abs(l));
  }
  if (std::isfinite(slowest)) return 200 * 2 * M_PI / slowest;
  if (std::isfinite(smallest)) return 200 / smallest;
  return rate > 0 ? 200 / rate : 100.0;
}

std::string perturbed_runs(const Problem& p, const std::vector<double>& x, const StabilityReport& r, std::string& verdict) {
  const eomgen_model_abi& m = *p.model;
  double rate = 0;
  for (auto l : r.eigenvalues) rate = std::max(rate, std::abs(l));
  double horizon = horizon_of(r, rate);
  if (rate == 0) rate = 1 / horizon;
  SimulationSettings s;
  s.t_end = horizon;
  s.dt_out = horizon / 2000;
  s.rtol = 1e-10;
  s.max_steps = 1'000'000;
  double worst = 0, when = 0;
  std::string worst_start;
  // each coordinate that is not cyclic, and each velocity, pushed both ways
  for (int component : reduced_state(m)) {
    auto i = static_cast<std::size_t>(component);
    for (double sign : {1.0, -1.0}) {
      std::vector<double> y = x;
      double epsilon = 1e-3 * (i < m.num_coordinates ? std::max(1.0, std::abs(x[i])) : 1.0);
      PerturbationNorm norm{m, epsilon, rate};
      y[i] += sign * (i < m.num_coordinates ? epsilon : epsilon * rate);
      s.atol = 1e-12 * epsilon * std::min(1.0, rate);
      SimulationResult run = simulate(p, y, s);
      double grown = run.failed ? INFINITY : 0;
      for (std::size_t k = 0; k < run.trajectory.times.size(); ++k) {
        double d = norm(run.trajectory.states[k], x);
        if (d > grown || !std::isfinite(d)) grown = std::isfinite(d) ? d : INFINITY;
        if (d > 100 && when == 0) when = run.trajectory.times[k];
      }
      if (run.failed && when == 0) when = run.failure_time;
      if (grown > worst)
        worst = grown, worst_start = fmt::format("{} {:+.1e}", m.state_names[i], y[i] - x[i]);
    }
  }
  if (worst > 100) {
    verdict = "unstable";
    return fmt::format("a perturbation of {} grew more than a hundredfold{} (by t = {:.4g} s of a {:.4g} s run): unstable",
                       worst_start, std::isfinite(worst) ? fmt::format(", to {:.3g} times its size", worst) : " (the run broke off)",
                       when, horizon);
  }
  verdict = "stable";
  return fmt::format("perturbations of ±1e-3 in each coordinate and velocity (the velocities' times the system's rate "
                     "{:.3g} 1/s) stayed within {:.3g} times their size over {:.4g} s (about 200 periods of the slowest "
                     "mode): stable as far as a simulation can tell",
                     rate, worst, horizon);
}

}  // namespace

CriticalCase check_critical_case(const Problem& p, const std::vector<double>& x, const StabilityReport& r) {
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
  } else if (!m.conserves_energy_without_inputs || !unforced || !at_rest || has_pseudo_velocities(m)) {
    c.energy = "not applicable: Lagrange–Dirichlet needs a conservative system at rest";
  } else if (strict_minimum_of_potential(p, x, where)) {
    c.energy = "T + V is a Lyapunov function: V has a strict minimum at the equilibrium and T is positive definite, "
               "so the equilibrium is stable (Lagrange–Dirichlet)";
    c.nonlinear_verdict = "stable";
    return c;
  } else {
    c.energy = "decides nothing: " + where;
  }
  c.simulation = perturbed_runs(p, x, r, c.nonlinear_verdict);
  return c;
}

}  // namespace eomgen::runtime
