// Integrates the generated pendulum with classical RK4 and checks that the
// total energy T + V stays within 1e-9 of its start over 10 s.
#include <cmath>
#include <cstdio>

#include "swing.hpp"

namespace model = eomgen::models::swing;

int main() {
  model::Parameters<double> parameters;
  auto p = parameters.values();
  auto x = model::default_state;
  auto energy = [&](const std::array<double, model::num_states>& s) {
    return model::kinetic_energy(0.0, s.data(), p.data()) + model::potential_energy(0.0, s.data(), p.data());
  };
  const double e0 = energy(x), h = 1e-3;
  double worst = 0;
  for (int step = 0; step < 10000; ++step) {
    std::array<double, model::num_states> k1, k2, k3, k4, y;
    double t = step * h;
    model::rhs(t, x.data(), nullptr, p.data(), k1.data());
    for (std::size_t i = 0; i < x.size(); ++i) y[i] = x[i] + h / 2 * k1[i];
    model::rhs(t + h / 2, y.data(), nullptr, p.data(), k2.data());
    for (std::size_t i = 0; i < x.size(); ++i) y[i] = x[i] + h / 2 * k2[i];
    model::rhs(t + h / 2, y.data(), nullptr, p.data(), k3.data());
    for (std::size_t i = 0; i < x.size(); ++i) y[i] = x[i] + h * k3[i];
    model::rhs(t + h, y.data(), nullptr, p.data(), k4.data());
    for (std::size_t i = 0; i < x.size(); ++i) x[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    worst = std::fmax(worst, std::fabs(energy(x) - e0) / std::fabs(e0));
  }
  std::printf("swing: relative energy drift %.3e over 10 s with RK4, h = %g\n", worst, h);
  return worst < 1e-9 ? 0 : 1;
}
