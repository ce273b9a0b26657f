// MuJoCo 3's actuatorfrcrange (generator/import/joint_force_limits.hpp), which MuJoCo 2.2.2 refuses:
// read through the joints' user values and carried as a clamp of the joint's total actuator force,
// or left out with a warning where the file cannot be read so. Against MuJoCo's motion:
// MujocoImport.AJointsTotalActuatorForceIsClampedToItsRange.
#include <gtest/gtest.h>

#include <string>

#include "import/joint_force_limits.hpp"
#include "import/model_writer.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

TEST(JointForceLimits, TheRangesAreWrittenAsTheJointsUserValues) {
  EXPECT_TRUE(refuses_joint_force_range("Error: Schema violation: unrecognized attribute: 'actuatorfrcrange'\nElement 'joint', line 3\n"));
  EXPECT_TRUE(refuses_joint_force_range("Error: Schema violation: unrecognized attribute: 'actuatorfrclimited'\nElement 'joint', line 3\n"));
  EXPECT_FALSE(refuses_joint_force_range("Error: Schema violation: unrecognized attribute: 'actuatorfrcrange'\nElement 'motor', line 3\n"));
  EXPECT_EQ(with_force_range_as_user("<default><joint actuatorfrcrange=\"-5 5\" actuatorfrclimited=\"true\"/></default>\n"
                                     "<!-- <joint actuatorfrcrange=\"-1 1\"/> -->\n<joint name=\"a\" actuatorfrcrange='-2 3'/>"),
            "<default><joint user=\"-5 5\" /></default>\n<!-- <joint actuatorfrcrange=\"-1 1\"/> -->\n<joint name=\"a\" user='-2 3'/>");
  EXPECT_EQ(with_force_range_as_user("<default><joint actuatorfrcrange=\"-5 5\"/></default>\n"
                                     "<joint actuatorfrcrange=\"-5 5\" actuatorfrclimited=\"false\"/><joint actuatorfrclimited='false'/>"),
            "<default><joint user=\"-5 5\"/></default>\n<joint user=\"0 0\"  /><joint user=\"0 0\" />")
      << "a joint's own range that does not clamp, and one that its class would give";
  EXPECT_FALSE(with_force_range_as_user("<default><joint actuatorfrclimited=\"false\"/></default><joint actuatorfrcrange=\"-5 5\"/>"))
      << "a class that switches the clamp off";
  EXPECT_FALSE(with_force_range_as_user("<compiler autolimits=\"false\"/><joint actuatorfrcrange=\"-5 5\"/>"));
  EXPECT_FALSE(with_force_range_as_user("<joint actuatorfrcrange=\"-5 5\"/><joint user=\"1 2\"/>")) << "the file's own user values";
  EXPECT_TRUE(with_force_range_as_user("<motor user=\"1\"/><joint actuatorfrcrange=\"-5 5\"/>")) << "an actuator's are another array";
}

// a hinge with a range of -1 to 2, `limited` as written, driven by a motor of gear 10
std::string limited_hinge(const std::string& limited) {
  return R"(<mujoco model="clamp">
  <worldbody>
    <body name="arm" pos="0 0 1">
      <joint name="swing" axis="0 1 0" actuatorfrcrange="-1 2")" + limited + R"(/>
      <inertial pos="0 0 -0.2" mass="1" diaginertia="0.01 0.01 0.001"/>
    </body>
  </worldbody>
  <actuator><motor name="drive" joint="swing" gear="10"/></actuator>
</mujoco>
)";
}

std::string imported_hinge(const std::string& file) { return imported_robot_text("clamp.xml", file); }

TEST(JointForceLimits, TheJointsTotalIsClampedOrTheRangeWarnedOf) {
  std::string clamped = imported_hinge(limited_hinge(""));
  EXPECT_NE(clamped.find("generalized = { swing = \"clamp(10*drive, -1, 2)\" }"), std::string::npos) << clamped;
  EXPECT_NE(clamped.find("# note: the actuator force ranges (MuJoCo 3's actuatorfrcrange) of 1 joint(s)"), std::string::npos) << clamped;
  std::string unlimited = imported_hinge(limited_hinge(" actuatorfrclimited=\"false\""));
  EXPECT_NE(unlimited.find("generalized = { swing = \"10*drive\" }"), std::string::npos) << unlimited;
  EXPECT_EQ(unlimited.find("actuatorfrcrange"), std::string::npos) << "carried, as no clamp: " << unlimited;
  std::string classed = limited_hinge(" class=\"loose\"");
  classed.replace(classed.find("  <worldbody>"), 0, "  <default><default class=\"loose\"><joint actuatorfrclimited=\"false\"/></default></default>\n");
  std::string warned = imported_hinge(classed);
  EXPECT_NE(warned.find("generalized = { swing = \"10*drive\" }"), std::string::npos) << warned;
  EXPECT_NE(warned.find("# not carried: 'actuatorfrcrange'"), std::string::npos) << warned;
}

}  // namespace
}  // namespace eomgen::test
