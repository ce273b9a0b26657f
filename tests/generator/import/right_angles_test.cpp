// Right angles to the last digit are imported exactly (generator/import/right_angles.hpp): each of
// the cube's 24 turns, its quaternion a unit in the last place off, as MuJoCo's compiler makes it
// from rpy = "1.5707963267948966"; a turn stated to fewer digits, or no right angle, stays as read;
// and an arm imported with both has MuJoCo's dynamics. With --right-angles-within, turns stated
// to fewer digits are rounded to their right angles, and the arm then has the exact arm's dynamics.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <set>

#include <Eigen/Geometry>
#include <mujoco/mujoco.h>

#include "import/model_writer.hpp"
#include "import/right_angles.hpp"
#include "support/mujoco_dynamics.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

// the 24 rotations that map the coordinate axes onto themselves, with signs
std::vector<Eigen::Matrix3d> turns_of_the_cube() {
  std::vector<Eigen::Matrix3d> turns;
  int order[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto& o : order)
    for (int signs = 0; signs < 8; ++signs) {
      Eigen::Matrix3d P = Eigen::Matrix3d::Zero();
      for (int r = 0; r < 3; ++r) P(r, o[r]) = (signs >> r & 1) ? -1 : 1;
      if (P.determinant() > 0) turns.push_back(P);
    }
  return turns;
}

// the rotation of quat(w, x, y, z) as eomgen reads it, R(q)/|q|², exactly for integers
Eigen::Matrix3d integer_quaternion_rotation(const std::array<int, 4>& q) {
  Eigen::Quaterniond unit(q[0], q[1], q[2], q[3]);
  return unit.normalized().toRotationMatrix();
}

TEST(RightAngles, EveryTurnOfTheCubeIsWrittenExactly) {
  std::vector<Eigen::Matrix3d> turns = turns_of_the_cube();
  ASSERT_EQ(turns.size(), 24u);
  std::set<std::array<int, 4>> written;
  for (const Eigen::Matrix3d& P : turns) {
    Eigen::Quaterniond q(P);
    for (double sign : {1.0, -1.0})
      for (int off = 0; off < 16; ++off) {
        // each nonzero component a unit in the last place up or down, as rounding leaves it
        Quaternion read{sign * q.w(), sign * q.x(), sign * q.y(), sign * q.z()};
        for (std::size_t k = 0; k < 4; ++k)
          if (read[k] != 0) read[k] = std::nextafter(read[k], (off >> k & 1) ? 2.0 : -2.0);
        auto turn = right_angle_turn(read);
        ASSERT_TRUE(turn) << P;
        Eigen::Matrix3d R = integer_quaternion_rotation(*turn);
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) EXPECT_LE(std::abs(R(r, c) - P(r, c)), 1e-15) << P << "\nas\n" << R;
        int length = (*turn)[0] * (*turn)[0] + (*turn)[1] * (*turn)[1] + (*turn)[2] * (*turn)[2] + (*turn)[3] * (*turn)[3];
        EXPECT_TRUE(length == 1 || length == 2 || length == 4) << "integers of one size: exact in quat()";
        if (off == 0 && sign > 0) written.insert(*turn);
      }
  }
  EXPECT_EQ(written.size(), 24u);
}

Quaternion about_x(double angle) { return Quaternion{std::cos(angle / 2), std::sin(angle / 2), 0, 0}; }

TEST(RightAngles, TurnsStatedToFewerDigitsOrNoRightAngleStayAsRead) {
  EXPECT_TRUE(right_angle_turn(about_x(1.5707963267948966)));
  EXPECT_FALSE(right_angle_turn(about_x(3.14159265359))) << "2e-13 from pi: the file's robot";
  EXPECT_FALSE(right_angle_turn(about_x(1.5708)));
  EXPECT_FALSE(right_angle_turn(about_x(0.3)));
  EXPECT_FALSE(right_angle_turn({0.9238795325112867, 0, 0, -0.3826834323650898})) << "45 degrees";
  EXPECT_FALSE(right_angle_turn({0, 0, 0, 0}));
  auto identity = right_angle_turn({1, 0, 0, std::nextafter(0.0, 1.0)});
  ASSERT_TRUE(identity);
  EXPECT_EQ(*identity, (std::array<int, 4>{1, 0, 0, 0}));
}

