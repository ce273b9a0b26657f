// The quaternions of ball and free joints in simulation: the projection keeps them unit after
// every step and at every output time, without changing the motion (the rotation is that of
// q/|q|); without it their drift is reported as it is; a quaternion of length 0 is refused and
// one of another length divided by it at the start.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "generated/header_registry.hpp"
#include "simulation.hpp"

namespace eomgen::test {
namespace {

// x: x, y, z, qw, qx, qy, qz, der(x), der(y), der(z), wx, wy, wz (models/tumbling_body.toml)
double norm_error(const std::vector<double>& x) {
  return std::abs(std::sqrt(x[3] * x[3] + x[4] * x[4] + x[5] * x[5] + x[6] * x[6]) - 1);
}

Eigen::Matrix3d rotation(const std::vector<double>& x) {
  return Eigen::Quaterniond(x[3], x[4], x[5], x[6]).normalized().toRotationMatrix();
}

runtime::SimulationResult tumble(const std::string& integrator, bool projection, double rtol,
                                 std::vector<double> x0 = {}) {
  const GeneratedModel& g = generated_model("tumbling_body");
  runtime::Problem problem{g.abi, g.default_parameters, g.default_inputs};
  runtime::SimulationSettings s;
  s.t_end = 20;
  s.dt_out = 0.1;
  s.integrator = integrator;
  s.rtol = rtol;
  s.atol = rtol;
  s.step = 1e-3;
  s.projection = projection;
  return runtime::simulate(problem, x0.empty() ? g.default_state : x0, s);
}

double largest_norm_error(const runtime::Trajectory& t) {
  double largest = 0;
  for (const std::vector<double>& x : t.states) largest = std::max(largest, norm_error(x));
  return largest;
}

// the largest difference of the rotation and of ω between two runs over the same output times
double largest_difference(const runtime::Trajectory& a, const runtime::Trajectory& b) {
  EXPECT_EQ(a.times.size(), b.times.size());
  double largest = 0;
  for (std::size_t k = 0; k < std::min(a.times.size(), b.times.size()); ++k) {
    largest = std::max(largest, (rotation(a.states[k]) - rotation(b.states[k])).cwiseAbs().maxCoeff());
    for (std::size_t i = 10; i < 13; ++i) largest = std::max(largest, std::abs(a.states[k][i] - b.states[k][i]));
  }
  return largest;
}

TEST(Quaternions, TheProjectionKeepsThemUnitWithoutChangingTheMotion) {
  // Gauss–Legendre keeps qᵀq, a quadratic invariant of q' = ½ q ⊗ ω, by itself; the others drift
  // (the reference integrator, which the compiled-in models lack, in Simulate.ReportsWhether...)
  for (const char* integrator : {"arkode-dp5", "cvode-bdf", "cvode-adams", "rk4", "gauss-legendre"}) {
    SCOPED_TRACE(integrator);
    runtime::SimulationResult kept = tumble(integrator, true, 1e-12), free = tumble(integrator, false, 1e-12);
    ASSERT_FALSE(kept.failed) << kept.failure;
    ASSERT_FALSE(free.failed) << free.failure;
    EXPECT_LE(largest_norm_error(kept.trajectory), 4e-16);
    EXPECT_EQ(kept.largest_quaternion_norm_error, largest_norm_error(kept.trajectory));
    EXPECT_EQ(kept.quaternions_normalized, std::string(integrator) == "cvode-adams" ? "at the output times" : "after every step");
    EXPECT_TRUE(free.quaternions_normalized.empty());
    EXPECT_EQ(free.largest_quaternion_correction, 0.0);
    EXPECT_EQ(free.largest_quaternion_norm_error, largest_norm_error(free.trajectory));
    if (std::string(integrator) != "gauss-legendre" && std::string(integrator) != "rk4") {
      EXPECT_GT(free.largest_quaternion_norm_error, 1e-14) << "an adaptive integrator drifts |q|";
      EXPECT_GE(kept.largest_quaternion_correction, 1e-14);
    }
    EXPECT_LT(kept.largest_quaternion_correction, 1e-8);
    // the same motion to the integrators' accuracy: the rotation and ω of both runs
    EXPECT_LT(largest_difference(kept.trajectory, free.trajectory), 1e-8);
  }
}

TEST(Quaternions, AZeroQuaternionIsRefusedAndAnotherLengthDividedOut) {
  const GeneratedModel& g = generated_model("tumbling_body");
  std::vector<double> zero = g.default_state;
  std::fill(zero.begin() + 3, zero.begin() + 7, 0.0);
  runtime::SimulationResult refused = tumble("arkode-dp5", true, 1e-10, zero);
  EXPECT_TRUE(refused.failed);
  EXPECT_NE(refused.failure.find("(qw, qx, qy, qz) is 0 at the start and names no orientation"), std::string::npos)
      << refused.failure;
  // a turned start, once unit and once three times as long: the same motion, the long one divided
  std::vector<double> unit = g.default_state, longer = g.default_state;
  double half = 0.4, axis[3] = {0.6, 0.0, 0.8};
  unit[3] = std::cos(half);
  for (int a = 0; a < 3; ++a) unit[std::size_t(4 + a)] = std::sin(half) * axis[a];
  for (std::size_t i = 3; i < 7; ++i) longer[i] = 3 * unit[i];
  runtime::SimulationResult a = tumble("arkode-dp5", true, 1e-10, unit), b = tumble("arkode-dp5", true, 1e-10, longer);
  ASSERT_FALSE(a.failed) << a.failure;
  ASSERT_FALSE(b.failed) << b.failure;
  EXPECT_TRUE(a.warnings.empty());
  ASSERT_EQ(b.warnings.size(), 1u);
  EXPECT_NE(b.warnings[0].find("has length 3 at the start; it is divided by its length"), std::string::npos) << b.warnings[0];
  for (std::size_t i = 3; i < 7; ++i) EXPECT_NEAR(b.trajectory.states[0][i], unit[i], 4e-16);
  // the starts differ by rounding, and the runs then by what the integrator's step control makes of it
  EXPECT_LT(largest_difference(a.trajectory, b.trajectory), 1e-8);
  // without the projection the start stays as given, and the report says how far it is from unit
  runtime::SimulationResult c = tumble("arkode-dp5", false, 1e-10, longer);
  ASSERT_FALSE(c.failed) << c.failure;
  EXPECT_NEAR(c.largest_quaternion_norm_error, 2.0, 1e-8);
  EXPECT_LT(largest_difference(a.trajectory, c.trajectory), 1e-7);
}

}  // namespace
}  // namespace eomgen::test
