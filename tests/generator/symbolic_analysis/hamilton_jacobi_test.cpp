// The Hamilton–Jacobi check (Hiller §3.8.5) on the worked examples: the free
// particle's S = a x + b y − (a² + b²) t/(2m) simplifies to a zero residual; the
// harmonic oscillator's separated S (with sqrt and asin) holds at random points;
// a wrong S fails, and nonconservative models and mistakes in S are refused.
#include <gtest/gtest.h>

#include "symbolic_analysis/hamilton_jacobi.hpp"
#include "pipeline.hpp"
#include "symbolic/canonical_print.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

Equations hamilton(const std::string& name) {
  Derivation d = derive_model_file_as(model_path(name), "hamilton");
  EXPECT_TRUE(d.diagnostics.empty()) << d.diagnostics.format();
  return d.equations ? *d.equations : Equations{};
}

std::optional<HamiltonJacobiCheck> check(const std::string& model, const std::string& action, Diagnostics& diagnostics) {
  return check_hamilton_jacobi(hamilton(model), action, "S.txt", diagnostics);
}

const std::string oscillator = "-alpha*t + x/2*sqrt(2*m*alpha - m*k*x^2) + alpha*sqrt(m/k)*asin(x*sqrt(k/(2*alpha)))";

TEST(HamiltonJacobi, FreeParticleSimplifiesToZero) {
  Diagnostics d;
  auto c = check("free_particle_hamilton", "# comment\na*x + b*y - (a^2 + b^2)*t/(2*m)  # S\n", d);
  ASSERT_TRUE(c) << d.format();
  EXPECT_TRUE(c->symbolic);
  EXPECT_TRUE(c->holds());
  EXPECT_EQ(c->constants, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(c->momenta[0].name, "p_x");
  EXPECT_EQ(canonical_text(c->momenta[0].expression), "a");
  EXPECT_EQ(canonical_text(c->momenta[1].expression), "b");
}

TEST(HamiltonJacobi, HarmonicOscillatorHoldsAtRandomPoints) {
  Diagnostics d;
  auto c = check("harmonic_oscillator_hamilton", oscillator, d);
  ASSERT_TRUE(c) << d.format();
  EXPECT_TRUE(c->holds()) << c->failure;
  EXPECT_EQ(c->constants, (std::vector<std::string>{"alpha"}));
  if (!c->symbolic) {
    EXPECT_GE(c->points, 40);
    EXPECT_LT(c->largest_relative_residual, 1e-12);
  }
}

TEST(HamiltonJacobi, AWrongActionFails) {
  Diagnostics d;
  // the energy's sign flipped: dS/dt = +alpha
  auto flipped = check("harmonic_oscillator_hamilton", "alpha*t + x/2*sqrt(2*m*alpha - m*k*x^2) + alpha*sqrt(m/k)*asin(x*sqrt(k/(2*alpha)))", d);
  ASSERT_TRUE(flipped) << d.format();
  EXPECT_FALSE(flipped->holds());
  EXPECT_NE(flipped->failure.find("dS/dt + H = "), std::string::npos) << flipped->failure;
  // the free particle with a wrong time term: 1/m instead of 1/(2m), which simplifies to a nonzero residual
  auto twice = check("free_particle_hamilton", "a*x + b*y - (a^2 + b^2)*t/m", d);
  ASSERT_TRUE(twice);
  EXPECT_FALSE(twice->holds());
}

TEST(HamiltonJacobi, RefusesNonconservativeModelsAndMistakes) {
  Diagnostics damped;
  EXPECT_FALSE(check("pendulum_hamilton", "-alpha*t", damped));
  EXPECT_NE(damped.format().find("do not derive from H"), std::string::npos) << damped.format();
  Diagnostics typo;
  EXPECT_FALSE(check("harmonic_oscillator_hamilton", "x*sqrt(alpha", typo));
  EXPECT_FALSE(typo.empty());
  Diagnostics velocity;
  EXPECT_FALSE(check("harmonic_oscillator_hamilton", "der(x)*alpha", velocity));
  EXPECT_FALSE(velocity.empty());
  Diagnostics empty;
  EXPECT_FALSE(check("harmonic_oscillator_hamilton", "# nothing\n", empty));
  EXPECT_NE(empty.format().find("no expression for S"), std::string::npos);
}

TEST(HamiltonJacobi, CommandExitsByTheVerdict) {
  std::string dir = std::string(EOMGEN_SOURCE_DIR) + "/tests/hamilton_jacobi/";
  CommandOutput good = run_eomgen("check-integral '" + model_path("harmonic_oscillator_hamilton") + "' --action '" + dir +
                                  "harmonic_oscillator.txt' --format json");
  EXPECT_EQ(good.status, 0) << good.err;
  EXPECT_NE(good.out.find("\"holds\": true"), std::string::npos) << good.out;
  CommandOutput bad = run_eomgen("check-integral '" + model_path("harmonic_oscillator_hamilton") + "' --action '" + dir +
                                 "harmonic_oscillator_wrong.txt'");
  EXPECT_EQ(bad.status, 1) << bad.err;
  EXPECT_NE(bad.out.find("fails: dS/dt + H ="), std::string::npos) << bad.out;
  CommandOutput free = run_eomgen("check-integral '" + model_path("free_particle_hamilton") + "' --action '" + dir +
                                  "free_particle.txt'");
  EXPECT_EQ(free.status, 0) << free.err;
  EXPECT_NE(free.out.find("holds: the residual simplifies to 0"), std::string::npos) << free.out;
  CommandOutput missing = run_eomgen("check-integral '" + model_path("free_particle_hamilton") + "' --action /nonexistent");
  EXPECT_EQ(missing.status, 2);
}

}  // namespace
}  // namespace eomgen::test
