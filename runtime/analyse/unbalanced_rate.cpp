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
  std::vector<std::vector<double>> rates{rates_at_rest(problem, start)};
  std::mt19937 random(7);
  // moved by up to 1, 100, … 1e12 of their units: a spring of 1e-12 N/m under gravity changes the
  // rate by 1e-12 of it within one unit, and by a tenth within 1e12
  for (double reach = 1; rates.size() < configurations; reach *= 100)
    rates.push_back(rates_at_rest(problem, moved_at_random(m, start, reach, random)));
  double largest = 0;
  for (const std::vector<double>& r : rates)
    for (std::size_t v = 0; v < k; ++v) largest = std::max(largest, std::abs(r[n + v]));
  for (std::size_t v = 0; v < k; ++v) {
    double first = rates[0][n + v];
    bool constant = std::isfinite(first) && std::abs(first) > 1e-9 * largest;
    for (const std::vector<double>& r : rates)
      constant = constant && std::abs(r[n + v] - first) <= 1e-9 * std::abs(first);
    if (constant) return UnbalancedRate{v, first, configurations};
  }
  return std::nullopt;
}

}  // namespace eomgen::runtime
