// MuJoCo 3's kv and dampratio on a position servo (generator/import/servo_damping.hpp), which MuJoCo
// 2.2.2 refuses: read through the actuators' user values, which MuJoCo resolves through defaults and
// classes, so that the import equals that of the file MuJoCo 2.2.2 reads with the same servos written
// as <general> actuators with the velocity's bias, a damping ratio's gain being the one that the
// mass matrix at qpos0, worked out by hand here, gives; a file with user values of its own keeps them
// and its kv is left out with a warning.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "import/model_writer.hpp"
#include "import/servo_damping.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

TEST(ServoDamping, OnlyAPositionServosKvIsReadAsItsUserValue) {
  EXPECT_TRUE(refuses_position_damping("Error: Schema violation: unrecognized attribute: 'kv'\nElement 'position', line 4\n"));
  EXPECT_FALSE(refuses_position_damping("Error: Schema violation: unrecognized attribute: 'kv'\nElement 'motor', line 4\n"));
  EXPECT_EQ(with_servo_damping_as_user("<default><position kp=\"4\" kv='0.5'/></default>\n<!-- <position kv=\"1\"/> -->\n"
                            "<velocity kv=\"2\"/><position\n  joint=\"a\" kv=\"3\"/>"),
            "<default><position kp=\"4\" user='0.5'/></default>\n<!-- <position kv=\"1\"/> -->\n"
            "<velocity kv=\"2\"/><position\n  joint=\"a\" user=\"3\"/>");
  EXPECT_TRUE(refuses_position_damping("Error: Schema violation: unrecognized attribute: 'dampratio'\nElement 'position', line 4\n"));
  EXPECT_EQ(with_servo_damping_as_user("<position kp=\"4\" dampratio=' 0.5'/>\n<position joint=\"a\" dampratio=\"1\" kp=\"2\"/>"),
            "<position kp=\"4\" user=' -0.5'/>\n<position joint=\"a\" user=\"-1\" kp=\"2\"/>")
      << "a damping ratio is the user value's negative";
  EXPECT_EQ(with_servo_damping_as_user("<position dampratio=\"-1\"/>"), std::nullopt) << "MuJoCo 3 refuses a negative ratio";
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
  EXPECT_NE(noted.find("# note: the position servos' kv and dampratio (MuJoCo 3's velocity gain, and that gain as the damping ratio"), std::string::npos) << noted;
}

// the number written just before `term` in the text's forces (its first occurrence), or NaN
double coefficient_before(const std::string& text, const std::string& term) {
  std::size_t at = text.find(term, text.find("[[forces]]"));
  if (at == std::string::npos) return std::nan("");
  std::size_t start = text.find_last_of(" (", at - 1) + 1;
  return std::strtod(text.substr(start, at - start).c_str(), nullptr);
}

