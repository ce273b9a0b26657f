// The turns the equations of motion do not see (runtime/analyse/turning_symmetries.hpp), on
// models/ball_joint_top.toml: hanging under gravity it turns freely about the vertical through its
// pivot and about nothing else, at every time scale; without gravity about every axis. The turn's
// nearest point (distance_modulo_turns) against a search over the angle.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "analyse/turning_symmetries.hpp"
#include "generated/header_registry.hpp"
#include "support/ball_joint_top.hpp"

namespace eomgen::test {
namespace {

// the top hanging at rest: its centre straight below the pivot (parameters m, g)
std::vector<double> hanging_top() {
  Eigen::Quaterniond q = Eigen::Quaterniond::FromTwoVectors(top_centre_from_anchor(), -Eigen::Vector3d::UnitZ());
  return {q.w(), q.x(), q.y(), q.z(), 0, 0, 0};
}

runtime::Problem top_with_gravity(double g) {
  const GeneratedModel& model = generated_model("ball_joint_top");
  return runtime::Problem{model.abi, {1.5, g}, {}};
}

// at g = 9.81/T²: the rate of the swing, √(g/ℓ), times 1/T
TEST(TurningSymmetries, AHangingTopTurnsAboutTheVerticalAloneAtEveryTimeScale) {
  ASSERT_STREQ(top_with_gravity(1).model->parameter_names[1], "g");
  for (double T : {1e-12, 1.0, 1e12}) {
    double g = 9.81 / (T * T);
    std::vector<runtime::TurningSymmetry> found = runtime::turning_symmetries(top_with_gravity(g), hanging_top(), std::sqrt(g / top_centre_from_anchor().norm()));
    ASSERT_EQ(found.size(), 1u) << "T = " << T;
    ASSERT_EQ(found[0].axes.size(), 1u) << "T = " << T;
    EXPECT_NEAR(std::abs(found[0].axes[0].z()), 1, 1e-9) << "T = " << T << ": " << found[0].axes[0].transpose();
  }
}

// with no gravity nothing in the equations depends on the body's orientation in the world
TEST(TurningSymmetries, ATopWithoutGravityTurnsAboutEveryAxis) {
  std::vector<runtime::TurningSymmetry> found = runtime::turning_symmetries(top_with_gravity(0), hanging_top(), 0);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].axes.size(), 3u);
}

// the rate given to the sampled states does not decide: any speed of the top's spin, and 0 (the
// model's default spin taken instead)
TEST(TurningSymmetries, TheSampledSpeedDoesNotDecide) {
  for (double rate : {0.0, 1e-6, 1e6}) {
    std::vector<runtime::TurningSymmetry> found = runtime::turning_symmetries(top_with_gravity(9.81), hanging_top(), rate);
    ASSERT_EQ(found.size(), 1u) << rate;
    ASSERT_EQ(found[0].axes.size(), 1u) << rate;
    EXPECT_NEAR(std::abs(found[0].axes[0].z()), 1, 1e-9) << rate;
  }
}

Eigen::Vector4d turned(const Eigen::Vector3d& axis, double angle, const Eigen::Vector4d& p) {
  Eigen::Quaterniond r(Eigen::AngleAxisd(angle, axis)), q(p[0], p[1], p[2], p[3]);
  Eigen::Quaterniond out = r * q;
  return {out.w(), out.x(), out.y(), out.z()};
}

TEST(TurningSymmetries, TheDistanceModuloATurnIsTheNearestOverItsAngle) {
  Eigen::Vector4d p(0.9, 0.3, -0.2, 0.1);
  p.normalize();
  Eigen::Vector3d axis = Eigen::Vector3d(0.6, 0, 0.8);
  // along the turn itself: nothing left, either sign of the quaternion
  for (double angle : {0.3, -2.0, 3.1, 5.0}) {
    EXPECT_NEAR(runtime::distance_modulo_turns(turned(axis, angle, p), p, {axis}), 0, 1e-15) << angle;
    EXPECT_NEAR(runtime::distance_modulo_turns(-turned(axis, angle, p), p, {axis}), 0, 1e-15) << angle;
  }
  // off it: the least over a fine sweep of the angle, which it can only undercut
  Eigen::Vector4d q = turned(Eigen::Vector3d(0, 1, 0), 0.4, turned(axis, 1.3, p));
  double least = INFINITY;
  for (int k = 0; k < 200000; ++k)
    least = std::min(least, (q - turned(axis, 4 * M_PI * k / 200000, p)).norm());
  double found = runtime::distance_modulo_turns(q, p, {axis});
  EXPECT_LE(found, least + 1e-12);
  EXPECT_GT(found, 0.05);
  EXPECT_EQ(runtime::distance_modulo_turns(q, p, {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()}), 0);
}

TEST(TurningSymmetries, TheOtherAxesCompleteAnOrthonormalBasis) {
  Eigen::Vector3d a = Eigen::Vector3d(0.6, 0, 0.8);
  std::vector<Eigen::Vector3d> others = runtime::other_axes({a});
  ASSERT_EQ(others.size(), 2u);
  EXPECT_NEAR(others[0].dot(a), 0, 1e-15);
  EXPECT_NEAR(others[1].dot(a), 0, 1e-15);
  EXPECT_NEAR(others[0].dot(others[1]), 0, 1e-15);
  EXPECT_NEAR(others[0].norm(), 1, 1e-15);
  EXPECT_NEAR(others[1].norm(), 1, 1e-15);
  EXPECT_EQ(runtime::other_axes({}).size(), 3u);
}

}  // namespace
}  // namespace eomgen::test
