// Inertias that no rigid body has (generator/import/unbalanced_inertias.hpp): MuJoCo's compiler
// refuses a URDF link whose principal moments break A + B >= C, and with balanceinertia would
// average them; the import takes them as the file states them. The links' inertias read from the
// text are checked against MuJoCo's own reading of a valid one, and the imported arm's M against
// the stated tensor worked out by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <variant>

#include <mujoco/mujoco.h>

#include "import/mjcf_reader.hpp"
#include "import/model_writer.hpp"
#include "import/unbalanced_inertias.hpp"
#include "model/model.hpp"
#include "parse/model_file.hpp"
#include "pipeline.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

// R diag(moments) Rᵀ, R the quaternion's rotation: the tensor in the body's frame
std::array<double, 9> body_frame_tensor(const Triple& moments, const Quaternion& axes) {
  mjtNum q[4] = {axes[0], axes[1], axes[2], axes[3]}, R[9];
  mju_quat2Mat(R, q);
  std::array<double, 9> I{};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) I[std::size_t(3 * r + c)] += R[3 * r + k] * moments[std::size_t(k)] * R[3 * c + k];
  return I;
}

std::string one_link_urdf(const std::string& inertial) {
  return "<robot name=\"unbalanced\">\n  <link name=\"base\"/>\n  <link name=\"arm\">\n    <inertial>\n" + inertial +
         "    </inertial>\n  </link>\n  <joint name=\"swing\" type=\"continuous\">\n    <parent link=\"base\"/>\n"
         "    <child link=\"arm\"/>\n    <origin xyz=\"0 0 0\"/>\n    <axis xyz=\"0 0 1\"/>\n  </joint>\n</robot>\n";
}

TEST(UnbalancedInertias, TheTextsInertiaIsTheOneMujocoReadsFromAValidLink) {
  std::string urdf = one_link_urdf(
      "      <origin xyz=\"0.1 -0.02 0.03\" rpy=\"0.3 -0.7 1.1\"/>\n      <mass value=\"1.5\"/>\n"
      "      <inertia ixx=\"0.02\" ixy=\"0.003\" ixz=\"-0.002\" iyy=\"0.025\" iyz=\"0.004\" izz=\"0.03\"/>\n");
  std::vector<LinkInertia> links = urdf_link_inertias(urdf);
  ASSERT_EQ(links.size(), 1u);
  EXPECT_EQ(links[0].link, "arm");
  EXPECT_EQ(links[0].mass, 1.5);
  EXPECT_FALSE(links[0].unbalanced);
  auto read = read_with_mujoco(write_file("valid.urdf", urdf));
  ASSERT_TRUE(std::holds_alternative<Robot>(read)) << std::get<UnreadableRobot>(read).message;
  const RobotBody* arm = nullptr;
  for (const RobotBody& b : std::get<Robot>(read).bodies)
    if (b.name == "arm") arm = &b;
  ASSERT_NE(arm, nullptr);
  std::array<double, 9> ours = body_frame_tensor(links[0].principal, links[0].axes),
                        mujoco = body_frame_tensor(arm->principal_inertia, arm->inertia_axes);
  // MuJoCo's compiler leaves its principal axes of a turned full tensor about 5e-10 (relative) from
  // the stated one (measured: 2e-11 on moments of 0.03); a wrong order of roll, pitch and yaw is off
  // in the second digit
  for (std::size_t k = 0; k < 9; ++k) EXPECT_NEAR(ours[k], mujoco[k], 1e-9 * 0.03) << k;
}

TEST(UnbalancedInertias, AnArmWhoseMomentsBreakTheTriangleKeepsThemAsStated) {
  // about the link's frame, turned by rpy = (0, 0, π/2): I' = R I Rᵀ has I'xx = Iyy, I'yy = Ixx,
  // I'xy = −Ixy, I'xz = −Iyz, I'yz = Ixz, I'zz = Izz; the moments 0.00085, 0.00215, 0.01 break A + B ≥ C
  std::string urdf = one_link_urdf(
      "      <origin xyz=\"0.1 0 0\" rpy=\"0 0 1.5707963267948966\"/>\n      <mass value=\"1\"/>\n"
      "      <inertia ixx=\"0.001\" ixy=\"0.0005\" ixz=\"0.0003\" iyy=\"0.002\" iyz=\"0\" izz=\"0.01\"/>\n");
  const std::array<double, 9> stated{0.002, -0.0005, 0, -0.0005, 0.001, 0.0003, 0, 0.0003, 0.01};
  std::string path = write_file("unbalanced.urdf", urdf);
  auto read = read_with_mujoco(path);
  ASSERT_TRUE(std::holds_alternative<Robot>(read)) << std::get<UnreadableRobot>(read).message;
  const Robot& robot = std::get<Robot>(read);
  std::array<double, 9> restored{};
  for (const RobotBody& b : robot.bodies)
    if (b.name == "arm") restored = body_frame_tensor(b.principal_inertia, b.inertia_axes);
  for (std::size_t k = 0; k < 9; ++k) EXPECT_NEAR(restored[k], stated[k], 1e-17) << k;
  bool warned = false;
  for (const RobotWarning& w : robot.warnings) warned = warned || (w.name == "arm" && w.text.find("no rigid body has") != std::string::npos);
  EXPECT_TRUE(warned);
  // M = I'zz + m |c|² about the hinge through the link's origin: 0.02, where MuJoCo's balanced
  // moments would give 0.013/3 + 0.01
  Diagnostics diagnostics;
  auto text = imported_model_text(path, diagnostics, false);
  ASSERT_TRUE(text) << diagnostics.format();
  EXPECT_NE(text->find("unphysical_inertia = true"), std::string::npos) << *text;
  Equations e = derive_text(*text);
  ASSERT_EQ(e.num_velocities(), 1u);
  EXPECT_NEAR(value_at(e.mass_matrix(0, 0), point_by_name(e, {{"swing", 0.7}, {"der(swing)", 0.3}, {"g", 9.81}})), 0.02, 1e-15);
}

