// `eomgen stability --at p_phi=...`: the conical motion of the spherical pendulum on
// Routh's reduced system. With Omega² = g/(l cosθ0) and p_phi = m l² sin²θ0 Omega,
// the small oscillations about the cone have the frequency √(1 + 3cos²θ0)·Omega.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include <fmt/format.h>

#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

// the imaginary parts of the "eigenvalues" pairs of a stability JSON object
std::vector<double> eigenvalue_imaginary_parts(const std::string& json) {
  std::smatch list;
  std::vector<double> out;
  if (!std::regex_search(json, list, std::regex("\"eigenvalues\": \\[(.*?)\\]\\]"))) return out;
  std::string pairs = list[1].str() + "]";
  std::regex pair("\\[([^,\\]]+), ([^\\]]+)\\]");
  for (auto it = std::sregex_iterator(pairs.begin(), pairs.end(), pair); it != std::sregex_iterator(); ++it)
    out.push_back(std::stod((*it)[2].str()));
  return out;
}

TEST(RouthStability, ConicalMotionOfTheSphericalPendulum) {
  const double g = 9.81, l = 1, m = 1;  // the model's defaults
  for (double theta0 : {0.3, 0.6, 1.2}) {
    double omega = std::sqrt(g / (l * std::cos(theta0)));
    double p_phi = m * l * l * std::sin(theta0) * std::sin(theta0) * omega;
    double expected = std::sqrt(1 + 3 * std::cos(theta0) * std::cos(theta0)) * omega;
    CommandOutput r = run_eomgen(fmt::format("stability '{}' --at theta={:.17g} --at p_phi={:.17g} --format json",
                                          model_path("spherical_pendulum"), theta0, p_phi));
    ASSERT_EQ(r.status, 0) << r.err;
    std::vector<double> im = eigenvalue_imaginary_parts(r.out);
    ASSERT_EQ(im.size(), 2u) << "the reduced state is theta, der(theta): " << r.out;
    EXPECT_NEAR(std::abs(im[0]), expected, 1e-9 * expected) << "theta0 = " << theta0;
    EXPECT_NE(r.out.find("\"routh\": {\"eliminated\": [\"phi\"]"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\"verdict\": \"marginally_stable\""), std::string::npos) << r.out;
  }
}

TEST(RouthStability, TheConeIsFoundFromTheMomentumAlone) {
  // p_phi alone: the search finds the θ0 whose cone has this momentum, p² = m² l³ g sin⁴θ0 / cosθ0
  CommandOutput r = run_eomgen("stability '" + model_path("spherical_pendulum") + "' --at p_phi=0.5 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  std::smatch theta;
  ASSERT_TRUE(std::regex_search(r.out, theta, std::regex("\"theta\": ([-0-9.e]+)"))) << r.out;
  double t0 = std::stod(theta[1].str());
  EXPECT_NEAR(std::pow(std::sin(t0), 4) / std::cos(t0) * 9.81, 0.25, 1e-10) << r.out;
}

TEST(RouthStability, TextNamesTheReductionAndTheRouthian) {
  CommandOutput r = run_eomgen("stability '" + model_path("spherical_pendulum") + "' --at p_phi=0.5");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("Routh's reduction (Hiller §3.8.4): phi eliminated with p_phi=0.5 held"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("der(phi) = p_phi/(l^2*m*sin(theta)^2)"), std::string::npos) << r.out;
  CommandOutput cart = run_eomgen("stability '" + model_path("cart_pendulum") + "' --at p_x=1");
  EXPECT_EQ(cart.status, 2) << cart.out;
  EXPECT_NE(cart.err.find("Routh's reduction: an applied force or dissipation acts on x"), std::string::npos) << cart.err;
}

}  // namespace
}  // namespace eomgen::test
