// A file's <option> flags that switch forces off (generator/import/option_forces.hpp): the model
// imported without them, each with a note, and a medium warned of; the motion against MuJoCo's is
// tests/crosscheck/mjcf/switched_off_forces.xml in the MuJoCo oracle test. MuJoCo 3.3.6's spring and
// damper flags (generator/import/passive_flags.hpp), which MuJoCo 2.2.2 cannot read, are checked
// against files it reads that say the same: the springs or dampers left out, or passive="disable".
#include <gtest/gtest.h>

#include <string>

#include "import/model_writer.hpp"
#include "import/passive_flags.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

// a pendulum with a damped spring on its joint and a motor with a control range, under `option`
std::string sprung_pendulum_file(const std::string& option, const std::string& joint = R"(damping="0.5" stiffness="2")") {
  return "<mujoco model=\"flags\">\n  " + option + R"(
  <worldbody>
    <body name="arm" pos="0 0 1">
      <joint name="swing" axis="0 1 0" )" + joint + R"(/>
      <inertial pos="0 0 -0.2" mass="1" diaginertia="0.01 0.01 0.001"/>
    </body>
  </worldbody>
  <actuator><motor name="drive" joint="swing" gear="3" ctrlrange="-1 1" ctrllimited="true"/></actuator>
</mujoco>
)";
}

std::string imported_file(const std::string& file) { return imported_robot_text("flags.xml", file); }

std::string imported_with(const std::string& option) { return imported_file(sprung_pendulum_file(option)); }

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

// the model text without its notes, which say what the file switched off and how
std::string without_notes(std::string text) {
  for (std::size_t at = text.find("# note: "); at != std::string::npos; at = text.find("# note: ", at))
    text.erase(at, text.find('\n', at) + 1 - at);
  return text;
}

TEST(PassiveFlags, TheTwoFlagsAreWrittenAsMujoco22ReadsThem) {
  std::string text = "<option>\n  <flag gravity=\"disable\" spring=\"disable\"\n        damper='disable'/>\n</option>\n";
  PassiveSwitches both = translate_passive_flags(text);
  EXPECT_TRUE(both.springs_off && both.dampers_off);
  EXPECT_EQ(text, "<option>\n  <flag passive=\"disable\" gravity=\"disable\" \n        />\n</option>\n");
  std::string one = "<option><flag spring=\"enable\" damper=\"disable\"/></option>";
  PassiveSwitches dampers = translate_passive_flags(one);
  EXPECT_FALSE(dampers.springs_off);
  EXPECT_TRUE(dampers.dampers_off);
  EXPECT_EQ(one, "<option><flag  /></option>") << "one flag off: no passive, the import takes the dampers off";
  std::string none = "<joint springref=\"1\" springdamper=\"1 1\"/><!-- <flag spring=\"disable\"/> -->";
  EXPECT_FALSE(translate_passive_flags(none).springs_off) << "other attributes and comments are not flags";
  EXPECT_EQ(none, "<joint springref=\"1\" springdamper=\"1 1\"/><!-- <flag spring=\"disable\"/> -->");
  EXPECT_TRUE(refuses_passive_flag("Error: Schema violation: unrecognized attribute: 'damper'\nElement 'flag', line 2\n"));
  EXPECT_FALSE(refuses_passive_flag("Error: Schema violation: unrecognized attribute: 'spring'\nElement 'joint', line 5\n"))
      << "a spring on a joint is a mistake, which stays MuJoCo's error";
}

TEST(PassiveFlags, ASpringFlagTakesOffTheSpringsAsAFileWithoutThemSays) {
  std::string flagged = imported_with("<option><flag spring=\"disable\"/></option>");
  EXPECT_TRUE(mentions(flagged, "# note: springs are switched off in the file (<flag spring=\"disable\"/>): the springs of 1 "
                                "joint(s) and 0 tendon(s) are not carried"))
      << flagged;
  EXPECT_TRUE(mentions(flagged, "der(swing)^2")) << "the damper stays: " << flagged;
  EXPECT_EQ(without_notes(flagged), imported_file(sprung_pendulum_file("<option/>", R"(damping="0.5")")));
}

TEST(PassiveFlags, ADamperFlagTakesOffTheDampersAndTheMediumStays) {
  std::string flagged = imported_with("<option density=\"1.2\"><flag damper=\"disable\"/></option>");
  EXPECT_TRUE(mentions(flagged, "# note: dampers are switched off in the file (<flag damper=\"disable\"/>)")) << flagged;
  EXPECT_TRUE(mentions(flagged, "# not carried: the medium of <option density=\"1.2\"")) << "one flag leaves the medium: " << flagged;
  EXPECT_EQ(without_notes(flagged), imported_file(sprung_pendulum_file("<option density=\"1.2\"/>", R"(stiffness="2")")));
}

TEST(PassiveFlags, BothFlagsOffAreMujoco22sPassiveDisable) {
  std::string flagged = imported_with("<option density=\"1.2\"><flag spring=\"disable\" damper=\"disable\"/></option>");
  EXPECT_TRUE(mentions(flagged, "(<flag spring=\"disable\" damper=\"disable\"/>): the springs and dampers of 1 joint(s) and 0 "
                                "tendon(s), and the medium's forces, are not carried"))
      << flagged;
  EXPECT_EQ(without_notes(flagged), without_notes(imported_with("<option density=\"1.2\"><flag passive=\"disable\"/></option>")));
}

// two hinges whose fixed tendon has `tendon` (a spring and a damper), the first hinge `damper`
std::string tendon_file(const std::string& option, const std::string& tendon, const std::string& damper) {
  return "<mujoco model=\"flags\">\n  " + option + R"(
  <worldbody>
    <body name="upper" pos="0 0 1">
      <joint name="a" axis="0 1 0" )" + damper + R"(/>
      <inertial pos="0 0 -0.2" mass="1" diaginertia="0.01 0.01 0.001"/>
      <body name="lower" pos="0 0 -0.4">
        <joint name="b" axis="0 1 0"/>
        <inertial pos="0 0 -0.2" mass="0.5" diaginertia="0.005 0.005 0.001"/>
      </body>
    </body>
  </worldbody>
  <tendon><fixed name="t" )" + tendon + R"(><joint joint="a" coef="1"/><joint joint="b" coef="-0.5"/></fixed></tendon>
</mujoco>
)";
}

TEST(PassiveFlags, ATendonsSpringAndDamperFollowTheirFlags) {
  const std::string both = R"(stiffness="4" damping="0.2")", damper = R"(damping="0.3")";
  std::string springs_off = imported_file(tendon_file("<option><flag spring=\"disable\"/></option>", both, damper));
  EXPECT_TRUE(mentions(springs_off, "the springs of 0 joint(s) and 1 tendon(s) are not carried")) << springs_off;
  EXPECT_EQ(without_notes(springs_off), imported_file(tendon_file("<option/>", R"(damping="0.2")", damper)));
  std::string dampers_off = imported_file(tendon_file("<option><flag damper=\"disable\"/></option>", both, damper));
  EXPECT_TRUE(mentions(dampers_off, "the dampers of 1 joint(s) and 1 tendon(s) are not carried")) << dampers_off;
  EXPECT_EQ(without_notes(dampers_off), imported_file(tendon_file("<option/>", R"(stiffness="4")", "")));
  EXPECT_NE(without_notes(dampers_off), imported_file(tendon_file("<option/>", both, damper))) << "the flag changes the model";
}

}  // namespace
}  // namespace eomgen::test
