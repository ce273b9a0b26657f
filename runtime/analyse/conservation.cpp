#include "analyse/conservation.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "analyse/state_tolerances.hpp"

namespace eomgen::runtime {

std::vector<FirstIntegralDrift> first_integral_drift(const eomgen_model_abi& m, const RunSummary& run) {
  std::vector<FirstIntegralDrift> drift;
  if (run.first_integrals.size() != m.num_first_integrals) return drift;
  for (std::size_t i = 0; i < m.num_first_integrals; ++i) {
    FirstIntegralDrift d;
    d.name = m.first_integral_names[i];
    d.initial = run.first_integrals[i];
    d.largest_change = run.largest_integral_changes[i];
    d.relative_change = d.initial != 0 ? d.largest_change / std::abs(d.initial) : NAN;
    drift.push_back(d);
  }
  return drift;
}

namespace {

double energy(const Problem& p, double t, const std::vector<double>& x) {
  return p.model->kinetic_energy(t, x.data(), p.parameters.data()) + p.model->potential_energy(t, x.data(), p.parameters.data());
}

// dE/dt along the flow at (t, x) and the sum of the sizes of its terms, each state differentiated
// on its own size (1e-3 of a unit had been a step of 1e3 amplitudes for a well 1e-12 m wide, whose
// quartic energy it then took for one that changes)
std::pair<double, double> energy_rate(const Problem& p, double t, const std::vector<double>& x, const std::vector<double>& sizes) {
  const eomgen_model_abi& m = *p.model;
  std::vector<double> xdot(m.num_states), zero_inputs(m.num_inputs, 0.0);
  m.rhs(t, x.data(), zero_inputs.empty() ? nullptr : zero_inputs.data(), p.parameters.data(), xdot.data());
  double rate = 0, size = 0;
  for (std::size_t i = 0; i < m.num_states; ++i) {
    double h = 1e-6 * std::max(std::abs(x[i]), sizes[i] > 0 ? sizes[i] : 1e-3);
    std::vector<double> up = x, down = x;
    up[i] += h, down[i] -= h;
    double term = (energy(p, t, up) - energy(p, t, down)) / (2 * h) * xdot[i];
    rate += term, size += std::abs(term);
  }
  double ht = 1e-6 * std::max(std::abs(t), 1e-3), explicit_rate = (energy(p, t + ht, x) - energy(p, t - ht, x)) / (2 * ht);
  return {rate + explicit_rate, size + std::abs(explicit_rate)};
}

}  // namespace

bool energy_conserved_at(const Problem& problem, double t, const std::vector<double>& x) {
  const eomgen_model_abi& m = *problem.model;
  if (m.conserves_energy_without_inputs) return true;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> uniform(-1, 1);
  std::vector<double> sizes = state_sizes(problem, x);
  for (int probe = 0; probe < 4; ++probe) {
    std::vector<double> y = x;
    if (probe > 0)  // random velocities of the state's own size (analyse/state_tolerances.hpp), or 1
      for (std::size_t i = m.num_coordinates; i < m.num_states; ++i) y[i] = uniform(random) * (sizes[i] > 0 ? sizes[i] : 1.0);
    auto [rate, size] = energy_rate(problem, t, y, sizes);
    if (!std::isfinite(rate) || std::abs(rate) > 1e-6 * size) return false;
  }
  return true;
}

}  // namespace eomgen::runtime