// kv = 2 ζ sqrt(kp m), m the servo's reflected inertia at qpos0 (MuJoCo 3's mj_setConst): the
// shoulder sees the armature 0.01, the upper link's 0.01 + 1·0.2² and the lower's 0.005 + 0.5·0.6²
// about its axis; the elbow the lower link's 0.005 + 0.5·0.2² about its oblique axis (the centre
// on the axis's normal), over its gear's square; a tendon the sum over its joints of M_ii over
// its coefficients' squares. The joint's damping is gear² kv.
TEST(ServoDamping, ADampingRatioGivesTheGainOfTheInertiaAtTheInitialPose) {
  const std::string newer = R"(<mujoco model="ratios">
  <default><default class="arm"><position kp="40" dampratio="0.5" ctrlrange="-1 1" ctrllimited="true"/></default></default>
  <worldbody>
    <body name="upper" pos="0 0 1">
      <joint name="shoulder" axis="0 1 0" armature="0.01"/>
      <inertial pos="0 0 -0.2" mass="1" diaginertia="0.01 0.01 0.001"/>
      <body name="lower" pos="0 0 -0.4">
        <joint name="elbow" axis="0.3 1 0"/>
        <joint name="reach" type="slide" axis="0 0 1"/>
        <inertial pos="0 0 -0.2" mass="0.5" diaginertia="0.005 0.005 0.001"/>
      </body>
    </body>
  </worldbody>
  <tendon><fixed name="both"><joint joint="reach" coef="1"/><joint joint="elbow" coef="0.5"/></fixed></tendon>
  <actuator>
    <position name="lift" joint="shoulder" class="arm"/>
    <position name="bend" joint="elbow" kp="15" dampratio="1" gear="2"/>
    <position name="pull" tendon="both" kp="10" class="arm" dampratio="2"/>
  </actuator>
</mujoco>
)";
  Diagnostics diagnostics;
  std::string read = imported_servos("ratios", newer, diagnostics);
  ASSERT_FALSE(read.empty()) << diagnostics.format();
  const double shoulder = 0.01 + (0.01 + 1 * 0.04) + (0.005 + 0.5 * 0.36), elbow = 0.005 + 0.5 * 0.04, reach = 0.5;
  EXPECT_NEAR(coefficient_before(read, "*der(shoulder)"), 2 * 0.5 * std::sqrt(40 * shoulder), 1e-14) << read;
  EXPECT_NEAR(coefficient_before(read, "*der(elbow)"), 4 * 2 * 1 * std::sqrt(15 * elbow / 4), 1e-14) << read;
  EXPECT_NEAR(coefficient_before(read, "*(der(reach)"), 2 * 2 * std::sqrt(10 * (reach + elbow / 0.25)), 1e-14)
      << "the actuator's own ratio over its class's: " << read;
}

// MuJoCo 3 reads biasprm[2] > 0 of any position-like actuator (gain = −bias₁) as a damping ratio, a
// <general> one too: the same model as the <position dampratio> servos above, which take the user
// values' way; a velocity coefficient of zero or below stays a gain.
TEST(ServoDamping, APositiveVelocityCoefficientOfAPositionLikeActuatorIsItsDampingRatio) {
  const std::string position = servo_file("", R"(
    <position name="lift" joint="shoulder" kp="40" dampratio="0.5"/>
    <position name="bend" joint="elbow" kp="15" dampratio="1" gear="2"/>
    <position name="push" joint="reach" kp="10"/>)");
  const std::string general = servo_file("", R"(
    <general name="lift" joint="shoulder" gainprm="40" biasprm="0 -40 0.5" biastype="affine"/>
    <general name="bend" joint="elbow" gainprm="15" biasprm="0 -15 1" biastype="affine" gear="2"/>
    <general name="push" joint="reach" gainprm="10" biasprm="0 -10 -3" biastype="affine"/>)");
  Diagnostics diagnostics;
  std::string from_position = imported_servos("from_position", position, diagnostics, true);
  std::string from_general = imported_servos("from_general", general, diagnostics, true);
  ASSERT_FALSE(from_position.empty() || from_general.empty()) << diagnostics.format();
  EXPECT_NE(from_general.find("# note: 2 actuator(s) of a position servo's shape with a positive velocity coefficient ('lift', "
                              "'bend') read as MuJoCo 3 reads them"),
            std::string::npos)
      << from_general;
  EXPECT_NE(from_position.find("*der(shoulder)"), std::string::npos) << from_position;
  EXPECT_NEAR(coefficient_before(from_general, "*der(reach)"), 3, 1e-15) << "a gain kv = 3: " << from_general;
  std::string position_with_gain = imported_servos("from_position", servo_file("", R"(
    <position name="lift" joint="shoulder" kp="40" dampratio="0.5"/>
    <position name="bend" joint="elbow" kp="15" dampratio="1" gear="2"/>
    <position name="push" joint="reach" kp="10" kv="3"/>)"), diagnostics);
  EXPECT_EQ(without_lines_starting(from_general, "#"), without_lines_starting(position_with_gain, "#"));
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
