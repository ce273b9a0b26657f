// MuJoCo 3's default autolimits="true" (generator/import/automatic_limits.hpp): a file that gives a
// range without `limited` or `ctrllimited`, which MuJoCo 2.2.2 refuses, is read as MuJoCo 3 reads
// it, its control range a clamp; the same as the file that says limited="true" and
// ctrllimited="true" itself. A file that turns autolimits off keeps MuJoCo's error, as in MuJoCo 3.
#include <gtest/gtest.h>

#include <string>

#include "import/automatic_limits.hpp"
#include "import/model_writer.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

// a hinge with a range and a motor with a control range, each `limited` as `limits` writes it
std::string ranged_hinge(const std::string& compiler, const std::string& limited, const std::string& ctrllimited) {
  return "<mujoco model=\"limits\">\n" + compiler + R"(  <worldbody>
    <body name="arm" pos="0 0 1">
      <joint name="swing" axis="0 1 0" range="-1 2")" + limited + R"(/>
      <inertial pos="0 0 -0.2" mass="1" diaginertia="0.01 0.01 0.001"/>
    </body>
  </worldbody>
  <actuator><motor name="drive" joint="swing" gear="10" ctrlrange="-0.5 0.5")" + ctrllimited + R"(/></actuator>
</mujoco>
)";
}

TEST(AutomaticLimits, ARangeWithoutLimitedLimitsAsInMujoco3) {
  EXPECT_TRUE(refuses_range_without_limited("Error: joint has `range` but not `limited`. set the autolimits=\"true\" compiler "
                                            "option, specify `limited` explicitly (\"true\" or \"false\"), or remove the `range` "
                                            "attribute.\nElement 'joint', line 5\n"));
  EXPECT_FALSE(refuses_range_without_limited("Error: Schema violation: unrecognized attribute: 'autolimit'\n"));
  Diagnostics automatic_diagnostics, stated_diagnostics, off_diagnostics;
  auto automatic = imported_robot("automatic.xml", ranged_hinge("", "", ""), automatic_diagnostics);
  auto stated = imported_robot("stated.xml", ranged_hinge("", " limited=\"true\"", " ctrllimited=\"true\""), stated_diagnostics);
  ASSERT_TRUE(automatic) << automatic_diagnostics.format();
  ASSERT_TRUE(stated) << stated_diagnostics.format();
  EXPECT_NE(automatic->find("generalized = { swing = \"10*clamp(drive, -0.5, 0.5)\" }"), std::string::npos) << *automatic;
  ASSERT_NE(automatic->find("# note: ranges without `limited`"), std::string::npos) << *automatic;
  std::string without_note = without_lines_starting(*automatic, "# note: ");
  EXPECT_EQ(without_note.replace(without_note.find("automatic.xml"), 13, "stated.xml"), *stated);
  EXPECT_FALSE(imported_robot("off.xml", ranged_hinge("  <compiler autolimits=\"false\"/>\n", "", ""), off_diagnostics));
  EXPECT_NE(off_diagnostics.format().find("but not `limited`"), std::string::npos) << off_diagnostics.format();
}

}  // namespace
}  // namespace eomgen::test
