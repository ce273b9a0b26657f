// `stability --at` on an Appell model names some states and solves for the rest, as it does for
// Lagrange II: the asymmetric top on its ball joint, its angular velocity named zero, has its
// quaternion solved for. Checked against the top written out here: its centre above the pivot, and
// its linearization about the pivot, I_W δθ'' = m g h diag(1, 1, 0) δθ (the gravity moment of a
// small turn δθ of the inverted body, h the centre's height over the pivot, I_W its inertia about
// the pivot in world axes), which has the eigenvalues ±√μ of I_W⁻¹ m g h diag(1, 1, 0).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "parse/json_reader.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

// models/ball_joint_top.toml's numbers: the centre c and the anchor a in the body's axes, its
// inertia about the centre, its mass and g
const Eigen::Vector3d centre_from_anchor(0.12 - 0.1, 0.03, 0.25);
Eigen::Matrix3d inertia_about_pivot() {
  Eigen::Matrix3d I;
  I << 0.02, 0.001, -0.002, 0.001, 0.025, 0.0015, -0.002, 0.0015, 0.04;
  const Eigen::Vector3d& r = centre_from_anchor;
  return I + 1.5 * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
}

TEST(AppellCompletion, ATopAtRestHasItsQuaternionSolvedForAndStandsAboveItsPivot) {
  CommandOutput r = run_eomgen(fmt::format("stability '{}' --at wz=0 --format json", model_path("ball_joint_top")));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("with the named ones held, qw = "), std::string::npos) << r.err;
  Diagnostics diagnostics;
  std::optional<JsonValue> json = parse_json(r.out, "stability", diagnostics);
  ASSERT_TRUE(json) << r.out;
  const JsonValue& equilibrium = *json->find("equilibrium");
  Eigen::Quaterniond q(at(equilibrium, "qw"), at(equilibrium, "qx"), at(equilibrium, "qy"), at(equilibrium, "qz"));
  EXPECT_NEAR(q.norm(), 1, 1e-14);
  Eigen::Matrix3d R = q.normalized().toRotationMatrix();
  Eigen::Vector3d up = R * centre_from_anchor;
  double h = centre_from_anchor.norm();
  EXPECT_NEAR(up.x() / h, 0, 1e-9) << up.transpose();
  EXPECT_NEAR(up.y() / h, 0, 1e-9) << up.transpose();
  EXPECT_NEAR(up.z() / h, 1, 1e-9) << "above the pivot, not below";
  EXPECT_EQ(json->find("verdict")->text, "unstable");
  // the two rates at which the inverted top falls, against eomgen's positive real eigenvalues
  Eigen::Matrix3d world_inertia = R * inertia_about_pivot() * R.transpose();
  Eigen::Matrix3d moment = 1.5 * 9.81 * up.z() * Eigen::Vector3d(1, 1, 0).asDiagonal();
  Eigen::Vector3cd mu = (world_inertia.inverse() * moment).eigenvalues();
  std::vector<double> expected, found;
  for (const auto& m : mu)
    if (m.real() > 1e-9) expected.push_back(std::sqrt(m.real()));
  for (const JsonValue& e : json->find("eigenvalues")->items)
    if (e.items.at(0).value > 1e-6) found.push_back(e.items.at(0).value);
  std::sort(expected.begin(), expected.end()), std::sort(found.begin(), found.end());
  ASSERT_EQ(expected.size(), 2u);
  ASSERT_EQ(found.size(), 2u) << r.out;
  for (std::size_t k = 0; k < 2; ++k) EXPECT_NEAR(found[k] / expected[k], 1, 1e-8) << k;
}

// A named quaternion component holds the whole quaternion (it is kept unit): nothing is then free,
// and the state is checked as given
TEST(AppellCompletion, ANamedQuaternionComponentHoldsTheQuaternion) {
  CommandOutput r = run_eomgen(fmt::format("stability '{}' --at qw=0.9", model_path("ball_joint_top")));
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.err.find("is not an equilibrium"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("Newton on"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace eomgen::test
