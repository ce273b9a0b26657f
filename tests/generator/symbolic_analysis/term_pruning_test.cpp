// Pruning against what the terms are worth along a trajectory: the pendulum's damping
// term goes when d = 0 and stays when it is not; the double pendulum with m2 = 1e-3 loses
// the m2 terms of the first angle's equation, below a tenth of a percent of it.
#include <gtest/gtest.h>

#include <cmath>

#include "symbolic_analysis/term_pruning.hpp"
#include "pipeline.hpp"
#include "support/test_support.hpp"
#include "symbolic/canonical_print.hpp"

namespace eomgen::test {
namespace {

// a swing φ = a cos(3 t) sampled on [0, 2]
void swing(std::size_t n, double a, std::vector<double>& times, std::vector<std::vector<double>>& states) {
  for (int k = 0; k <= 40; ++k) {
    double t = 0.05 * k;
    times.push_back(t);
    std::vector<double> x(2 * n, 0.0);
    x[0] = a * std::cos(3 * t), x[n] = -3 * a * std::sin(3 * t);
    states.push_back(x);
  }
}

TEST(TermPruning, ATermThatVanishesAlongTheTrajectoryGoes) {
  Equations e = derive_model("pendulum");  // m, l, g, d
  std::vector<double> times;
  std::vector<std::vector<double>> states;
  swing(1, 1.0, times, states);
  Pruning undamped = prune_terms(e, {1, 1, 9.81, 0}, {}, times, states, 1e-3);
  ASSERT_TRUE(undamped.refusal.empty()) << undamped.refusal;
  EXPECT_EQ(undamped.dropped, (std::vector<std::string>{"f[0]: -d*der(phi)"}));
  EXPECT_EQ(canonical_text(undamped.equations.forcing[0]), "-g*l*m*sin(phi)");
  EXPECT_EQ(undamped.equations.model_name, "pendulum_pruned");
  Pruning damped = prune_terms(e, {1, 1, 9.81, 0.5}, {}, times, states, 1e-3);
  EXPECT_TRUE(damped.dropped.empty());
  EXPECT_FALSE(damped.refusal.empty());
}

TEST(TermPruning, ALightSecondBobsTermsInTheFirstEquationGo) {
  Equations e = derive_model("double_pendulum");  // m1, m2, l1, l2, g; input tau
  std::vector<double> times;
  std::vector<std::vector<double>> states;
  swing(2, 0.8, times, states);
  Pruning p = prune_terms(e, {1, 1e-3, 1, 1, 9.81}, {0}, times, states, 1e-2);
  ASSERT_TRUE(p.refusal.empty()) << p.refusal;
  for (const std::string& d : p.dropped) EXPECT_TRUE(d.find("m2") != std::string::npos || d == "f[0]: tau") << d;
  EXPECT_EQ(canonical_text(p.equations.mass_matrix(0, 0)), "l1^2*m1");
  EXPECT_NE(canonical_text(p.equations.forcing[1]), "0") << "the second angle's own equation stays";
}

}  // namespace
}  // namespace eomgen::test
