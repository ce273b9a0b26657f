// Numbers at the size of double rounding in robot files are taken as zero at import
// (generator/import/rounding_noise.hpp): cos(π/2) printed as 6.12323e-17 in an axis, offsets far
// below the robot's size, a quaternion's 2e-17 beside 0.7, moments of 1e-35 on a body of a
// kilogram; numbers of the robot's own are kept, however small; and an arm written with such
// noise imports to the model of the same arm written without it, with MuJoCo's dynamics.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include <mujoco/mujoco.h>

#include "import/model_writer.hpp"
#include "import/rounding_noise.hpp"
#include "support/mujoco_dynamics.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

TEST(RoundingNoise, NumbersAtRoundingsSizeOfTheirScaleAreZeroAndOthersStay) {
  Robot r;
  RobotBody upper;
  upper.position = {0.032, -2.67276e-51, 0.3};
  upper.orientation = {0.7071054825112364, -0.7071080798594737, 2.1648927039189623e-17, -2.1648847518386393e-17};
  upper.mass = 1.33687;
  upper.center = {4.33681e-19, 0.0185, 1e-12};
  upper.principal_inertia = {-2.40741e-35, 0, 2.40741e-35};
  RobotJoint hinge;
  hinge.type = "hinge";
  hinge.axis = {0, -1, 6.12323e-17};
  upper.joints.push_back(hinge);
  RobotBody screw;
  screw.parent = 0;
  screw.position = {0, 0, 1e-13};
  screw.mass = 1e-3;
  screw.principal_inertia = {1e-9, 1e-9, 3e-15};
  hinge.axis = {0.6, 0.8, 1e-14};
  screw.joints.push_back(hinge);
  r.bodies = {upper, screw};
  RoundingNoise noise = without_rounding_noise(r);
  EXPECT_EQ(noise.numbers, 7);
  EXPECT_LE(noise.largest, 8.0);
  const RobotBody& a = r.bodies[0];
  EXPECT_EQ(a.position, (Triple{0.032, 0, 0.3}));
  EXPECT_EQ(a.orientation, (Quaternion{0.7071054825112364, -0.7071080798594737, 0, 0})) << "1.5708 rad, not π/2: as read";
  EXPECT_EQ(a.center, (Triple{0, 0.0185, 1e-12})) << "1e-12 m is 4500 units of rounding of the robot's 0.3 m";
  EXPECT_EQ(a.principal_inertia, (Triple{0, 0, 0}));
  EXPECT_EQ(a.joints[0].axis, (Triple{0, -1, 0}));
  const RobotBody& b = r.bodies[1];
  EXPECT_EQ(b.position, (Triple{0, 0, 1e-13})) << "450 units of rounding of 0.3 m";
  EXPECT_EQ(b.principal_inertia, (Triple{1e-9, 1e-9, 3e-15})) << "a gram's moments, above its mass times the size squared's rounding";
  EXPECT_EQ(b.joints[0].axis, (Triple{0.6, 0.8, 1e-14})) << "45 units of rounding: an axis of the file's";
  Robot empty;
  EXPECT_EQ(without_rounding_noise(empty).numbers, 0);
}

// an elbow about the y axis as iCub's URDF writes it (cos(π/2) to six digits in the axis, sin(π)
// in an origin) and a wrist about x, with `noise` or with exact zeros
std::string rounded_elbow_arm(bool noise) {
  std::string tiny_axis = noise ? "6.12323e-17" : "0", tiny_origin = noise ? "-1.36916e-17" : "0",
              tiny_centre = noise ? "4.33681e-19" : "0";
  return R"(<?xml version="1.0"?>
<robot name="rounded_elbow_arm">
  <link name="base"/>
  <link name="upper">
    <inertial><origin xyz=")" + tiny_centre + R"( 0.01 -0.12"/><mass value="1.9"/><inertia ixx="0.021" ixy="0" ixz="0" iyy="0.019" iyz="0" izz="0.004"/></inertial>
  </link>
  <link name="fore">
    <inertial><origin xyz="0.01 0 -0.1"/><mass value="1.2"/><inertia ixx="0.009" ixy="0.0004" ixz="0" iyy="0.008" iyz="0" izz="0.002"/></inertial>
  </link>
  <joint name="shoulder" type="revolute">
    <parent link="base"/><child link="upper"/><origin xyz="0 0 0.5"/><axis xyz="0 -1 )" + tiny_axis + R"("/>
    <limit lower="-2" upper="2" effort="50" velocity="2"/>
  </joint>
  <joint name="elbow" type="revolute">
    <parent link="upper"/><child link="fore"/><origin xyz="0 )" + tiny_origin + R"( -0.2236"/><axis xyz="1 0 )" + tiny_axis + R"("/>
    <limit lower="-2" upper="2" effort="50" velocity="2"/>
  </joint>
</robot>
)";
}

TEST(RoundingNoise, AnArmWrittenWithRoundingNoiseImportsAsWithoutIt) {
  Diagnostics d;
  std::string noisy_path = write_file("rounded_elbow_arm.urdf", rounded_elbow_arm(true));
  auto noisy = imported_model_text(noisy_path, d, false);
  auto clean = imported_model_text(write_file("exact_elbow_arm.urdf", rounded_elbow_arm(false)), d, false);
  ASSERT_TRUE(noisy && clean) << d.format();
  std::size_t note = noisy->find("# note: 4 number(s) at the size of double rounding taken as zero");
  ASSERT_NE(note, std::string::npos) << *noisy;
  std::string without_note = noisy->substr(0, note) + noisy->substr(noisy->find('\n', note) + 1);
  std::string renamed = *clean;
  for (std::size_t at; (at = renamed.find("exact_elbow_arm.urdf")) != std::string::npos;)
    renamed.replace(at, 20, "rounded_elbow_arm.urdf");
  EXPECT_EQ(without_note, renamed);
  EXPECT_NE(noisy->find("axis = [\"0\", \"-1\", \"0\"]"), std::string::npos) << *noisy;
  EXPECT_NE(noisy->find("axis = [\"1\", \"0\", \"0\"]"), std::string::npos) << *noisy;
  Equations e = derive_text(*noisy, "rounded_elbow_arm.toml");
  char error[1000] = "";
  std::unique_ptr<mjModel, void (*)(mjModel*)> m(mj_loadXML(noisy_path.c_str(), nullptr, error, sizeof error), mj_deleteModel);
  ASSERT_TRUE(m) << error;
  expect_mujoco_dynamics(e, m.get(), {"shoulder", "elbow"}, 3, 1e-15, 1e-14);
}

}  // namespace
}  // namespace eomgen::test
