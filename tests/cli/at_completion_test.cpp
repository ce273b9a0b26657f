// `stability --at` names some states and solves for the rest on Appell and Lagrange I models, as it
// does for Lagrange II. The asymmetric top on its ball joint, its angular velocity named zero, has
// its quaternion solved for, at every time scale. Checked against the top written out here: its
// centre above the pivot, and its linearization about the pivot, I_W δθ'' = m g h diag(1, 1, 0) δθ
// (the gravity moment of a small turn δθ of the inverted body, h the centre's height over the
// pivot, I_W its inertia about the pivot in world axes), which has the eigenvalues ±√μ of
// I_W⁻¹ m g h diag(1, 1, 0).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "parse/json_reader.hpp"
#include "support/ball_joint_top.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

// at time scales T of 1e-12, 1 and 1e12 s (g = 9.81/T²): the same quaternion, and rates × T
TEST(AtCompletion, ATopAtRestHasItsQuaternionSolvedForAndStandsAboveItsPivot) {
  for (double T : {1.0, 1e-12, 1e12}) {
    CommandOutput r = run_eomgen(fmt::format("stability '{}' --set g={:.17g} --at wz=0 --format json",
                                             model_path("ball_joint_top"), 9.81 / (T * T)));
    ASSERT_EQ(r.status, 0) << "T = " << T << "\n" << r.err;
    EXPECT_NE(r.err.find("with the named ones held, qw = "), std::string::npos) << r.err;
    Diagnostics diagnostics;
    std::optional<JsonValue> json = parse_json(r.out, "stability", diagnostics);
    ASSERT_TRUE(json) << r.out;
    const JsonValue& equilibrium = *json->find("equilibrium");
    Eigen::Quaterniond q(at(equilibrium, "qw"), at(equilibrium, "qx"), at(equilibrium, "qy"), at(equilibrium, "qz"));
    EXPECT_NEAR(q.norm(), 1, 1e-14);
    Eigen::Matrix3d R = q.normalized().toRotationMatrix();
    Eigen::Vector3d up = R * top_centre_from_anchor();
    double h = top_centre_from_anchor().norm();
    EXPECT_NEAR(up.x() / h, 0, 1e-9) << "T = " << T << ": " << up.transpose();
    EXPECT_NEAR(up.y() / h, 0, 1e-9) << "T = " << T << ": " << up.transpose();
    EXPECT_NEAR(up.z() / h, 1, 1e-9) << "above the pivot, not below";
    EXPECT_EQ(json->find("verdict")->text, "unstable");
    // the two rates at which the inverted top falls (at g = 9.81, times T), against eomgen's
    // positive real eigenvalues
    Eigen::Matrix3d world_inertia = R * top_inertia_about_pivot() * R.transpose();
    Eigen::Matrix3d moment = 1.5 * 9.81 * up.z() * Eigen::Vector3d(1, 1, 0).asDiagonal();
    Eigen::Vector3cd mu = (world_inertia.inverse() * moment).eigenvalues();
    std::vector<double> expected, found;
    for (const auto& m : mu)
      if (m.real() > 1e-9) expected.push_back(std::sqrt(m.real()));
    for (const JsonValue& e : json->find("eigenvalues")->items)
      if (e.items.at(0).value * T > 1e-6) found.push_back(e.items.at(0).value * T);
    std::sort(expected.begin(), expected.end()), std::sort(found.begin(), found.end());
    ASSERT_EQ(expected.size(), 2u);
    ASSERT_EQ(found.size(), 2u) << r.out;
    for (std::size_t k = 0; k < 2; ++k) EXPECT_NEAR(found[k] / expected[k], 1, 1e-8) << "T = " << T << ", " << k;
  }
}

// A named quaternion component holds the whole quaternion (it is kept unit): nothing is then free,
// and the state is checked as given
TEST(AtCompletion, ANamedQuaternionComponentHoldsTheQuaternion) {
  CommandOutput r = run_eomgen(fmt::format("stability '{}' --at qw=0.9", model_path("ball_joint_top")));
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.err.find("is not an equilibrium"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("Newton on"), std::string::npos) << r.err;
}

// Lagrange I: the coordinates not named close the constraints around the named ones. The Cartesian
// pendulum held at x = 0 hangs at y = −l; the four-bar held at its equilibrium's crank angle (found
// by the search) closes its loop at that equilibrium's coupler and rocker; held at 1.2 rad, where it
// is none, the refusal names where the loop closes, and the loop closes there (to the six digits
// printed) with a residual far past the tolerance; at time scales T of 1e-12, 1 and 1e12 s
TEST(AtCompletion, ALagrangeOneModelClosesItsConstraintsAroundTheNamedCoordinates) {
  for (double T : {1.0, 1e-12, 1e12}) {
    std::string g = fmt::format(" --set g={:.17g}", 9.81 / (T * T));
    JsonValue hanging = run_json(fmt::format("stability '{}' --at x=0", model_path("pendulum_cartesian")) + g);
    EXPECT_NEAR(at(*hanging.find("equilibrium"), "y"), -1, 1e-12) << "T = " << T;
    std::string four_bar = fmt::format("stability '{}'", model_path("four_bar_linkage")) + g;
    const JsonValue searched = *run_json(four_bar).find("equilibrium");
    CommandOutput held = run_eomgen(four_bar + fmt::format(" --at crank={:.17g} --format json", at(searched, "crank")));
    ASSERT_EQ(held.status, 0) << "T = " << T << "\n" << held.err;
    EXPECT_NE(held.err.find("with the named ones held, coupler = "), std::string::npos) << held.err;
    Diagnostics diagnostics;
    std::optional<JsonValue> json = parse_json(held.out, "stability", diagnostics);
    ASSERT_TRUE(json) << held.out;
    for (const char* name : {"coupler", "rocker"})
      EXPECT_NEAR(at(*json->find("equilibrium"), name), at(searched, name), 1e-9) << "T = " << T << ", " << name;
    CommandOutput off = run_eomgen(four_bar + " --at crank=1.2");
    EXPECT_EQ(off.status, 2) << off.out;
    std::smatch m;
    std::regex closed("the constraints close at coupler = ([-0-9.e]+), rocker = ([-0-9.e]+), where the largest "
                      "residual of the equations of motion is ([0-9.e+-]+) \\(tolerance ([0-9.e+-]+)\\)");
    ASSERT_TRUE(std::regex_search(off.err, m, closed)) << off.err;
    // models/four_bar_linkage.toml's lengths; the pin:
    // a (cos c1, sin c1) + b (cos c12, sin c12) = (d, 0) + c (cos c3, sin c3)
    const double a = 0.2, b = 0.5, c = 0.4, d = 0.45, c1 = 1.2, c12 = c1 + std::stod(m[1]), c3 = std::stod(m[2]);
    EXPECT_NEAR(a * std::cos(c1) + b * std::cos(c12) - d - c * std::cos(c3), 0, 1e-5);
    EXPECT_NEAR(a * std::sin(c1) + b * std::sin(c12) - c * std::sin(c3), 0, 1e-5);
    EXPECT_GT(std::stod(m[3]), 1e3 * std::stod(m[4])) << "T = " << T;
  }
}

}  // namespace
}  // namespace eomgen::test
