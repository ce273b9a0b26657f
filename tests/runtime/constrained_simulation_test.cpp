// Simulating constrained models (compiled-in headers, the runtime directly, and the
// command line for the IDA run): the Cartesian pendulum under Lagrange I follows the
// angle pendulum, constraint residuals stay small with stabilization and drift without,
// energy is conserved by the conservative nonholonomic models, and the knife edge
// moves on its analytic circle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>

#include "generated/header_registry.hpp"
#include "simulation.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

runtime::SimulationResult run(const std::string& model, runtime::SimulationSettings settings, std::vector<double> x0 = {}) {
  const GeneratedModel& g = generated_model(model);
  runtime::Problem problem{g.abi, g.default_parameters, g.default_inputs};
  if (x0.empty()) x0 = g.default_state;
  return runtime::simulate(problem, x0, settings);
}

// arkode-dp5, not arkode-verner: Fehlberg 7(8)'s error estimate vanishes on components that are pure
// quadratures (x' = v cos(phi) of the knife edge), and it then steps far too long
runtime::SimulationSettings accurate(double t_end, const std::string& integrator = "arkode-dp5") {
  runtime::SimulationSettings s;
  s.t_end = t_end;
  s.dt_out = 0.05;
  s.integrator = integrator;
  s.rtol = 1e-12;
  s.atol = 1e-13;
  return s;
}

TEST(LagrangeOne, CartesianPendulumFollowsTheAnglePendulum) {
  runtime::SimulationResult cartesian = run("pendulum_cartesian", accurate(10));
  runtime::SimulationResult angle = run("pendulum", accurate(10));
  ASSERT_FALSE(cartesian.failed) << cartesian.failure;
  ASSERT_FALSE(angle.failed) << angle.failure;
  ASSERT_EQ(cartesian.trajectory.times.size(), angle.trajectory.times.size());
  const auto& pendulum = generated_model("pendulum").default_parameters;  // m, l, g, d
  ASSERT_EQ(generated_model("pendulum_cartesian").default_parameters, std::vector<double>(pendulum.begin(), pendulum.begin() + 3));
  ASSERT_EQ(pendulum[3], 0.0);
  double l = pendulum[1], worst = 0;
  for (std::size_t k = 0; k < angle.trajectory.times.size(); ++k) {
    double phi = angle.trajectory.states[k][0];
    worst = std::max({worst, std::abs(cartesian.trajectory.states[k][0] - l * std::sin(phi)),
                      std::abs(cartesian.trajectory.states[k][1] + l * std::cos(phi))});
  }
  EXPECT_LT(worst, 1e-8);
}

TEST(LagrangeOne, RodForceIsTheCentripetalPlusGravityForce) {
  // rod tension −2 l λ (the force on the bob is 2λ (x, y)) = m v²/l + m g cos φ, with cos φ = −y/l
  runtime::SimulationResult r = run("pendulum_cartesian", accurate(2));
  ASSERT_FALSE(r.failed);
  const auto& p = generated_model("pendulum_cartesian").default_parameters;  // m, l, g
  double m = p[0], l = p[1], g = p[2];
  for (std::size_t k = 0; k < r.trajectory.times.size(); ++k) {
    const auto& x = r.trajectory.states[k];
    double speed2 = x[2] * x[2] + x[3] * x[3], cos_phi = -x[1] / l;
    EXPECT_NEAR(-2 * l * r.trajectory.multipliers[k][0], m * speed2 / l + m * g * cos_phi, 1e-8);
  }
}

TEST(LagrangeOne, ResidualsStaySmallWithStabilizationAndDriftWithout) {
  runtime::SimulationSettings s;
  s.t_end = 100;
  s.dt_out = 0.1;
  runtime::SimulationResult stabilized = run("slider_crank", s);
  ASSERT_FALSE(stabilized.failed) << stabilized.failure;
  EXPECT_LT(stabilized.max_position_residual, 1e-8);
  EXPECT_LT(stabilized.max_velocity_residual, 1e-8);
  s.baumgarte = false;
  s.projection = false;
  runtime::SimulationResult plain = run("slider_crank", s);
  ASSERT_FALSE(plain.failed) << plain.failure;
  EXPECT_GT(plain.max_position_residual, 1e-6) << "the index-1 form without stabilization should drift";
  EXPECT_GT(plain.max_position_residual, 100 * stabilized.max_position_residual);
}