// two links: the elbow turned by rpy = -pi/2 to the last digit and the wrist by pi to 12 digits
const char* const right_angled_arm = R"(<?xml version="1.0"?>
<robot name="right_angled_arm">
  <link name="base"/>
  <link name="upper">
    <inertial><origin xyz="0.02 0 0.15"/><mass value="2.0"/><inertia ixx="0.02" ixy="0" ixz="0" iyy="0.018" iyz="0" izz="0.004"/></inertial>
  </link>
  <link name="fore">
    <inertial><origin xyz="0 0.01 0.12"/><mass value="1.3"/><inertia ixx="0.011" ixy="0" ixz="0" iyy="0.009" iyz="0" izz="0.002"/></inertial>
  </link>
  <link name="hand">
    <inertial><origin xyz="0.01 0 0.04"/><mass value="0.6"/><inertia ixx="0.002" ixy="0" ixz="0" iyy="0.0015" iyz="0" izz="0.001"/></inertial>
  </link>
  <joint name="shoulder" type="revolute">
    <parent link="base"/><child link="upper"/><origin xyz="0 0 0.333"/><axis xyz="0 0 1"/>
    <limit lower="-2.9" upper="2.9" effort="87" velocity="2.1"/>
  </joint>
  <joint name="elbow" type="revolute">
    <parent link="upper"/><child link="fore"/><origin xyz="0 0 0.3" rpy="-1.5707963267948966 0 0"/><axis xyz="0 0 1"/>
    <limit lower="-1.7" upper="1.7" effort="87" velocity="2.1"/>
  </joint>
  <joint name="wrist" type="revolute">
    <parent link="fore"/><child link="hand"/><origin xyz="0.08 0 0.25" rpy="3.14159265359 0 0"/><axis xyz="0 0 1"/>
    <limit lower="-2.9" upper="2.9" effort="12" velocity="2.6"/>
  </joint>
</robot>
)";

TEST(RightAngles, AnArmImportsItsRightAngleExactlyAndKeepsMuJoCosDynamics) {
  std::string path = write_file("right_angled_arm.urdf", right_angled_arm);
  Diagnostics diagnostics;
  auto text = imported_model_text(path, diagnostics, false);
  ASSERT_TRUE(text) << diagnostics.format();
  EXPECT_NE(text->find("rotation = \"quat(1, -1, 0, 0)\""), std::string::npos) << *text;
  EXPECT_NE(text->find("1.0341155355510722e-13, 1, 0, 0)\""), std::string::npos)
      << "pi to 12 digits, as MuJoCo read it\n" << *text;
  Equations e = derive_text(*text, "right_angled_arm.toml");
  ASSERT_EQ(e.num_velocities(), 3u);
  char error[1000] = "";
  std::unique_ptr<mjModel, void (*)(mjModel*)> m(mj_loadXML(path.c_str(), nullptr, error, sizeof error), mj_deleteModel);
  ASSERT_TRUE(m) << error;
  expect_mujoco_dynamics(e, m.get(), {"shoulder", "elbow", "wrist"}, 5, 1e-14, 1e-13);
}

TEST(RightAngles, TheNearestRightAngleAndHowFarATurnIsFromIt) {
  const double half_pi = 1.5707963267948966, pi = 3.141592653589793;
  auto five_digits = nearest_right_angle(about_x(1.5708));
  ASSERT_TRUE(five_digits);
  EXPECT_EQ(five_digits->turn, (std::array<int, 4>{1, 1, 0, 0}));
  EXPECT_NEAR(five_digits->angle, 1.5708 - half_pi, 1e-15);
  auto twelve_digits = nearest_right_angle(about_x(-3.14159265359));
  ASSERT_TRUE(twelve_digits);
  EXPECT_NEAR(twelve_digits->angle, 3.14159265359 - pi, 1e-15) << "accurate where acos would keep 8 digits";
  // a small turn about an oblique axis is that far from no turn at all
  Eigen::Quaterniond oblique(Eigen::AngleAxisd(0.05, Eigen::Vector3d(1, 1, 0).normalized()));
  auto near_identity = nearest_right_angle({oblique.w(), oblique.x(), oblique.y(), oblique.z()});
  ASSERT_TRUE(near_identity);
  EXPECT_EQ(near_identity->turn, (std::array<int, 4>{1, 0, 0, 0}));
  EXPECT_NEAR(near_identity->angle, 0.05, 1e-15);
  EXPECT_FALSE(nearest_right_angle(about_x(0.3)));
  EXPECT_FALSE(nearest_right_angle({0.9238795325112867, 0, 0, -0.3826834323650898})) << "45 degrees";
  EXPECT_FALSE(nearest_right_angle({0, 0, 0, 0}));
}

