#include "analyse/local_power_law.hpp"

#include <algorithm>
#include <limits>

#include <Eigen/Dense>

#include "analyse/constrained_first_order.hpp"
#include "analyse/first_order_form.hpp"

namespace eomgen::runtime {

const std::vector<double>& probe_radii() {
  static const std::vector<double> radii = [] {
    std::vector<double> r;
    for (int k = -40; k <= 40; ++k) r.push_back(std::pow(10.0, k));
    return r;
  }();
  return radii;
}

namespace {

constexpr double exponent_tolerance = 0.1;

double local_exponent(double lower, double upper) { return std::log10(std::abs(upper / lower)); }

bool usable(double change) { return std::isfinite(change) && change != 0; }

// Each rate's rounding at x: a rate is a sum of terms that cancel at an equilibrium away from the
// origin (a hanging top's gravity moments, each about m g ℓ), and a change below ε times their size
// shows the order of the sum, not the rate's law. Their size, Σ_j |∂f_r/∂x_j| |x_j| + |f_r|, from
// jacobian_state, times 64 for the sum's many terms. A law read below it had given the hanging top's
// spin a perturbation of 1e-10: its row grew as 0.014 wz² up to wz = 1e-8, and as the 0.085 wz² of
// its equations beyond, once the terms added before the cancellation came out of the rounding.
std::vector<double> rounding_floors(const Problem& p, const std::vector<double>& x, const std::vector<double>& at_x) {
  const eomgen_model_abi& m = *p.model;
  Eigen::MatrixXd J = state_jacobian(p, 0.0, x);
  std::vector<double> floors(m.num_states);
  for (std::size_t r = 0; r < m.num_states; ++r) {
    double size = std::abs(at_x[r]);
    for (std::size_t j = 0; j < m.num_states; ++j) size += std::abs(J(long(r), long(j)) * x[j]);
    floors[r] = 64 * std::numeric_limits<double>::epsilon() * size;
  }
  return floors;
}

// Where a row's terms cancel for every r (a free body's ω² terms in a row that stays at rest), its
// change is their rounding: a unit in the last place of terms that grow as a power of r, which steps
// by powers of two and, three radii in a row, may pass for a law (one ending at 1e-37 rad/s had sized
// a push at that). It hits exactly 0 again and again between nonzero changes, where a smooth change
// crosses zero once at most in a decade. From three such zeros on, the changes up to the last of them
// are taken for rounding.
std::size_t rounded_up_to(const std::vector<double>& changes, std::size_t end) {
  std::size_t first_nonzero = end, last_nonzero = 0;
  for (std::size_t k = 0; k < end; ++k)
    if (changes[k] != 0) first_nonzero = std::min(first_nonzero, k), last_nonzero = k;
  std::size_t zeros = 0, last_zero = 0;
  for (std::size_t k = first_nonzero; k < last_nonzero; ++k)
    if (changes[k] == 0) ++zeros, last_zero = k;
  return zeros >= 3 ? last_zero + 1 : 0;
}

}  // namespace

PowerLaw leading_power_law(const std::vector<double>& changes) {
  PowerLaw law;
  std::size_t end = 0;
  while (end < changes.size() && std::isfinite(changes[end])) ++end;
  for (std::size_t k = rounded_up_to(changes, end); k + 2 < end; ++k) {
    double a = changes[k], b = changes[k + 1], c = changes[k + 2];
    if (!usable(a) || !usable(b) || !usable(c) || (a > 0) != (b > 0) || (b > 0) != (c > 0)) continue;
    double first = local_exponent(a, b), second = local_exponent(b, c);
    if (first < 0.5 || std::abs(first - second) > exponent_tolerance) continue;
    law.found = true;
    law.exponent = (first + second) / 2;
    law.sign = a > 0 ? 1 : -1;
    law.from = probe_radii()[k];
    law.change = a;
    std::size_t last = k + 2;
    while (last + 1 < end && usable(changes[last + 1]) && (changes[last + 1] > 0) == (a > 0) &&
           std::abs(local_exponent(changes[last], changes[last + 1]) - law.exponent) <= exponent_tolerance)
      ++last;
    law.extent = last + 1 == changes.size() ? INFINITY : probe_radii()[last];
    return law;
  }
  return law;
}

std::vector<double> nonlinearity_lengths(const Problem& p, const std::vector<double>& x) {
  const eomgen_model_abi& m = *p.model;
  const std::vector<double>& radii = probe_radii();
  std::vector<double> at_x(m.num_states), moved(m.num_states), lengths(m.num_states, INFINITY);
  // a Lagrange I model's rates without Baumgarte's terms, whose gains are the model's rates in 1/s
  // and not the system's: at a time scale of 1e12 s they broke a Cartesian pendulum's law at 1e-9
  // of its rod's length instead of 0.1
  auto rate = [&](const std::vector<double>& y, std::vector<double>& out) {
    if (m.num_multipliers) Eigen::VectorXd::Map(out.data(), long(out.size())) = unstabilized_rate(p, y);
    else m.rhs(0.0, y.data(), p.held_inputs(), p.parameters.data(), out.data());
  };
  rate(x, at_x);
  std::vector<double> floors = rounding_floors(p, x, at_x);
  for (std::size_t component = 0; component < m.num_states; ++component) {
    std::vector<std::vector<double>> changes(m.num_states, std::vector<double>(radii.size(), NAN));
    for (std::size_t k = 0; k < radii.size(); ++k) {
      std::vector<double> y = x;
      y[component] += radii[k];
      rate(y, moved);
      for (std::size_t row = 0; row < m.num_states; ++row) {
        double change = moved[row] - at_x[row];
        changes[row][k] = std::abs(change) <= floors[row] ? 0.0 : change;
      }
    }
    for (const auto& row : changes) {
      PowerLaw law = leading_power_law(row);
      if (law.found) lengths[component] = std::min(lengths[component], law.extent);
    }
  }
  return lengths;
}

}  // namespace eomgen::runtime
