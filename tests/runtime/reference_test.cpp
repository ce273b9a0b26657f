// The reference integrator against closed-form solutions: the large-amplitude
// pendulum (Jacobi's elliptic functions) and the torque-free asymmetric rigid body
// (Euler's equations, Jacobi's solution), both to 1e-12 relative, with the
// integrator's own error estimate checked to be an honest bound.
#include <gtest/gtest.h>

#include <cmath>

#include <cstdio>

#include <Eigen/Dense>

#include "analyse/accuracy.hpp"
#include "reference/reference_solution.hpp"

#include "../generated/free_rigid_body.hpp"
#include "../generated/pendulum.hpp"
#include "../generated/tumbling_body.hpp"

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

// A free body on a quaternion, spun near its intermediate axis (models/tumbling_body.toml,
// Hiller §3.9.4): over 100 s it flips again and again as Jacobi's solution of Euler's equations
// says, passes every orientation with no singularity, its centre falls as z0 + vz0 t − g t²/2, and
// it keeps its energy and its angular momentum R I ω in inertial axes to 1e-10.
TEST(Reference, FreeBodyOnAQuaternionTumblesAsEulersEquationsSay) {
  namespace m = eomgen::models::tumbling_body;
  using W = reference::Wide;
  std::vector<W> p;
  for (double v : m::default_parameters) p.push_back(W(v));
  auto rhs = [&](W t, const W* x, W* xdot) { m::rhs<W>(t, x, nullptr, p.data(), xdot); };
  std::vector<double> x0(m::default_state.begin(), m::default_state.end()), times = output_times(100, 0.25);
  auto rows = reference_rows(rhs, m::num_states, x0, times, 0.02);
  long double I1 = m::default_parameters[0], I2 = m::default_parameters[1], I3 = m::default_parameters[2];
  double mass = m::default_parameters[3], g = m::default_parameters[4];
  // x: x, y, z, qw, qx, qy, qz, der(x), der(y), der(z), wx, wy, wz
  long double w10 = x0[10], w30 = x0[12];
  ASSERT_EQ(x0[11], 0.0);
  long double E2 = I1 * w10 * w10 + I3 * w30 * w30, L2 = I1 * I1 * w10 * w10 + I3 * I3 * w30 * w30;
  ASSERT_GT(L2, E2 * I2);
  long double w2m = std::sqrt((E2 * I3 - L2) / (I2 * (I3 - I2)));
  long double rate = std::sqrt((I3 - I2) * (L2 - E2 * I1) / (I1 * I2 * I3));
  long double mm = (I2 - I1) * (E2 * I3 - L2) / ((I3 - I2) * (L2 - E2 * I1));
  auto energy = [&](const std::vector<double>& x) {
    return 0.5 * mass * (x[7] * x[7] + x[8] * x[8] + x[9] * x[9]) + mass * g * x[2] +
           0.5 * (double(I1) * x[10] * x[10] + double(I2) * x[11] * x[11] + double(I3) * x[12] * x[12]);
  };
  auto momentum = [&](const std::vector<double>& x) {
    Eigen::Quaterniond q(x[3], x[4], x[5], x[6]);
    return Eigen::Vector3d(q.normalized().toRotationMatrix() *
                           Eigen::Vector3d(double(I1) * x[10], double(I2) * x[11], double(I3) * x[12]));
  };
  double E0 = energy(x0), w0 = std::sqrt(double(w10 * w10 + w30 * w30));
  Eigen::Vector3d L0 = momentum(x0);
  double worst_w = 0, worst_E = 0, worst_L = 0, worst_z = 0, worst_norm = 0, largest_wy = 0;
  int flips = 0;
  for (std::size_t k = 0; k < times.size(); ++k) {
    const std::vector<double>& x = rows[k];
    Jacobi j = jacobi(rate * times[k], mm);
    long double exact[3] = {w10 * j.cn, w2m * j.sn, w30 * j.dn};
    for (int a = 0; a < 3; ++a) worst_w = std::max(worst_w, std::abs(x[std::size_t(10 + a)] - double(exact[a])) / w0);
    worst_E = std::max(worst_E, std::abs(energy(x) - E0) / E0);
    worst_L = std::max(worst_L, (momentum(x) - L0).norm() / L0.norm());
    double z = x0[2] + x0[9] * times[k] - g * times[k] * times[k] / 2;
    worst_z = std::max(worst_z, std::abs(x[2] - z) / std::max(1.0, std::abs(z)));
    worst_norm = std::max(worst_norm, std::abs(std::sqrt(x[3] * x[3] + x[4] * x[4] + x[5] * x[5] + x[6] * x[6]) - 1));
    if (k > 0 && rows[k - 1][11] * x[11] < 0) ++flips;
    largest_wy = std::max(largest_wy, std::abs(x[11]));
  }
  std::printf("tumbling body over 100 s: ω %.2g, energy %.2g, angular momentum %.2g, fall %.2g, |q| %.2g; %d flips\n",
              worst_w, worst_E, worst_L, worst_z, worst_norm, flips);
  EXPECT_LT(worst_w, 1e-10) << "ω against Jacobi's solution";
  EXPECT_LT(worst_E, 1e-10) << "energy";
  EXPECT_LT(worst_L, 1e-10) << "angular momentum in inertial axes";
  EXPECT_LT(worst_z, 1e-10) << "the centre's fall";
  EXPECT_LT(worst_norm, 1e-10) << "|q| stays 1";
  EXPECT_GT(largest_wy, 0.99 * double(w2m)) << "the body turns over to its intermediate axis";
  EXPECT_GE(flips, 4) << "it flips again and again";
}

}  // namespace
}  // namespace eomgen::test
