// The reference integrator against closed-form solutions: the large-amplitude
// pendulum (Jacobi's elliptic functions) and the torque-free asymmetric rigid body
// (Euler's equations, Jacobi's solution), both to 1e-12 relative, with the
// integrator's own error estimate checked to be an honest bound.
#include <gtest/gtest.h>

#include <cmath>

#include "analyse/accuracy.hpp"
#include "reference/reference_solution.hpp"

#include "../generated/free_rigid_body.hpp"
#include "../generated/pendulum.hpp"

namespace eomgen::test {
namespace {

// sn, cn, dn(u | m) by the arithmetic–geometric mean (Abramowitz & Stegun 16.4), in long double
struct Jacobi {
  long double sn, cn, dn;
};
Jacobi jacobi(long double u, long double m) {
  long double a[40], c[40], b = std::sqrt(1 - m);
  a[0] = 1;
  c[0] = std::sqrt(m);
  int n = 0;
  while (std::abs(c[n]) > 1e-21L && n < 38) {
    a[n + 1] = (a[n] + b) / 2;
    c[n + 1] = (a[n] - b) / 2;
    b = std::sqrt(a[n] * b);
    ++n;
  }
  long double phi = std::ldexp(a[n] * u, n), previous = phi;
  for (int k = n; k > 0; --k) {
    previous = phi;
    phi = (phi + std::asin(c[k] / a[k] * std::sin(phi))) / 2;
  }
  return {std::sin(phi), std::cos(phi), std::cos(phi) / std::cos(previous - phi)};
}

// K(m) = π / (2 AGM(1, sqrt(1 − m)))
long double complete_elliptic(long double m) {
  long double a = 1, b = std::sqrt(1 - m);
  for (int i = 0; i < 40 && std::abs(a - b) > 1e-21L; ++i) {
    long double next = (a + b) / 2;
    b = std::sqrt(a * b);
    a = next;
  }
  return 3.14159265358979323846264338327950288L / (2 * a);
}

template <class Rhs>
std::vector<std::vector<double>> reference_rows(Rhs rhs, std::size_t n, const std::vector<double>& x0,
                                                const std::vector<double>& times, double step) {
  std::vector<double> out(times.size() * n);
  long used = reference::integrate(rhs, n, 0.0, x0.data(), times.data(), times.size(), step, out.data());
  EXPECT_GT(used, 0);
  std::vector<std::vector<double>> rows;
  for (std::size_t k = 0; k < times.size(); ++k) rows.emplace_back(out.begin() + k * n, out.begin() + (k + 1) * n);
  return rows;
}

std::vector<double> output_times(double t_end, double dt) {
  std::vector<double> t;
  for (int k = 1; k * dt <= t_end + 1e-12; ++k) t.push_back(k * dt);
  return t;
}

TEST(Reference, LargeAmplitudePendulumMatchesJacobisSolution) {
  namespace m = eomgen::models::pendulum;
  using W = reference::Wide;
  std::vector<W> p;
  for (double v : m::default_parameters) p.push_back(W(v));  // m, l, g, d = 0
  auto rhs = [&](W t, const W* x, W* xdot) { m::rhs<W>(t, x, nullptr, p.data(), xdot); };
  double phi0 = 2.8, l = m::default_parameters[1], g = m::default_parameters[2];
  ASSERT_EQ(m::default_parameters[3], 0.0);
  std::vector<double> times = output_times(10, 0.05);
  auto coarse = reference_rows(rhs, 2, {phi0, 0}, times, 0.02);
  auto fine = reference_rows(rhs, 2, {phi0, 0}, times, 0.01);
  // sin(φ/2) = k cd(ω t | k²), k = sin(φ0/2), ω = sqrt(g/l); φ' from d/dt
  long double k = std::sin(phi0 / 2.0L), omega = std::sqrt(static_cast<long double>(g) / l);
  std::vector<std::vector<double>> exact;
  for (double t : times) {
    Jacobi j = jacobi(omega * t, k * k);
    long double cd = j.cn / j.dn, s = k * cd;
    long double phi = 2 * std::asin(s);
    // d(cd)/du = −(1 − m) sn / dn², so φ' = 2 k ω d(cd)/du / cos(φ/2)
    long double dphi = 2 * k * omega * (-(1 - k * k) * j.sn / (j.dn * j.dn)) / std::sqrt(1 - s * s);
    exact.push_back({static_cast<double>(phi), static_cast<double>(dphi)});
  }
  double error = runtime::trajectory_error(fine, exact), estimate = runtime::trajectory_error(coarse, fine);
  EXPECT_LT(error, 1e-12);
  EXPECT_LE(error, std::max(estimate, 2e-16) * 10) << "the estimate " << estimate << " must bound the error " << error;
  // the period: 4K/ω, and the closed form is checked at it too
  double period = static_cast<double>(4 * complete_elliptic(k * k) / omega);
  auto at_period = reference_rows(rhs, 2, {phi0, 0}, {period}, 0.01);
  EXPECT_NEAR(at_period[0][0], phi0, 1e-12 * phi0);
}

TEST(Reference, CoarseStepIsReportedHonestly) {
  // a deliberately coarse macro step: the estimate from halving must not understate the error
  namespace m = eomgen::models::pendulum;
  using W = reference::Wide;
  std::vector<W> p;
  for (double v : m::default_parameters) p.push_back(W(v));
  auto rhs = [&](W t, const W* x, W* xdot) { m::rhs<W>(t, x, nullptr, p.data(), xdot); };
  std::vector<double> times = output_times(10, 0.5);
  auto coarse = reference_rows(rhs, 2, {2.8, 0}, times, 0.5);
  auto finer = reference_rows(rhs, 2, {2.8, 0}, times, 0.25);
  auto exact = reference_rows(rhs, 2, {2.8, 0}, times, 0.01);
  double error = runtime::trajectory_error(finer, exact), estimate = runtime::trajectory_error(coarse, finer);
  EXPECT_GT(runtime::trajectory_error(coarse, exact), 1e-10) << "the coarse step should show an error";
  EXPECT_LE(error, estimate);
}

TEST(Reference, FreeRigidBodyMatchesEulersEquationsSolution) {
  namespace m = eomgen::models::free_rigid_body;
  using W = reference::Wide;
  std::vector<W> p;
  for (double v : m::default_parameters) p.push_back(W(v));
  auto rhs = [&](W t, const W* x, W* xdot) { m::rhs<W>(t, x, nullptr, p.data(), xdot); };
  std::vector<double> x0(m::default_state.begin(), m::default_state.end()), times = output_times(10, 0.05);
  auto rows = reference_rows(rhs, m::num_states, x0, times, 0.01);
  auto coarse = reference_rows(rhs, m::num_states, x0, times, 0.02);
  // Jacobi's solution for I1 < I2 < I3 and L² > 2E I2, starting from ω = (ω1, 0, ω3) with ω1, ω3 > 0
  std::vector<double> p_double(m::default_parameters.begin(), m::default_parameters.end());
  long double I1 = p_double[0], I2 = p_double[1], I3 = p_double[2];
  double w0[3];
  m::outputs<double>(0.0, x0.data(), nullptr, p_double.data(), w0);
  ASSERT_TRUE(I1 < I2 && I2 < I3 && w0[0] > 0 && w0[1] == 0 && w0[2] > 0);
  long double w10 = w0[0], w30 = w0[2];
  long double E2 = I1 * w10 * w10 + I3 * w30 * w30, L2 = I1 * I1 * w10 * w10 + I3 * I3 * w30 * w30;
  ASSERT_GT(L2, E2 * I2);
  long double w1m = std::sqrt((E2 * I3 - L2) / (I1 * (I3 - I1))), w2m = std::sqrt((E2 * I3 - L2) / (I2 * (I3 - I2)));
  long double w3m = std::sqrt((L2 - E2 * I1) / (I3 * (I3 - I1)));
  long double rate = std::sqrt((I3 - I2) * (L2 - E2 * I1) / (I1 * I2 * I3));
  long double mm = (I2 - I1) * (E2 * I3 - L2) / ((I3 - I2) * (L2 - E2 * I1));
  ASSERT_NEAR(static_cast<double>(w1m), w0[0], 1e-15);
  ASSERT_NEAR(static_cast<double>(w3m), w0[2], 1e-15);
  std::vector<std::vector<double>> computed, exact;
  for (std::size_t k = 0; k < times.size(); ++k) {
    double y[3];
    m::outputs<double>(times[k], rows[k].data(), nullptr, p_double.data(), y);
    computed.push_back({y[0], y[1], y[2]});
    Jacobi j = jacobi(rate * times[k], mm);
    exact.push_back({static_cast<double>(w1m * j.cn), static_cast<double>(w2m * j.sn), static_cast<double>(w3m * j.dn)});
  }
  double error = runtime::trajectory_error(computed, exact);
  EXPECT_LT(error, 1e-12);
  EXPECT_LT(runtime::trajectory_error(coarse, rows), 1e-12);
}

}  // namespace
}  // namespace eomgen::test
