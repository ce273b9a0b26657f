// Lyapunov's critical case decided by perturbed runs (runtime/analyse/critical_case.cpp): how large
// each push is, so that it stays a small perturbation of the system in any units and at any rate,
// and what a run that breaks off decides. Each model here had been given a wrong verdict: a sleigh
// at rest "unstable" in large units, a pendulum beside a stiff spring pushed over the top, two
// oscillators of very different rates "unstable" because CVODE stopped.
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <regex>
#include <string>

#include <fmt/format.h>

#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

// Two undamped oscillators at 1/T and 1e6/T rad/s, their springs generalized forces (so that
// Lagrange–Dirichlet does not apply): 200 slow periods are 3e7 fast ones, and CVODE's step limit
// ends the fast runs early. Such a run decides nothing: undecided, not the "unstable (the run broke
// off)" of a run that had grown. And K's range of exactly 1e12 is positive definite well beyond
// rounding: measured in the linearization's energy, not per state, where a slow velocity pushed at
// the fast rate had "grown" a millionfold. At a time scale of 1e12 s (k, K over T²) alone: each
// broken run takes CVODE's million steps, about 2 s.
TEST(CriticalCaseRuns, ARunThatBreaksOffWithoutGrowingDecidesNothing) {
  std::string model = write_model("two_rates", R"toml(
[model]
name = "two_rates"
title = "two undamped oscillators, their springs generalized forces"
[parameters]
m = 1.0
k = 1.0
K = 1e12
[coordinates]
x = 0.0
y = 0.0
[[particles]]
name = "slow"
mass = "m"
position = ["x", "0", "0"]
[[particles]]
name = "fast"
mass = "m"
position = ["0", "y", "0"]
[[forces]]
generalized = { x = "-k*x", y = "-K*y" }
)toml");
  const double T = 1e12;
  JsonValue r = run_json(fmt::format("stability '{}' --set k={:.17g} --set K={:.17g}", model, 1 / (T * T), 1e12 / (T * T)));
  EXPECT_EQ(field(r, "verdict").text, "marginally_stable") << "T = " << T;
  const JsonValue& critical = field(r, "critical_case");
  const std::string simulation = field(critical, "simulation").text;
  EXPECT_EQ(field(critical, "nonlinear_verdict").text, "undecided") << "T = " << T << ": " << simulation;
  EXPECT_NE(simulation.find("broke off"), std::string::npos) << simulation;
  EXPECT_NE(simulation.find("in the linearization's energy"), std::string::npos) << simulation;
  EXPECT_NE(simulation.find("the simulation decides nothing (CVODE"), std::string::npos) << simulation;
}

// A pendulum (g/l = 1/T² s⁻²) beside a stiff, critically damped spring (K = 1e6/T², c = 2e3/T),
// given as a generalized force so that Lagrange–Dirichlet does not apply, at time scales T from
// 1e-12 to 1e12 s: hanging, it is stable. Its velocity pushed at the spring's rate of 1e3/T, 10/T
// rad/s, had sent it over the top, and the runs had called it unstable; at its own rate √(K_ii/M_ii)
// = 1/T the push is theta's over T. The same system for Appell and Hamilton (p_theta = m l² der(theta),
// m = l = 1: the same push), their first-order forms measured in their linearization's energy too,
// where per state both had been called unstable after the same push of 10/T.
std::string pendulum_beside_a_stiff_spring(const std::string& method) {
  return write_model("pendulum_beside_a_stiff_spring_" + method, R"toml(
[model]
name = "pendulum_beside_a_stiff_spring_)toml" + method + R"toml("
title = "a pendulum beside a stiff damped spring, the spring a generalized force"
method = ")toml" + method + R"toml("
[parameters]
m = 1.0
l = 1.0
g = 1.0
K = 1e6
c = 2e3
[coordinates]
theta = 0.0
y = 0.0
[[particles]]
name = "bob"
mass = "m"
position = ["l*sin(theta)", "-l*cos(theta)", "0"]
[[particles]]
name = "block"
mass = "m"
position = ["0", "0", "y"]
[gravity]
acceleration = ["0", "-g", "0"]
[[forces]]
generalized = { y = "-K*y - c*der(y)" }
)toml");
}