// Adams is projected at the output times and restarted there; CVodeReInit sets CVODE's counters to
// zero, and the report had said "steps 0, rhs evaluations 0" of a run of thousands
TEST(LagrangeOne, AdamsCountsItsStepsAcrossItsRestarts) {
  runtime::SimulationSettings s = accurate(10, "cvode-adams");
  runtime::SimulationResult r = run("pendulum_cartesian", s);
  ASSERT_FALSE(r.failed) << r.failure;
  EXPECT_EQ(r.projections, long(r.trajectory.times.size()) - 1) << "projected at every output time";
  EXPECT_GE(r.statistics.steps, r.projections) << "at least one step between two output times";
  EXPECT_GE(r.statistics.rhs_evaluations, r.statistics.steps);
}

TEST(LagrangeOne, ConsistentStartKeepsTheGivenCrankAngleAndRate) {
  runtime::SimulationResult r = run("slider_crank", accurate(0.1));
  ASSERT_FALSE(r.failed);
  const GeneratedModel& g = generated_model("slider_crank");
  double r_crank = g.default_parameters[0], l = g.default_parameters[1];  // r, l
  const auto& x0 = r.trajectory.states.front();
  EXPECT_EQ(x0[0], g.default_state[0]);  // phi as in the model file
  EXPECT_EQ(x0[3], g.default_state[3]);  // der(phi)
  EXPECT_NEAR(x0[1], -std::asin(r_crank * std::sin(x0[0]) / l), 1e-13);
  EXPECT_NEAR(x0[2], r_crank * std::cos(x0[0]) + l * std::cos(x0[1]), 1e-13);
}

// the consistent start meets the rod constraint to 1e-14 of its own size whatever the unit: an
// absolute 1e-14 took a pendulum of 1 µm started 0.1 % off its rod as consistent
TEST(LagrangeOne, TheConsistentStartMeetsTheConstraintOnEveryLengthScale) {
  const GeneratedModel& g = generated_model("pendulum_cartesian");
  std::vector<std::string> names(g.abi->parameter_names, g.abi->parameter_names + g.abi->num_parameters);
  auto index = [&](const char* name) { return std::size_t(std::find(names.begin(), names.end(), name) - names.begin()); };
  for (double length : {1e-12, 1e-6, 1.0, 1e6, 1e12}) {
    std::vector<double> parameters = g.default_parameters;
    parameters[index("l")] = length;
    parameters[index("g")] = 9.81 * length;  // the same motion in time
    runtime::Problem problem{g.abi, parameters, g.default_inputs};
    std::vector<double> x0 = {std::sin(0.5) * length, -std::cos(0.5) * length * 1.001, 0, 0};  // 0.1 % off the rod
    runtime::SimulationSettings s = accurate(0.1);
    s.atol = 1e-13 * length;
    runtime::SimulationResult r = runtime::simulate(problem, x0, s);
    ASSERT_FALSE(r.failed) << r.failure;
    const auto& start = r.trajectory.states.front();
    double rod = start[0] * start[0] + start[1] * start[1] - length * length;
    EXPECT_LT(std::abs(rod), 1e-13 * length * length) << "length " << length;
    EXPECT_LT(r.max_position_residual, 1e-9 * length * length) << "length " << length;
  }
}

TEST(LagrangeOne, IdaRunsTheSliderCrankWithSmallResiduals) {
  runtime::SimulationSettings s = accurate(10, "ida");
  s.rtol = 1e-10;
  s.atol = 1e-12;
  runtime::SimulationResult r = run("slider_crank", s);
  ASSERT_FALSE(r.failed) << r.failure;
  EXPECT_LT(r.max_position_residual, 1e-8);
  EXPECT_LT(r.max_velocity_residual, 1e-8);
  double e0 = r.trajectory.energies.front(), worst = 0;
  for (double e : r.trajectory.energies) worst = std::max(worst, std::abs(e - e0) / std::abs(e0));
  EXPECT_LT(worst, 1e-5);
}

