// Why an actuator is left out (generator/import/actuator_reasons.hpp): each of MuJoCo's actuators
// that eomgen cannot carry is named in the imported file's opening comments with the one reason that
// applies to it, and the motors beside them are carried, one on a hinge given in its parent's frame
// (the same axis; tests/crosscheck/mjcf/mjcf_features.xml has one against MuJoCo).
#include <gtest/gtest.h>

#include <string>

#include "import/model_writer.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

// a hinged arm with a ball-jointed tip, driven in every way MuJoCo 2.2.2 reads (the actuators with
// states last, as it asks)
const char* driven_arm = R"(<mujoco model="drives">
  <worldbody>
    <body name="arm" pos="0 0 1">
      <joint name="swing" axis="0 1 0"/>
      <inertial pos="0 0 -0.2" mass="1" diaginertia="0.01 0.01 0.001"/>
      <site name="grip" pos="0 0 -0.4"/>
      <body name="tip" pos="0 0 -0.4">
        <joint name="wrist" type="ball"/>
        <inertial pos="0 0 -0.1" mass="0.2" diaginertia="0.001 0.001 0.0005"/>
      </body>
    </body>
  </worldbody>
  <actuator>
    <motor name="drive" joint="swing" gear="3"/>
    <general name="parented" jointinparent="swing" gear="2"/>
    <general name="parented_ball" jointinparent="wrist" gear="0 1 0"/>
    <general name="stiffening" joint="swing" gaintype="affine" gainprm="1 2 0"/>
    <motor name="twist" joint="wrist" gear="0 0 1"/>
    <motor name="push" site="grip" gear="1 0 0 0 0 0"/>
    <general name="lagged" joint="swing" dyntype="filter" dynprm="0.05"/>
    <general name="summed" joint="swing" dyntype="integrator"/>
  </actuator>
</mujoco>
)";

TEST(ActuatorReasons, EachActuatorLeftOutIsNamedWithItsReason) {
  std::string text = imported_robot_text("drives.xml", driven_arm);
  EXPECT_TRUE(mentions(text, "'lagged' is left out: its activation dynamics, a filter (da/dt = (u - a)/tau)")) << text;
  EXPECT_TRUE(mentions(text, "'summed' is left out: its activation dynamics, an integrator (da/dt = u)")) << text;
  EXPECT_TRUE(mentions(text, "'stiffening' is left out: its gain depends on the position and its rate")) << text;
  EXPECT_TRUE(mentions(text, "'twist' is left out: it drives a ball or free joint")) << text;
  EXPECT_TRUE(mentions(text, "'push' is left out: it acts through a site")) << text;
  EXPECT_FALSE(mentions(text, "'drive' is left out")) << text;
  EXPECT_TRUE(mentions(text, "'parented_ball' is left out: it drives a ball or free joint")) << text;
  EXPECT_TRUE(mentions(text, "3*drive")) << "the motor beside them is carried: " << text;
  EXPECT_TRUE(mentions(text, "2*parented")) << "a hinge's axis in its parent's frame is its own: " << text;
}

}  // namespace
}  // namespace eomgen::test
