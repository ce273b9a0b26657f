// A run with a budget of right-hand-side evaluations (what `eomgen scene` gives runs that
// could only be chosen by being cheaper than one it has) stops at the first output time
// past the budget, with the trajectory up to there unchanged, and is not stopped below it.
#include <gtest/gtest.h>

#include "generated/header_registry.hpp"
#include "simulation.hpp"

namespace eomgen::test {
namespace {

runtime::SimulationResult pendulum_by_rk4(long budget) {
  const GeneratedModel& g = generated_model("pendulum");
  runtime::Problem problem{g.abi, g.default_parameters, g.default_inputs};
  runtime::SimulationSettings s;
  s.t_end = 10, s.dt_out = 0.1, s.integrator = "rk4", s.step = 1e-3;
  s.max_rhs_evaluations = budget;
  return runtime::simulate(problem, g.default_state, s);
}

TEST(SimulationBudget, StopsAtTheFirstOutputTimePastTheBudget) {
  runtime::SimulationResult whole = pendulum_by_rk4(0), cut = pendulum_by_rk4(4000);
  ASSERT_FALSE(whole.failed) << whole.failure;
  ASSERT_TRUE(cut.failed);
  EXPECT_TRUE(cut.over_budget);
  // rk4 costs 4 evaluations a step, 400 an output interval: 4000 are spent at t = 1, passed at t = 1.1
  EXPECT_NEAR(cut.failure_time, 1.1, 1e-12) << cut.failure;
  ASSERT_EQ(cut.trajectory.times.size(), 12u);
  for (std::size_t k = 0; k < cut.trajectory.times.size(); ++k)
    EXPECT_EQ(cut.trajectory.states[k], whole.trajectory.states[k]) << "t = " << cut.trajectory.times[k];
  EXPECT_NE(cut.failure.find("budget"), std::string::npos) << cut.failure;
}

TEST(SimulationBudget, ARunWithinItsBudgetIsNotStopped) {
  runtime::SimulationResult r = pendulum_by_rk4(40'001);
  EXPECT_FALSE(r.failed) << r.failure;
  EXPECT_FALSE(r.over_budget);
  EXPECT_EQ(r.statistics.rhs_evaluations, 40'000);
}

}  // namespace
}  // namespace eomgen::test