void expect_pushed_at_its_own_rate(const std::string& method, std::initializer_list<double> time_scales) {
  std::string model = pendulum_beside_a_stiff_spring(method);
  std::string velocity = method == "hamilton" ? "p_theta" : R"(der\(theta\))";
  for (double T : time_scales) {
    SCOPED_TRACE(method + ", T = " + fmt::format("{}", T));
    JsonValue r = run_json(fmt::format("stability '{}' --set g={:.17g} --set K={:.17g} --set c={:.17g}", model, 1 / (T * T),
                                       1e6 / (T * T), 2e3 / T));
    EXPECT_EQ(field(r, "verdict").text, "marginally_stable");
    const JsonValue& critical = field(r, "critical_case");
    const std::string simulation = field(critical, "simulation").text;
    EXPECT_EQ(field(critical, "nonlinear_verdict").text, "stable") << simulation;
    EXPECT_NE(simulation.find("in the linearization's energy"), std::string::npos) << simulation;
    // the velocity's push is theta's at the pendulum's own rate √(g/l) = 1/T (printed to two digits)
    std::smatch push;
    ASSERT_TRUE(std::regex_search(simulation, push, std::regex(R"(theta ±([0-9.e+-]+), y ±[0-9.e+-]+, )" + velocity +
                                                               R"( ±([0-9.e+-]+))")))
        << simulation;
    EXPECT_NEAR(std::stod(push[2]) * T / std::stod(push[1]), 1, 0.05) << simulation;
  }
}

TEST(CriticalCaseRuns, ASlowCoordinatesVelocityIsPushedAtItsOwnRate) {
  expect_pushed_at_its_own_rate("lagrange2", {1e-12, 1e-6, 1.0, 1e6, 1e12});
  expect_pushed_at_its_own_rate("appell", {1e-12, 1.0, 1e12});
  expect_pushed_at_its_own_rate("hamilton", {1e-12, 1.0, 1e12});
}

// models/chaplygin_sleigh.toml at rest, its lengths in units of u from 1e-12 to 1e12 (a = 0.2 u,
// J = 0.05 u²): its forward speed v (m/s) and turning rate w (rad/s) trade kinetic energy
// m v² + (J + m a²) w², so pushes of one energy stay within once their size: stable. Pushes of 1e-3
// of each had turned a push of w into a speed of about a w, 2e5 times v's push at u = 1e6, and had
// called the sleigh at rest unstable from u = 1e3 on.
TEST(CriticalCaseRuns, PseudoVelocitiesArePushedWithOneKineticEnergyInAnyUnits) {
  for (double u : {1e-12, 1e-9, 1e-6, 1e-3, 1.0, 1e3, 1e6, 1e9, 1e12}) {
    JsonValue r = run_json(fmt::format("stability '{}' --at w=0 --set a={:.17g} --set J={:.17g}", model_path("chaplygin_sleigh"),
                                       0.2 * u, 0.05 * u * u));
    const JsonValue& critical = field(r, "critical_case");
    const std::string simulation = field(critical, "simulation").text;
    EXPECT_EQ(field(critical, "nonlinear_verdict").text, "stable") << "u = " << u << ": " << simulation;
    EXPECT_NE(simulation.find("at most the kinetic energy of the least of them"), std::string::npos) << simulation;
    std::smatch within;
    ASSERT_TRUE(std::regex_search(simulation, within, std::regex("stayed within ([0-9.e+-]+) times"))) << simulation;
    EXPECT_LE(std::stod(within[1]), 1.001) << "u = " << u << ": the energy of a push is kept";
  }
}

}  // namespace
}  // namespace eomgen::test