TEST(RightAngles, RoundingMovesOnlyTheTurnsWithinItsAngle) {
  Robot robot;
  for (double angle : {1.5708, 3.14159, 1.56, 1.5707963267948966, 0.0})
    robot.bodies.push_back(RobotBody{}), robot.bodies.back().orientation = about_x(angle);
  robot.bodies.back().inertia_axes = about_x(-1.5708);
  Robot as_read = robot;
  RightAngleRounding noted = rounded_right_angles(robot, 0);
  EXPECT_EQ(noted.rounded, 0);
  EXPECT_EQ(noted.near, 2) << "1.5708 and 3.14159; not 1.56 (0.011 rad off), nor the exact ones";
  EXPECT_NEAR(noted.largest_near, 1.5708 - 1.5707963267948966, 1e-15);
  for (std::size_t b = 0; b < robot.bodies.size(); ++b) EXPECT_EQ(robot.bodies[b].orientation, as_read.bodies[b].orientation);
  RightAngleRounding done = rounded_right_angles(robot, 3e-6);
  EXPECT_EQ(done.rounded, 1) << "3.14159 is 2.7e-6 from pi";
  EXPECT_EQ(done.near, 1);
  EXPECT_TRUE(right_angle_turn(robot.bodies[1].orientation));
  EXPECT_FALSE(right_angle_turn(robot.bodies[0].orientation));
  done = rounded_right_angles(robot, 1e-5);
  EXPECT_EQ(done.rounded, 1) << "1.5708; 3.14159 is exact by now";
  EXPECT_EQ(done.near, 0);
  EXPECT_NEAR(done.largest_rounded, 1.5708 - 1.5707963267948966, 1e-15);
  EXPECT_TRUE(right_angle_turn(robot.bodies[0].orientation));
  EXPECT_EQ(robot.bodies[2].orientation, as_read.bodies[2].orientation) << "1.56 is no right angle";
  EXPECT_EQ(robot.bodies[4].inertia_axes, as_read.bodies[4].inertia_axes)
      << "axes of inertia a little off the frame's are products of inertia: as read";
}

TEST(RightAngles, AnArmStatedToFiveDigitsAndRoundedHasTheExactArmsDynamics) {
  std::string five_digits = right_angled_arm;
  for (auto [from, to] : {std::pair<std::string, std::string>{"-1.5707963267948966", "-1.5708"}, {"3.14159265359", "3.1416"}})
    five_digits.replace(five_digits.find(from), from.size(), to);
  std::string path = write_file("five_digit_arm.urdf", five_digits);
  Diagnostics as_read_diagnostics, rounded_diagnostics;
  auto as_read = imported_model_text(path, as_read_diagnostics, false);
  ASSERT_TRUE(as_read) << as_read_diagnostics.format();
  EXPECT_NE(as_read->find("# note: 2 turn(s) are within 7.3e-06 rad of a right angle"), std::string::npos) << *as_read;
  EXPECT_NE(as_read->find("`eomgen import --right-angles-within 1e-05` writes them as exact right angles"), std::string::npos);
  EXPECT_EQ(as_read->find("quat(1, -1, 0, 0)"), std::string::npos);
  auto rounded = imported_model_text(path, rounded_diagnostics, false, "", {false, false, 1e-5});
  ASSERT_TRUE(rounded) << rounded_diagnostics.format();
  EXPECT_NE(rounded->find("rotation = \"quat(1, -1, 0, 0)\""), std::string::npos) << *rounded;
  EXPECT_NE(rounded->find("rotation = \"quat(0, 1, 0, 0)\""), std::string::npos) << *rounded;
  EXPECT_NE(rounded->find("# note: 2 turn(s) within 7.3e-06 rad of a right angle written as exact right angles"), std::string::npos);
  // the oracle: MuJoCo reading the arm whose turns the file states exactly
  std::string exact = right_angled_arm;
  exact.replace(exact.find("3.14159265359"), 13, "3.141592653589793");
  std::string exact_path = write_file("exact_arm.urdf", exact);
  char error[1000] = "";
  std::unique_ptr<mjModel, void (*)(mjModel*)> m(mj_loadXML(exact_path.c_str(), nullptr, error, sizeof error), mj_deleteModel);
  ASSERT_TRUE(m) << error;
  expect_mujoco_dynamics(derive_text(*rounded, "five_digit_arm.toml"), m.get(), {"shoulder", "elbow", "wrist"}, 5, 1e-14, 1e-13);
}

}  // namespace
}  // namespace eomgen::test
