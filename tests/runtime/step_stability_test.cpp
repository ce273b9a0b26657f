// The regions of absolute stability of the fixed-step methods against their closed
// forms: RK4 on the imaginary axis up to h·ω = 2√2, on the negative real axis up to
// the root of 1 + z + z²/2 + z³/6 + z⁴/24 = −1 (z ≈ −2.7853); Störmer–Verlet for an
// oscillation up to h·ω = 2.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "analyse/step_stability.hpp"

namespace eomgen::runtime {
namespace {

using namespace std::complex_literals;

TEST(StepStability, ClassicalRungeKuttaOnTheImaginaryAxisUpToTwoRootTwo) {
  double limit = 2 * std::sqrt(2.0);
  EXPECT_TRUE(inside_stability_region("rk4", (limit - 1e-9) * 1i));
  EXPECT_FALSE(inside_stability_region("rk4", (limit + 1e-6) * 1i));
  EXPECT_FALSE(inside_stability_region("rk4", 4.0i)) << "h = 0.2 s on ω = 20 rad/s";
}

TEST(StepStability, ClassicalRungeKuttaOnTheNegativeRealAxis) {
  // 1 + z + z²/2 + z³/6 + z⁴/24 = −1 has its real root near −2.785293563
  EXPECT_TRUE(inside_stability_region("rk4", std::complex<double>(-2.7852, 0)));
  EXPECT_FALSE(inside_stability_region("rk4", std::complex<double>(-2.7854, 0)));
  EXPECT_TRUE(inside_stability_region("rk4", std::complex<double>(-1, 0)));
}

TEST(StepStability, StoermerVerletUpToHOmegaTwo) {
  EXPECT_TRUE(inside_stability_region("verlet", 1.999i));
  EXPECT_FALSE(inside_stability_region("verlet", 2.001i));
}

}  // namespace
}  // namespace eomgen::runtime
