// The leading power law of a change and how far it holds, on laws whose exponents and ends are
// known: r², r − r³/L² (its law ends near L, for L from 1e-12 to 1e12), 1 − cos r and
// (1e6 + r⁴) − 1e6 computed in double (their rounding at small r follows no law and is passed
// over), a falling change, changes that are zero or of no steady power, and the rounding of terms
// that cancel for every r, which hits zero again and again.
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

// models/gimbal_cardan.toml at rest (β = 0.2, γ = 0.3): der(alpha)''s change along der(gamma), whose
// terms cancel for every ω, as the generated rhs computed it. Its first four radii rise by 2^7 each
// (the last place of terms growing as ω²) and had read as a law of exponent 2.1 ending at 1e-37;
// its exact zeros between nonzero changes show it is rounding. A smooth change that crosses zero
// at a probe radius (r − r² at r = 1) keeps its law.
TEST(LocalPowerLaw, RoundingThatHitsZeroAgainAndAgainIsNoLaw) {
  std::vector<double> rounding{
      5.85e-98, 7.49e-96, 9.59e-94, 1.23e-91, 7.85e-90, 5.03e-88, 1.29e-85, 0, 5.27e-82, 0, 8.64e-78, 5.53e-76,
      7.07e-74, 1.81e-71, 5.8e-70, 0, 9.5e-66, 1.22e-63, 7.78e-62, 0, 6.37e-58, 8.16e-56, 5.22e-54, 6.68e-52,
      8.55e-50, 5.47e-48, 7.01e-46, 0, 1.15e-41, 7.35e-40, 1.41e-37, 0, 7.7e-34, -4.93e-32, -6.31e-30,
      8.08e-28, 1.55e-25, 6.62e-24, 1.69e-21, 5.42e-20, 0, 8.88e-16, 5.68e-14, -7.28e-12, 4.66e-10, -5.96e-08,
      1.53e-05, 0, 0, 8, 512, 6.55e+04, 0, 5.37e+08, 6.87e+10, 2.64e+13, 1.13e+15, -7.21e+16, 9.22e+18,
      5.9e+20, 1.51e+23, 9.67e+24, 1.86e+27, 7.92e+28, 1.01e+31, 1.95e+33, -8.31e+34, 0, 6.81e+38, 8.71e+40,
      5.58e+42, 2.14e+45, 0, 0, 1.5e+51, 1.44e+53, 6.13e+54, 1.57e+57, 5.02e+58, 0, 8.23e+62};
  ASSERT_EQ(rounding.size(), runtime::probe_radii().size());
  EXPECT_FALSE(leading_power_law(rounding).found);
  PowerLaw crossing = law_of([](double r) { return r - r * r; });
  ASSERT_TRUE(crossing.found);
  EXPECT_NEAR(crossing.exponent, 1, 1e-6);
  EXPECT_EQ(crossing.from, 1e-40);
  EXPECT_NEAR(crossing.extent, 0.1, 1e-15);  // the r² term is a tenth of r there
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
