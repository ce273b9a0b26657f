// The leading power law of a change and how far it holds, on laws whose exponents and ends are
// known: r², r − r³/L² (its law ends near L, for L from 1e-12 to 1e12), 1 − cos r and
// (1e6 + r⁴) − 1e6 computed in double (their rounding at small r follows no law and is passed
// over), a falling change, and changes that are zero or of no steady power.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "analyse/local_power_law.hpp"

namespace eomgen::test {
namespace {

using runtime::leading_power_law;
using runtime::PowerLaw;

PowerLaw law_of(const std::function<double(double)>& change) {
  std::vector<double> changes;
  for (double r : runtime::probe_radii()) changes.push_back(change(r));
  return leading_power_law(changes);
}

TEST(LocalPowerLaw, APureLawHoldsAcrossTheWholeGrid) {
  PowerLaw law = law_of([](double r) { return 3 * r * r; });
  ASSERT_TRUE(law.found);
  EXPECT_NEAR(law.exponent, 2, 1e-12);
  EXPECT_EQ(law.sign, 1);
  EXPECT_EQ(law.from, 1e-40);
  EXPECT_TRUE(std::isinf(law.extent));
}

TEST(LocalPowerLaw, ALinearLawEndsWhereTheCubicTermTakesOverAtEveryScale) {
  for (int e = -12; e <= 12; e += 3) {
    double L = std::pow(10.0, e);
    PowerLaw law = law_of([L](double r) { return -r + r * r * r / (L * L); });
    ASSERT_TRUE(law.found) << "L = " << L;
    EXPECT_NEAR(law.exponent, 1, 1e-6) << "L = " << L;
    EXPECT_EQ(law.sign, -1) << "L = " << L;
    // at r = L/10 the cubic term is 1% of the linear one; at L the two cancel
    EXPECT_NEAR(law.extent / L, 0.1, 1e-6) << "L = " << L;
  }
}

TEST(LocalPowerLaw, RoundingAtSmallRadiiIsPassedOver) {
  PowerLaw cosine = law_of([](double r) { return 1 - std::cos(r); });
  ASSERT_TRUE(cosine.found);
  EXPECT_NEAR(cosine.exponent, 2, 0.02);
  EXPECT_EQ(cosine.sign, 1);
  EXPECT_GE(cosine.from, 1e-8);  // below, 1 − cos r is 0 or one unit in the last place
  volatile double offset = 1e6;  // kept from being folded away
  PowerLaw quartic = law_of([&](double r) { return (offset + r * r * r * r) - offset; });
  ASSERT_TRUE(quartic.found);
  EXPECT_NEAR(quartic.exponent, 4, 0.02);
  EXPECT_GE(quartic.from, 1e-2);  // r⁴ below the offset's last place, 1.2e-10, at r < 3e-3
}

TEST(LocalPowerLaw, NoChangeOrNoSteadyPowerIsNoLaw) {
  EXPECT_FALSE(law_of([](double) { return 0.0; }).found);
  EXPECT_FALSE(law_of([](double r) { return std::sin(1 / r); }).found);
  EXPECT_FALSE(law_of([](double) { return NAN; }).found);
  // a constant step is a change of exponent 0: no law of a smooth function at an equilibrium
  EXPECT_FALSE(law_of([](double) { return 1.0; }).found);
}

}  // namespace
}  // namespace eomgen::test