// At rtol 1e-12, atol 1e-14, IDA's own first step on the four-bar was 1.3e-14 and its Newton
// failed there (the iteration matrix singular in double). It now runs, also in time units of
// 1e-6 and 1e6 (g scaled by 1/k² and the rates by 1/k, so that the motion is the same at t·k;
// the multipliers then scale by 1/k², which a fixed tolerance on them did not follow), and it
// follows the ODE form integrated by arkode-dp5 at the same tolerances. What the user gives in
// the time unit scales with it: Baumgarte's gains are rates, and the one atol of q and q' is set
// for the rates at k = 1e-6 (1e-14 on rates of 1e6 asks for 1e-20 where a rate passes through
// zero: no Newton iteration meets that). At k = 1e6 no one atol suits both (1e-14 leaves the
// rates of 1e-6 at 1e-8 of their size, 1e-20 fails where an angle passes through zero), so
// there the run is checked for its constraints alone.
TEST(LagrangeOne, IdaStartsAtTightTolerancesOnEveryTimeScale) {
  const GeneratedModel& g = generated_model("four_bar_linkage");
  std::size_t gravity = 0;
  while (std::string(g.abi->parameter_names[gravity]) != "g") ++gravity;
  for (double k : {1e-6, 1.0, 1e6}) {
    runtime::SimulationSettings s = accurate(2 * k, "ida");
    s.dt_out = 0.05 * k;
    s.atol = 1e-14 / std::min(k, 1.0);
    std::vector<double> parameters = g.default_parameters;
    parameters[gravity] /= k * k;
    std::vector<double> x0 = g.default_state;
    for (std::size_t i = 3; i < 6; ++i) x0[i] /= k;
    runtime::Problem problem{g.abi, parameters, g.default_inputs};
    runtime::SimulationResult dae = runtime::simulate(problem, x0, s);
    ASSERT_FALSE(dae.failed) << "time unit " << k << ": " << dae.failure;
    EXPECT_LT(dae.max_position_residual, 10 * s.rtol) << "time unit " << k;  // lengths of order 1
    if (k > 1) continue;
    s.integrator = "arkode-dp5";
    s.baumgarte_alpha = s.baumgarte_beta = g.abi->baumgarte_alpha / k;
    runtime::SimulationResult ode = runtime::simulate(problem, x0, s);
    ASSERT_FALSE(ode.failed) << ode.failure;
    ASSERT_EQ(dae.trajectory.times.size(), ode.trajectory.times.size());
    double worst = 0;
    for (std::size_t row = 0; row < dae.trajectory.times.size(); ++row)
      for (std::size_t i = 0; i < 3; ++i)
        worst = std::max(worst, std::abs(dae.trajectory.states[row][i] - ode.trajectory.states[row][i]));
    EXPECT_LT(worst, 1e-8) << "time unit " << k;
  }
}

TEST(LagrangeOne, IdaRefusesModelsWithoutMultipliers) {
  EXPECT_THROW(run("knife_edge", accurate(1, "ida")), std::invalid_argument);
}

class ConservativeNonholonomic : public ::testing::TestWithParam<std::string> {};

TEST_P(ConservativeNonholonomic, EnergyIsConservedAndConstraintsHold) {
  runtime::SimulationResult r = run(GetParam(), accurate(100));
  ASSERT_FALSE(r.failed) << r.failure;
  ASSERT_TRUE(generated_model(GetParam()).abi->conserves_energy_without_inputs);
  double e0 = r.trajectory.energies.front(), worst = 0;
  for (double e : r.trajectory.energies) worst = std::max(worst, std::abs(e - e0) / std::abs(e0));
  EXPECT_LT(worst, 1e-8) << GetParam();
  EXPECT_LT(r.max_velocity_residual, 1e-8) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Models, ConservativeNonholonomic, ::testing::Values("knife_edge", "chaplygin_sleigh", "rolling_disk"));

TEST(Appell, KnifeEdgeMovesOnACircle) {
  // v, w constant: x = x0 + v/w (sin φ − sin φ0), y = y0 − v/w (cos φ − cos φ0), φ = φ0 + w t
  runtime::SimulationResult r = run("knife_edge", accurate(20));
  ASSERT_FALSE(r.failed);
  const auto& start = r.trajectory.states.front();  // x, y, phi, v, w
  double x0 = start[0], y0 = start[1], phi0 = start[2], v = start[3], w = start[4], worst = 0;
  ASSERT_NE(w, 0.0);
  for (std::size_t k = 0; k < r.trajectory.times.size(); ++k) {
    double t = r.trajectory.times[k], phi = phi0 + w * t;
    const auto& x = r.trajectory.states[k];
    worst = std::max({worst, std::abs(x[0] - x0 - v / w * (std::sin(phi) - std::sin(phi0))),
                      std::abs(x[1] - y0 + v / w * (std::cos(phi) - std::cos(phi0))), std::abs(x[2] - phi),
                      std::abs(x[3] - v), std::abs(x[4] - w)});
  }
  EXPECT_LT(worst, 1e-9);
}

TEST(Appell, ChaplyginSleighStopsTurning) {
  // energy stays, the turning rate dies away and the speed tends to sqrt(2E/m)
  runtime::SimulationResult r = run("chaplygin_sleigh", accurate(100));
  ASSERT_FALSE(r.failed);
  const auto& end = r.trajectory.states.back();
  double energy = r.trajectory.energies.front();
  EXPECT_LT(std::abs(end[4]), 1e-3);
  double m = generated_model("chaplygin_sleigh").default_parameters[0];
  EXPECT_NEAR(end[3], std::sqrt(2 * energy / m), 1e-3);
}

}  // namespace
}  // namespace eomgen::test
