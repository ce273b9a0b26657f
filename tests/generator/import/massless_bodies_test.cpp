// Moving bodies without mass or inertia (generator/import/massless_bodies.hpp): the compiler's mass
// bounds go where MuJoCo reads them, what was raised to them goes back to zero, and a robot with no
// mass at all stays refused. (tests/crosscheck/mujoco_oracle_test.cpp checks a URDF's massless link
// between two joints against MuJoCo's same arm with both joints in one body.)
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "import/massless_bodies.hpp"
#include "import/model_writer.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

TEST(MasslessBodies, TheBoundsGoIntoTheCompilerOrOneIsAdded) {
  const std::string bounds = " boundmass=\"2e-15\" boundinertia=\"2e-15\"";
  EXPECT_EQ(with_mass_bounds("<robot name=\"r\">\n  <link name=\"a\"/>\n</robot>"),
            "<robot name=\"r\"><mujoco><compiler" + bounds + "/></mujoco>\n  <link name=\"a\"/>\n</robot>");
  EXPECT_EQ(with_mass_bounds("<robot name=\"r\"><mujoco><compiler fusestatic=\"false\"/></mujoco></robot>"),
            "<robot name=\"r\"><mujoco><compiler" + bounds + " fusestatic=\"false\"/></mujoco></robot>");
  EXPECT_EQ(with_mass_bounds("<mujoco model=\"m\">\n  <!-- <compiler/> -->\n  <worldbody/>\n</mujoco>"),
            "<mujoco model=\"m\"><compiler" + bounds + "/>\n  <!-- <compiler/> -->\n  <worldbody/>\n</mujoco>");
  std::string own = "<mujoco><compiler boundmass=\"0.001\"/></mujoco>";
  EXPECT_EQ(with_mass_bounds(own), own) << "a file's own bound stands";
}

TEST(MasslessBodies, WhatWasRaisedToTheBoundIsZeroAgain) {
  RobotBody link, point, heavy;
  link.name = "cross", link.mass = massless_bound, link.principal_inertia = {massless_bound, massless_bound, massless_bound};
  link.joints.resize(1);
  point.name = "bob", point.mass = 0.5, point.principal_inertia = {massless_bound, massless_bound, massless_bound};
  point.joints.resize(1);
  heavy.name = "arm", heavy.mass = 1, heavy.principal_inertia = {0.1, 0.1, 0.02};
  heavy.joints.resize(1);
  RobotBody base;
  base.name = "base", base.mass = massless_bound;
  std::vector<RobotBody> bodies{base, link, point, heavy};
  EXPECT_EQ(without_mass_bounds(bodies), (std::vector<std::string>{"cross", "bob"})) << "the static base is not named";
  EXPECT_EQ(bodies[0].mass, 0);
  EXPECT_EQ(bodies[1].mass, 0);
  EXPECT_EQ(bodies[1].principal_inertia[2], 0);
  EXPECT_EQ(bodies[2].mass, 0.5);
  EXPECT_EQ(bodies[2].principal_inertia[0], 0);
  EXPECT_EQ(bodies[3].principal_inertia[2], 0.02);
}

// a robot whose moving bodies have no mass at all has no dynamics: MuJoCo's refusal stands
TEST(MasslessBodies, ARobotWithoutMassStaysRefused) {
  std::string path = temporary_directory() + "/weightless.urdf";
  std::ofstream(path) << R"(<robot name="weightless"><link name="a"/><link name="b"/>
  <joint name="j" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/>
  <limit lower="-1" upper="1" effort="1" velocity="1"/></joint></robot>)";
  Diagnostics diagnostics;
  EXPECT_FALSE(imported_model_text(path, diagnostics, false));
  EXPECT_NE(diagnostics.format().find("weightless.urdf:2:1: error: joint 'j' moves no body with mass or inertia, so that the "
                                     "robot's mass matrix is singular"),
            std::string::npos) << diagnostics.format();
  EXPECT_NE(diagnostics.format().find("hint: give the bodies it moves an <inertial>"), std::string::npos);
}

}  // namespace
}  // namespace eomgen::test