TEST(UnbalancedInertias, ADummyLinksRankOneInertiaHasTwoZeroMoments) {
  std::vector<LinkInertia> links = urdf_link_inertias(one_link_urdf(
      "      <mass value=\"1e-6\"/>\n      <inertia ixx=\"1e-6\" ixy=\"1e-6\" ixz=\"1e-6\" iyy=\"1e-6\" iyz=\"1e-6\" izz=\"1e-6\"/>\n"));
  ASSERT_EQ(links.size(), 1u);
  Triple m = links[0].principal;
  std::sort(m.begin(), m.end());
  EXPECT_EQ(m[0], 0.0);
  EXPECT_EQ(m[1], 0.0);
  EXPECT_NEAR(m[2], 3e-6, 1e-20);
  EXPECT_TRUE(links[0].unbalanced);
}

TEST(UnbalancedInertias, OnlyTheRefusalTurnsBalancingOn) {
  EXPECT_TRUE(refuses_unbalanced_inertia("Error: inertia must satisfy A + B >= C; use 'balanceinertia' to fix\nObject name = arm"));
  EXPECT_FALSE(refuses_unbalanced_inertia("Error: mass and inertia cannot be negative"));
  EXPECT_EQ(with_balanced_inertias("<robot name=\"r\"><mujoco><compiler fusestatic=\"false\"/></mujoco></robot>"),
            "<robot name=\"r\"><mujoco><compiler balanceinertia=\"true\" fusestatic=\"false\"/></mujoco></robot>");
  std::string own = "<robot name=\"r\"><mujoco><compiler balanceinertia=\"false\"/></mujoco></robot>";
  EXPECT_EQ(with_balanced_inertias(own), own) << "a file's own choice stands";
}

// a pendulum about z whose body has the moments given: what the model file says of them
std::string pendulum_with_moments(const std::string& moments, const std::string& flag) {
  return "[model]\nname = \"pendulum\"\n\n[parameters]\ng = 9.81\n\n[coordinates]\nphi = { initial = 0.1, rate = 0 }\n\n"
         "[[rigid_bodies]]\nname = \"bob\"\nmass = \"2\"\ncenter = [\"0.3*sin(phi)\", \"-0.3*cos(phi)\", \"0\"]\n"
         "rotation = \"rot_z(phi)\"\ninertia = " + moments + "\n" + flag + "\n[gravity]\nacceleration = [\"0\", \"-g\", \"0\"]\n";
}

std::string pendulum_model_errors(const std::string& text) {
  Diagnostics d;
  ModelFile file = parse_model_text(text, "pendulum.toml", d);
  if (d.empty()) build_model(file, d);
  return d.format();
}

TEST(UnbalancedInertias, TheModelFileTakesAnUnphysicalInertiaOnlyWhenToldTo) {
  const std::string unbalanced = "[\"0.006\", \"0.006\", \"0.06\"]", negative = "[\"0.006\", \"-1e-9\", \"0.006\"]";
  EXPECT_NE(pendulum_model_errors(pendulum_with_moments(unbalanced, "")).find("no rigid body has this inertia"), std::string::npos);
  EXPECT_NE(pendulum_model_errors(pendulum_with_moments(negative, "")).find("must not be negative"), std::string::npos);
  EXPECT_EQ(pendulum_model_errors(pendulum_with_moments(unbalanced, "unphysical_inertia = true")), "");
  EXPECT_EQ(pendulum_model_errors(pendulum_with_moments(negative, "unphysical_inertia = true")), "");
  EXPECT_NE(pendulum_model_errors(pendulum_with_moments(unbalanced, "unphysical_inertia = \"yes\"")).find("expected true or false"), std::string::npos);
  // M = Izz + m s² about the pivot, the moments as written
  Equations e = derive_text(pendulum_with_moments(unbalanced, "unphysical_inertia = true"));
  EXPECT_NEAR(value_at(e.mass_matrix(0, 0), point_by_name(e, {{"phi", 0.4}, {"der(phi)", 0.2}, {"g", 9.81}})), 0.06 + 2 * 0.09, 1e-15);
}

}  // namespace
}  // namespace eomgen::test
