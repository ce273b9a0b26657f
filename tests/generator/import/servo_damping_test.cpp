// MuJoCo 3's kv on a position servo (generator/import/servo_damping.hpp), which MuJoCo 2.2.2 refuses:
// read through the actuators' user values, which MuJoCo resolves through defaults and classes, so
// that the import equals that of the file MuJoCo 2.2.2 reads with the same servos written as
// <general> actuators with the velocity's bias; a file with user values of its own keeps them and
// its kv is left out with a warning.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "import/model_writer.hpp"
#include "import/servo_damping.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

TEST(ServoDamping, OnlyAPositionServosKvIsReadAsItsUserValue) {
  EXPECT_TRUE(refuses_position_kv("Error: Schema violation: unrecognized attribute: 'kv'\nElement 'position', line 4\n"));
  EXPECT_FALSE(refuses_position_kv("Error: Schema violation: unrecognized attribute: 'kv'\nElement 'motor', line 4\n"));
  EXPECT_EQ(with_kv_as_user("<default><position kp=\"4\" kv='0.5'/></default>\n<!-- <position kv=\"1\"/> -->\n"
                            "<velocity kv=\"2\"/><position\n  joint=\"a\" kv=\"3\"/>"),
            "<default><position kp=\"4\" user='0.5'/></default>\n<!-- <position kv=\"1\"/> -->\n"
            "<velocity kv=\"2\"/><position\n  joint=\"a\" user=\"3\"/>");
  EXPECT_TRUE(has_actuator_user_values("<mujoco>\n<general joint=\"a\" user=\"1 2\"/>"));
  EXPECT_FALSE(has_actuator_user_values("<size nuser_actuator=\"2\"/><!-- <motor user=\"1\"/> --><motor joint=\"a\"/>"));
  EXPECT_FALSE(has_actuator_user_values("<joint name=\"a\" user=\"1\"/>")) << "a joint's user values are another array";
}

// two hinges and a slide driven by `actuators`, with `defaults`
std::string servo_file(const std::string& defaults, const std::string& actuators) {
  return R"(<mujoco model="servos">
  <default>)" + defaults + R"(</default>
  <worldbody>
    <body name="upper" pos="0 0 1">
      <joint name="shoulder" axis="0 1 0"/>
      <inertial pos="0 0 -0.2" mass="1" diaginertia="0.01 0.01 0.001"/>
      <body name="lower" pos="0 0 -0.4">
        <joint name="elbow" axis="0.3 1 0"/>
        <joint name="reach" type="slide" axis="0 0 1"/>
        <inertial pos="0 0 -0.2" mass="0.5" diaginertia="0.005 0.005 0.001"/>
      </body>
    </body>
  </worldbody>
  <actuator>)" + actuators + R"(
  </actuator>
</mujoco>
)";
}

std::string imported_servos(const std::string& name, const std::string& file, Diagnostics& diagnostics, bool notes = false) {
  std::string text = imported_robot(name + ".xml", file, diagnostics).value_or("");
  // the file's name and the notes aside
  if (std::size_t at = text.find(name + ".xml"); at != std::string::npos) text.replace(at, name.size() + 4, "servos.xml");
  return notes ? text : without_lines_starting(text, "# note: ");
}

TEST(ServoDamping, KvThroughDefaultsAndClassesIsTheVelocitysBias) {
  const std::string newer = servo_file(R"(<default class="arm"><position kp="40" kv="4" ctrlrange="-1 1" ctrllimited="true"/></default>)",
                                       R"(
    <position name="lift" joint="shoulder" class="arm"/>
    <position name="bend" joint="elbow" kp="15" kv="1.5"/>
    <velocity name="push" joint="reach" kv="2"/>
    <motor name="twist" joint="elbow" gear="3"/>)");
  const std::string older = servo_file("", R"(
    <general name="lift" joint="shoulder" gainprm="40" biastype="affine" biasprm="0 -40 -4" ctrlrange="-1 1" ctrllimited="true"/>
    <general name="bend" joint="elbow" gainprm="15" biastype="affine" biasprm="0 -15 -1.5"/>
    <velocity name="push" joint="reach" kv="2"/>
    <motor name="twist" joint="elbow" gear="3"/>)");
  Diagnostics diagnostics;
  std::string read = imported_servos("newer_servos", newer, diagnostics);
  ASSERT_FALSE(read.empty()) << diagnostics.format();
  EXPECT_EQ(read, imported_servos("older_servos", older, diagnostics));
  EXPECT_NE(read.find("der(shoulder)"), std::string::npos) << "the servo's damping: " << read;
  std::string noted = imported_servos("newer_servos", newer, diagnostics, true);
  EXPECT_NE(noted.find("# note: the position servos' kv (MuJoCo 3's velocity gain) read through"), std::string::npos) << noted;
}

TEST(ServoDamping, AFileWithUserValuesOfItsOwnLeavesKvOut) {
  const std::string newer = servo_file("", R"(
    <position name="lift" joint="shoulder" kp="40" kv="4" user="9"/>)");
  Diagnostics diagnostics;
  std::string read = imported_servos("own_user", newer, diagnostics);
  ASSERT_FALSE(read.empty()) << diagnostics.format();
  EXPECT_NE(read.find("# not carried: 'kv'"), std::string::npos) << read;
  EXPECT_EQ(read.find("der(shoulder)"), std::string::npos) << read;
}

}  // namespace
}  // namespace eomgen::test
