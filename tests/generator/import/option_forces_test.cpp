// A file's <option> flags that switch forces off (generator/import/option_forces.hpp): the model
// imported without them, each with a note, and a medium warned of; the motion against MuJoCo's is
// tests/crosscheck/mjcf/switched_off_forces.xml in the MuJoCo oracle test.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "import/model_writer.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

// a pendulum with a damped spring on its joint and a motor with a control range, under `option`
std::string sprung_pendulum_file(const std::string& option) {
  return "<mujoco model=\"flags\">\n  " + option + R"(
  <worldbody>
    <body name="arm" pos="0 0 1">
      <joint name="swing" axis="0 1 0" damping="0.5" stiffness="2"/>
      <inertial pos="0 0 -0.2" mass="1" diaginertia="0.01 0.01 0.001"/>
    </body>
  </worldbody>
  <actuator><motor name="drive" joint="swing" gear="3" ctrlrange="-1 1" ctrllimited="true"/></actuator>
</mujoco>
)";
}

std::string imported_with(const std::string& option) {
  std::string path = temporary_directory() + "/flags.xml";
  std::ofstream(path) << sprung_pendulum_file(option);
  Diagnostics diagnostics;
  std::optional<std::string> text = imported_model_text(path, diagnostics, false);
  EXPECT_TRUE(text) << diagnostics.format();
  return text.value_or("");
}

bool mentions(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(OptionForces, WithNoFlagEveryForceIsCarried) {
  std::string text = imported_with("<option/>");
  EXPECT_TRUE(mentions(text, "acceleration = [\"0\", \"0\", \"-9.81\"]")) << text;
  EXPECT_TRUE(mentions(text, "der(swing)^2")) << text;
  EXPECT_TRUE(mentions(text, "potential = \"(2*swing^2)/2\"")) << text;
  EXPECT_TRUE(mentions(text, "3*clamp(drive, -1, 1)")) << text;
  EXPECT_FALSE(mentions(text, "switched off")) << text;
}

TEST(OptionForces, GravityAndClampingSwitchedOffAreLeftOut) {
  std::string text = imported_with("<option><flag gravity=\"disable\" clampctrl=\"disable\"/></option>");
  EXPECT_TRUE(mentions(text, "acceleration = [\"0\", \"0\", \"0\"]")) << text;
  EXPECT_TRUE(mentions(text, "# note: gravity is switched off")) << text;
  EXPECT_FALSE(mentions(text, "clamp(")) << text;
  EXPECT_TRUE(mentions(text, "3*drive")) << text;
  EXPECT_TRUE(mentions(text, "# note: control clamping is switched off")) << text;
  EXPECT_TRUE(mentions(text, "der(swing)^2")) << "the damper stays: " << text;
}

TEST(OptionForces, PassiveForcesAndActuationSwitchedOffAreLeftOut) {
  std::string text = imported_with("<option density=\"1.2\"><flag passive=\"disable\" actuation=\"disable\"/></option>");
  EXPECT_FALSE(mentions(text, "der(swing)^2")) << text;
  EXPECT_FALSE(mentions(text, "swing^2)/2")) << text;
  EXPECT_FALSE(mentions(text, "[inputs]")) << text;
  EXPECT_FALSE(mentions(text, "drive")) << text;
  EXPECT_TRUE(mentions(text, "springs and dampers of 1 joint(s) and 0 tendon(s), and the medium's forces, are not carried")) << text;
  EXPECT_TRUE(mentions(text, "its 1 actuator(s) are not imported")) << text;
  EXPECT_FALSE(mentions(text, "# not carried: the medium")) << "passive forces off: no medium acts" << text;
}

TEST(OptionForces, AMediumIsWarnedOf) {
  std::string text = imported_with("<option density=\"1000\" viscosity=\"0.001\"/>");
  EXPECT_TRUE(mentions(text, "# not carried: the medium of <option density=\"1000\" viscosity=\"0.001\">")) << text;
}

}  // namespace
}  // namespace eomgen::test
