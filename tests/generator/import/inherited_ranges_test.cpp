// MuJoCo 3's inheritrange on a position servo (generator/import/inherited_ranges.hpp), which MuJoCo 2.2.2
// refuses: read through the actuators' group, which MuJoCo resolves through defaults and classes, so
// that the import equals that of the file MuJoCo 2.2.2 reads with the control ranges written out; a
// fractional value, or a file with groups of its own, leaves it out with a warning.
#include <gtest/gtest.h>

#include <string>

#include "import/inherited_ranges.hpp"
#include "import/model_writer.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

TEST(InheritedRanges, AWholeValueIsWrittenAsTheGroup) {
  EXPECT_TRUE(refuses_inheritrange("Error: Schema violation: unrecognized attribute: 'inheritrange'\nElement 'position', line 4\n"));
  EXPECT_FALSE(refuses_inheritrange("Error: Schema violation: unrecognized attribute: 'inheritrange'\nElement 'joint', line 4\n"));
  EXPECT_EQ(with_inheritrange_as_group("<default><position kp=\"4\" inheritrange='1.0'/></default>\n"
                                       "<!-- <position inheritrange=\"0.5\"/> --><position joint=\"a\" inheritrange=\"2\"/>"),
            "<default><position kp=\"4\" group=\"1\"/></default>\n"
            "<!-- <position inheritrange=\"0.5\"/> --><position joint=\"a\" group=\"2\"/>");
  EXPECT_FALSE(with_inheritrange_as_group("<position joint=\"a\" inheritrange=\"0.9\"/>")) << "a group is a whole number";
  EXPECT_FALSE(with_inheritrange_as_group("<motor joint=\"b\" group=\"3\"/><position joint=\"a\" inheritrange=\"1\"/>"))
      << "the file's own groups";
}

// two hinges with ranges and a fixed tendon with one, driven by `actuators`, with `defaults`
std::string ranged_file(const std::string& defaults, const std::string& actuators) {
  return R"(<mujoco model="ranges">
  <compiler angle="radian"/>
  <default>)" + defaults + R"(</default>
  <worldbody>
    <body name="upper" pos="0 0 1">
      <joint name="hip" axis="0 1 0" limited="true" range="-1 2"/>
      <inertial pos="0 0 -0.2" mass="1" diaginertia="0.01 0.01 0.001"/>
      <body name="lower" pos="0 0 -0.4">
        <joint name="knee" axis="1 0 0" limited="true" range="-2 0"/>
        <joint name="free_turn" axis="0 0 1"/>
        <inertial pos="0 0 -0.2" mass="0.5" diaginertia="0.005 0.005 0.001"/>
      </body>
    </body>
  </worldbody>
  <tendon><fixed name="both" limited="true" range="0 0.4"><joint joint="hip" coef="1"/><joint joint="knee" coef="0.5"/></fixed></tendon>
  <actuator>)" + actuators + R"(
  </actuator>
</mujoco>
)";
}

// the imported text, its file's name and its notes aside
std::string imported_ranges(const std::string& name, const std::string& file) {
  Diagnostics diagnostics;
  std::string text = imported_robot(name + ".xml", file, diagnostics).value_or("");
  EXPECT_FALSE(text.empty()) << diagnostics.format();
  if (std::size_t at = text.find(name + ".xml"); at != std::string::npos) text.replace(at, name.size() + 4, "ranges.xml");
  return without_lines_starting(text, "# note: ");
}

TEST(InheritedRanges, ServosTakeTheirJointsOrTendonsRangeThroughDefaultsAndClasses) {
  std::string newer = imported_ranges("newer_ranges", ranged_file(R"(<default class="arm"><position kp="40" kv="3" inheritrange="1"/></default>)", R"(
    <position name="lift" joint="hip" class="arm"/>
    <position name="bend" joint="knee" class="arm" inheritrange="2"/>
    <position name="pull" tendon="both" class="arm"/>
    <motor name="turn" joint="free_turn" class="arm"/>)"));
  std::string older = imported_ranges("older_ranges", ranged_file("", R"(
    <general name="lift" joint="hip" gainprm="40" biastype="affine" biasprm="0 -40 -3" ctrllimited="true" ctrlrange="-1 2"/>
    <general name="bend" joint="knee" gainprm="40" biastype="affine" biasprm="0 -40 -3" ctrllimited="true" ctrlrange="-3 1"/>
    <general name="pull" tendon="both" gainprm="40" biastype="affine" biasprm="0 -40 -3" ctrllimited="true" ctrlrange="0 0.4"/>
    <motor name="turn" joint="free_turn"/>)"));
  EXPECT_EQ(newer, older) << "with kv in the same class";
  EXPECT_NE(older.find("clamp(lift, -1, 2)"), std::string::npos) << older;
}

TEST(InheritedRanges, WhatCannotBeInheritedIsWarnedOf) {
  std::string no_range = imported_ranges("no_range", ranged_file("", R"(
    <position name="spin" joint="free_turn" kp="5" inheritrange="1"/>)"));
  EXPECT_NE(no_range.find("# not carried: actuator 'spin': inheritrange: its joint or tendon has no range"), std::string::npos) << no_range;
  EXPECT_EQ(no_range.find("clamp(spin"), std::string::npos) << no_range;
  std::string fraction = imported_ranges("fraction", ranged_file("", R"(
    <position name="lift" joint="hip" kp="5" inheritrange="0.9"/>)"));
  EXPECT_NE(fraction.find("# not carried: 'inheritrange'"), std::string::npos) << fraction;
  EXPECT_EQ(fraction.find("clamp(lift"), std::string::npos) << fraction;
}

}  // namespace
}  // namespace eomgen::test
