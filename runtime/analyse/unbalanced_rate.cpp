#include "analyse/unbalanced_rate.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "analyse/first_order_form.hpp"
#include "integrate/quaternion_norms.hpp"

namespace eomgen::runtime {

namespace {

// x' at rest in configuration q (velocities zero)
std::vector<double> rates_at_rest(const Problem& p, std::vector<double> x) {
  const eomgen_model_abi& m = *p.model;
  std::fill(x.begin() + std::ptrdiff_t(m.num_coordinates), x.end(), 0.0);
  std::vector<double> rates(m.num_states);
  m.rhs(0.0, x.data(), p.held_inputs(), p.parameters.data(), rates.data());
  return rates;
}

// f of M q'' = f at rest in configuration q
std::vector<double> forces_at_rest(const Problem& p, std::vector<double> x) {
  const eomgen_model_abi& m = *p.model;
  std::fill(x.begin() + std::ptrdiff_t(m.num_coordinates), x.end(), 0.0);
  std::vector<double> f(m.num_states - m.num_coordinates);
  m.forcing(0.0, x.data(), p.held_inputs(), p.parameters.data(), f.data());
  return f;
}

// the row (from `first`, `size` of them) of `values` that is one number in every configuration,
// beyond 1e-9 of the largest seen
std::optional<std::size_t> constant_row(const std::vector<std::vector<double>>& values, std::size_t first, std::size_t size) {
  double largest = 0;
  for (const std::vector<double>& r : values)
    for (std::size_t v = 0; v < size; ++v) largest = std::max(largest, std::abs(r[first + v]));
  for (std::size_t v = 0; v < size; ++v) {
    double at_start = values[0][first + v];
    bool constant = std::isfinite(at_start) && std::abs(at_start) > 1e-9 * largest;
    for (const std::vector<double>& r : values)
      constant = constant && std::abs(r[first + v] - at_start) <= 1e-9 * std::abs(at_start);
    if (constant) return v;
  }
  return std::nullopt;
}

// start's configuration moved at random: each coordinate by up to `reach` times max(1, |q|),
// quaternions normalized
std::vector<double> moved_at_random(const eomgen_model_abi& m, std::vector<double> x, double reach, std::mt19937& random) {
  std::uniform_real_distribution<double> step(-1, 1);
  for (std::size_t i = 0; i < m.num_coordinates; ++i) x[i] += reach * step(random) * std::max(1.0, std::abs(x[i]));
  normalize_quaternions(m, x.data());
  return x;
}

}  // namespace

std::optional<UnbalancedRate> unbalanced_rate(const Problem& problem, const std::vector<double>& start) {
  const eomgen_model_abi& m = *problem.model;
  if (m.num_constraints) return std::nullopt;
  std::size_t n = m.num_coordinates, k = m.num_states - n;
  constexpr int configurations = 8;
  std::vector<std::vector<double>> configurations_tried{start}, rates, forces;
  std::mt19937 random(7);
  // moved by up to 1, 100, … 1e12 of their units: a spring of 1e-12 N/m under gravity changes the
  // rate by 1e-12 of it within one unit, and by a tenth within 1e12
  for (double reach = 1; configurations_tried.size() < configurations; reach *= 100)
    configurations_tried.push_back(moved_at_random(m, start, reach, random));
  for (const std::vector<double>& x : configurations_tried)
    rates.push_back(rates_at_rest(problem, x)), forces.push_back(forces_at_rest(problem, x));
  if (std::optional<std::size_t> v = constant_row(rates, n, k)) return UnbalancedRate{*v, rates[0][n + *v], configurations};
  if (std::optional<std::size_t> v = constant_row(forces, 0, k))
    return UnbalancedRate{*v, forces[0][*v], configurations, true};
  return std::nullopt;
}

}  // namespace eomgen::runtime
