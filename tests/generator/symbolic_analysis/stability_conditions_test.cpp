// The Watt governor's symbolic Hurwitz conditions against Vyshnegradsky's
// condition, derived by hand for this model (Hiller §7.6): with s = sin θ0,
// c = cos θ0 at the steady motion κ c = P, n² ω0² l c = g, the reduced system
// (ω, θ, θ') is stable exactly when b ω0 (J + 2ml²n²s² + 8ml²n²c²) > 4 m l² c κ.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "symbolic_analysis/stability_conditions.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

struct Governor {
  double m, l, n, J, b, kappa, P, g;
  double theta() const { return std::acos(P / kappa); }
  double omega() const { return std::sqrt(g / (l * n * n * std::cos(theta()))); }
  bool vyshnegradsky() const {
    double s = std::sin(theta()), c = std::cos(theta());
    return b * omega() * (J + 2 * m * l * l * n * n * s * s + 8 * m * l * l * n * n * c * c) > 4 * m * l * l * c * kappa;
  }
  std::vector<double> parameters() const { return {m, l, n, J, b, kappa, P, g}; }  // model order
  std::vector<double> state() const { return {0, theta(), omega(), 0}; }
};

Governor defaults() { return {1.0, 0.25, 2.0, 0.5, 0.8, 10.0, 8.660254037844386, 9.81}; }

bool all_hold(const StabilityConditions& c, const GiNaC::exmap& at) {
  for (const GiNaC::ex& condition : c.conditions) {
    GiNaC::ex v = condition.subs(at).evalf();
    if (!(GiNaC::ex_to<GiNaC::numeric>(v).to_double() > 0)) return false;
  }
  return true;
}

GiNaC::ex symbol_named(const Equations& e, const std::string& name) { return closed_form(e, name); }

TEST(StabilityConditions, GovernorKeepingDampingAndInertiaIsVyshnegradsky) {
  Equations e = derive_model("watt_governor");
  Governor base = defaults();
  StabilityConditions c = stability_conditions(e, {"b", "J"}, base.parameters(), {}, base.state());
  EXPECT_TRUE(c.equilibrium_equations.empty()) << "b and J do not move the steady motion";
  ASSERT_FALSE(c.conditions.empty());
  std::mt19937 random(5);
  std::uniform_real_distribution<double> damping(0.01, 1.0), inertia(0.01, 3.0);
  int stable = 0;
  for (int k = 0; k < 300; ++k) {
    Governor gov = base;
    gov.b = damping(random), gov.J = inertia(random);
    GiNaC::exmap at{{symbol_named(e, "b"), gov.b}, {symbol_named(e, "J"), gov.J}};
    EXPECT_EQ(all_hold(c, at), gov.vyshnegradsky()) << "b = " << gov.b << ", J = " << gov.J;
    stable += gov.vyshnegradsky();
  }
  EXPECT_GT(stable, 30);
  EXPECT_LT(stable, 270);  // both sides of the boundary were sampled
}

TEST(StabilityConditions, GovernorBoundaryIsExactInTheDamping) {
  Equations e = derive_model("watt_governor");
  Governor base = defaults();
  StabilityConditions c = stability_conditions(e, {"b", "J"}, base.parameters(), {}, base.state());
  for (double J : {0.1, 0.5, 2.0}) {
    Governor gov = base;
    gov.J = J;
    double s = std::sin(gov.theta()), co = std::cos(gov.theta()), m = gov.m, l = gov.l, n = gov.n;
    double b_star = 4 * m * l * l * co * gov.kappa / (gov.omega() * (J + 2 * m * l * l * n * n * s * s + 8 * m * l * l * n * n * co * co));
    for (double factor : {1 - 1e-6, 1 + 1e-6}) {
      GiNaC::exmap at{{symbol_named(e, "b"), b_star * factor}, {symbol_named(e, "J"), J}};
      EXPECT_EQ(all_hold(c, at), factor > 1) << "J = " << J;
    }
  }
}

// keeping κ moves the steady motion: the conditions are then in θ and der(phi),
// with the equilibrium equations beside them
TEST(StabilityConditions, GovernorWithMovingSteadyMotion) {
  Equations e = derive_model("watt_governor");
  Governor base = defaults();
  StabilityConditions c = stability_conditions(e, {"b", "kappa"}, base.parameters(), {}, base.state());
  ASSERT_EQ(c.equilibrium_equations.size(), 2u);
  std::mt19937 random(8);
  std::uniform_real_distribution<double> damping(0.01, 2.0), gain(9.0, 30.0);
  for (int k = 0; k < 100; ++k) {
    Governor gov = base;
    gov.b = damping(random), gov.kappa = gain(random);
    GiNaC::exmap at{{symbol_named(e, "b"), gov.b}, {symbol_named(e, "kappa"), gov.kappa},
                    {symbol_named(e, "theta"), gov.theta()}, {symbol_named(e, "d_phi"), gov.omega()}};
    for (const GiNaC::ex& equation : c.equilibrium_equations)
      EXPECT_NEAR(GiNaC::ex_to<GiNaC::numeric>(equation.subs(at).evalf()).to_double(), 0.0, 1e-6);
    EXPECT_EQ(all_hold(c, at), gov.vyshnegradsky()) << "b = " << gov.b << ", kappa = " << gov.kappa;
  }
}

TEST(StabilityConditions, ExactNumbersReadBackTheirDecimals) {
  EXPECT_EQ(exact_number(9.81), GiNaC::numeric(981, 100));
  EXPECT_EQ(exact_number(-0.125), GiNaC::numeric(-1, 8));
  EXPECT_EQ(exact_number(1.5e-7), GiNaC::numeric(15, 100000000));
  EXPECT_EQ(exact_number(0.5000000000000001, 12), GiNaC::numeric(1, 2));
}

}  // namespace
}  // namespace eomgen::test
