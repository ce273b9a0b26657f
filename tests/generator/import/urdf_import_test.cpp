// URDF links fixed to their parents keep their names (generator/import/urdf_text.hpp):
// MuJoCo's URDF reader would fuse them into their parents, so the file is read from memory with
// fusestatic off. The text edit leaves every line where it was and respects the file's own
// <mujoco> section; a massless fixed leaf (a tool flange) becomes a frame and a point of its name;
// and the robot's dynamics are MuJoCo's: M and the bias forces at random states, against MuJoCo
// reading the same text. (Reading the file as it is, MuJoCo fuses the flange into the upper arm
// and re-diagonalizes the sum of their inertias by its eigenvalue iteration, whose rounding
// moves M by about 1e-11; the fused model has no flange to compare anyway.)
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <memory>
#include <random>
#include <sstream>

#include <fmt/format.h>
#include <mujoco/mujoco.h>

#include "import/model_writer.hpp"
#include "import/urdf_text.hpp"
#include "pipeline.hpp"
#include "support/mujoco_dynamics.hpp"
#include "support/urdf_inertias.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

TEST(UrdfStaticLinks, TheCompilerSettingGoesIntoTheRobotOnItsOwnLine) {
  std::string urdf = "<?xml version=\"1.0\"?>\n<!-- not this <robot> -->\n<robot name=\"r\">\n  <link name=\"a\"/>\n</robot>\n";
  std::string kept = with_static_links_kept(urdf);
  EXPECT_EQ(line_breaks(kept), line_breaks(urdf));
  EXPECT_NE(kept.find("<robot name=\"r\"><mujoco><compiler fusestatic=\"false\"/></mujoco>\n"), std::string::npos) << kept;
  EXPECT_EQ(kept.find("robot> --><mujoco>"), std::string::npos) << "a comment is no element";
}

TEST(UrdfStaticLinks, TheFilesOwnMujocoSectionKeepsItsSettings) {
  std::string with_compiler = "<robot name=\"r\">\n<mujoco>\n<compiler meshdir=\"meshes\"/>\n</mujoco>\n</robot>\n";
  EXPECT_NE(with_static_links_kept(with_compiler).find("<compiler fusestatic=\"false\" meshdir=\"meshes\"/>"), std::string::npos);
  std::string without_compiler = "<robot name=\"r\">\n<mujoco>\n<option timestep=\"0.01\"/>\n</mujoco>\n</robot>\n";
  EXPECT_NE(with_static_links_kept(without_compiler).find("<mujoco><compiler fusestatic=\"false\"/>\n<option"), std::string::npos);
  std::string chosen = "<robot name=\"r\">\n<mujoco>\n<compiler fusestatic=\"true\"/>\n</mujoco>\n</robot>\n";
  EXPECT_EQ(with_static_links_kept(chosen), chosen) << "the file's own choice stands";
  EXPECT_TRUE(is_urdf_path("a/b/robot.URDF"));
  EXPECT_FALSE(is_urdf_path("robot.xml"));
  EXPECT_TRUE(has_robot_root("<?xml version=\"1.0\"?>\n<!-- <mujoco> in a comment -->\n<robot name=\"arm\">\n</robot>"));
  EXPECT_TRUE(has_robot_root("<robot>"));
  EXPECT_FALSE(has_robot_root("<mujoco model=\"robot\"><robot/></mujoco>"));
  EXPECT_FALSE(has_robot_root("<robotic_arm/>"));
  EXPECT_FALSE(has_robot_root("<!-- unclosed comment <robot>"));
  // xacro's output keeps its namespace and the macros it commented out: URDF all the same
  EXPECT_EQ(urdf_text_mistake("<robot xmlns:xacro=\"http://www.ros.org/wiki/xacro\" name=\"a\">\n"
                              "<!-- <xacro:if value=\"${right}\"> --></robot>", "a.urdf").line, 0);
  EXPECT_EQ(urdf_text_mistake("<robot name=\"a\">\n<!-- c -->\n  <origin xyz=\"0 0 ${l}\"/></robot>", "a.urdf.xacro").line, 3);
}

// a three-link arm with a heavy fixed flange between its last two joints and a massless tool link
const char* const flanged_arm = R"(<?xml version="1.0"?>
<robot name="flanged_arm">
  <link name="base"/>
  <link name="upper">
    <inertial><origin xyz="0 0 0.15" rpy="0.1 0.2 0.3"/><mass value="1.2"/><inertia ixx="0.011" ixy="0.001" ixz="-0.0005" iyy="0.012" iyz="0.0002" izz="0.004"/></inertial>
  </link>
  <link name="flange">
    <inertial><origin xyz="0 0.01 0.02" rpy="0 0 0"/><mass value="0.5"/><inertia ixx="0.001" ixy="0" ixz="0" iyy="0.002" iyz="0" izz="0.0015"/></inertial>
  </link>
  <link name="fore">
    <inertial><origin xyz="0.02 0 0.12" rpy="0 0 0"/><mass value="0.8"/><inertia ixx="0.006" ixy="0" ixz="0" iyy="0.006" iyz="0" izz="0.001"/></inertial>
  </link>
  <link name="tool0"/>
  <joint name="shoulder" type="revolute">
    <parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.1" rpy="0 0.3 0"/><axis xyz="0 1 0"/>
    <limit lower="-2" upper="2" effort="50" velocity="3"/>
  </joint>
  <joint name="mount" type="fixed">
    <parent link="upper"/><child link="flange"/>
    <origin xyz="0 0.05 0.3" rpy="0.2 0 0.4"/>
  </joint>
  <joint name="elbow" type="continuous">
    <parent link="flange"/><child link="fore"/>
    <origin xyz="0 0 0.05" rpy="0 0 0"/><axis xyz="1 0 1"/>
  </joint>
  <joint name="tool" type="fixed">
    <parent link="fore"/><child link="tool0"/>
    <origin xyz="0 0 0.25" rpy="0 1.5707963267948966 0"/>
  </joint>
</robot>
)";

TEST(UrdfImport, FixedLinksKeepTheirNamesAndTheDynamicsStayTheFiles) {
  std::string path = temporary_directory() + "/flanged_arm.urdf";
  std::ofstream(path) << flanged_arm;
  Diagnostics diagnostics;
  auto text = imported_model_text(path, diagnostics, false);
  ASSERT_TRUE(text) << diagnostics.format();
  for (const char* line : {"name = \"flange\"\nparent = \"upper\"", "name = \"tool0\"\nparent = \"fore\"",
                           "[[points]]\nname = \"tool0\"\nframe = \"tool0\"\nposition = [\"0\", \"0\", \"0\"]",
                           "[[rigid_bodies]]\nname = \"flange\""})
    EXPECT_NE(text->find(line), std::string::npos) << line << " in\n" << *text;
  EXPECT_EQ(text->find("[[points]]\nname = \"flange\""), std::string::npos) << "a link with mass or children is no mere point";
  Equations e = derive_text(*text, "flanged_arm.toml");
  ASSERT_EQ(e.num_velocities(), 2u);
  char error[1000] = "";
  std::unique_ptr<mjModel, void (*)(mjModel*)> fused(mj_loadXML(path.c_str(), nullptr, error, sizeof error), mj_deleteModel);
  ASSERT_TRUE(fused) << error;
  EXPECT_EQ(fused->nbody, 3) << "MuJoCo reading the file itself fuses the flange and the tool";
  std::string kept = temporary_directory() + "/kept.urdf";
  std::ofstream(kept) << with_static_links_kept(flanged_arm);
  std::unique_ptr<mjModel, void (*)(mjModel*)> m(mj_loadXML(kept.c_str(), nullptr, error, sizeof error), mj_deleteModel);
  ASSERT_TRUE(m) << error;
  ASSERT_EQ(m->nbody, 6) << "the world, the base and four links";
  with_stated_urdf_inertias(m.get(), kept);
  expect_mujoco_dynamics(e, m.get(), {"shoulder", "elbow"}, 3, 1e-13, 1e-12);
}

TEST(UrdfStaticLinks, NoMassIsTakenFromShapesUnlessTheFileSaysSo) {
  std::string urdf = "<robot name=\"r\">\n  <link name=\"a\"/>\n</robot>\n";
  std::string read = without_masses_from_geometry(urdf);
  EXPECT_EQ(line_breaks(read), line_breaks(urdf));
  EXPECT_NE(read.find("<robot name=\"r\"><mujoco><compiler inertiafromgeom=\"false\"/></mujoco>\n"), std::string::npos) << read;
  EXPECT_NE(without_masses_from_geometry(with_static_links_kept(urdf)).find("<compiler inertiafromgeom=\"false\" fusestatic=\"false\"/>"),
            std::string::npos);
  std::string chosen = "<robot name=\"r\">\n<mujoco>\n<compiler inertiafromgeom=\"true\"/>\n</mujoco>\n</robot>\n";
  EXPECT_EQ(without_masses_from_geometry(chosen), chosen) << "the file's own choice stands";
  std::string links = "<robot name=\"r\">\n  <link name=\"base\"/>\n"
                      "  <link name=\"camera\"><visual><geometry><box size=\"0.1 0.1 0.1\"/></geometry></visual></link>\n"
                      "  <link name=\"arm\"><inertial><mass value=\"1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" "
                      "izz=\"1\"/></inertial><collision><geometry><cylinder radius=\"0.1\" length=\"1\"/></geometry></collision></link>\n"
                      "  <link name=\"frame_only\"><visual><origin xyz=\"0 0 1\"/></visual></link>\n"
                      "  <link name=\"hull\"><collision><geometry><mesh filename=\"hull.stl\"/></geometry></collision></link>\n</robot>\n";
  EXPECT_EQ(colliding_links_without_inertial(links), (std::vector<std::string>{"hull"})) << "MuJoCo discards a URDF's visuals";
}

// the flanged arm with a wrist camera: a link without an <inertial>, drawn and colliding as a
// cylinder and a box, fixed to the forearm. URDF readers take it as massless; MuJoCo alone would
// weigh its collision box (0.288 kg), and on a floating base fuse that into the forearm
std::string camera_arm() {
  std::string urdf = flanged_arm;
  urdf.replace(urdf.find("  <link name=\"tool0\"/>"), 0,
               "  <link name=\"camera\">\n"
               "    <visual><origin xyz=\"0 0 0.04\"/><geometry><cylinder radius=\"0.03\" length=\"0.08\"/></geometry></visual>\n"
               "    <collision><origin xyz=\"0 0 0.04\"/><geometry><box size=\"0.06 0.06 0.08\"/></geometry></collision>\n"
               "  </link>\n");
  urdf.replace(urdf.find("</robot>"), 0,
               "  <joint name=\"camera_mount\" type=\"fixed\">\n"
               "    <parent link=\"fore\"/><child link=\"camera\"/><origin xyz=\"0.03 0 0.1\" rpy=\"0 0.4 0\"/>\n  </joint>\n");
  return urdf;
}

TEST(UrdfImport, ALinkWithoutInertialIsMasslessAsUrdfHasIt) {
  std::string urdf = camera_arm(), path = write_file("camera_arm.urdf", urdf);
  Diagnostics diagnostics;
  auto text = imported_model_text(path, diagnostics, false);
  ASSERT_TRUE(text) << diagnostics.format();
  EXPECT_NE(text->find("1 link(s) without an <inertial> but with collision shapes ('camera'): massless, as URDF has them"), std::string::npos)
      << *text;
  EXPECT_EQ(text->find("[[rigid_bodies]]\nname = \"camera\""), std::string::npos) << *text;
  Equations e = derive_text(*text, "camera_arm.toml");
  // MuJoCo reading the file as URDF readers do: fixed links kept, no mass from shapes, tensors as stated
  std::string as_urdf = urdf, kept = temporary_directory() + "/camera_arm_kept.urdf";
  as_urdf.insert(as_urdf.find('>', as_urdf.find("<robot")) + 1, "<mujoco><compiler fusestatic=\"false\" inertiafromgeom=\"false\"/></mujoco>");
  std::ofstream(kept) << as_urdf;
  char error[1000] = "";
  std::unique_ptr<mjModel, void (*)(mjModel*)> m(mj_loadXML(kept.c_str(), nullptr, error, sizeof error), mj_deleteModel);
  ASSERT_TRUE(m) << error;
  with_stated_urdf_inertias(m.get(), kept);
  expect_mujoco_dynamics(e, m.get(), {"shoulder", "elbow"}, 4, 1e-13, 1e-12);

  // on a floating base the forearm's body is the forearm alone: its mass and its moments as stated
  // (the base given mass: without, it would float above the shoulder alone, M singular, refused)
  std::string weighed = urdf;
  weighed.replace(weighed.find("<link name=\"base\"/>"), 19,
                  "<link name=\"base\"><inertial><mass value=\"2\"/><inertia ixx=\"0.02\" ixy=\"0\" ixz=\"0\" iyy=\"0.02\" "
                  "iyz=\"0\" izz=\"0.02\"/></inertial></link>");
  path = write_file("weighed_camera_arm.urdf", weighed);
  Diagnostics floating_diagnostics;
  auto floating = imported_model_text(path, floating_diagnostics, false, {}, {true});
  ASSERT_TRUE(floating) << floating_diagnostics.format();
  std::size_t fore = floating->find("name = \"fore\"\nframe = \"fore\"");
  ASSERT_NE(fore, std::string::npos) << *floating;
  EXPECT_NEAR(std::stod(floating->substr(floating->find("mass = \"", fore) + 8)), 0.8, 1e-14) << floating->substr(fore, 300);
  std::size_t inertia = floating->find("inertia = [\"", fore);
  double trace = 0;
  std::size_t at = inertia + 12;
  for (int k = 0; k < 3; ++k, at = floating->find('"', floating->find('"', at) + 1) + 1) trace += std::stod(floating->substr(at));
  EXPECT_NEAR(trace, 0.006 + 0.006 + 0.001, 1e-17) << floating->substr(fore, 300);
}

// --masses-from-shapes reads the file as MuJoCo does: the camera weighs its collision box (MuJoCo
// discards a URDF's visual shapes); a finger without an <inertial>,
// which URDF leaves massless and so the mass matrix singular, is refused with that option as the fix
TEST(UrdfImport, MassesFromShapesWeighLinksWithoutInertialAsMujocoDoes) {
  std::string path = write_file("camera_arm.urdf", camera_arm());
  Diagnostics diagnostics;
  auto text = imported_model_text(path, diagnostics, false, {}, {false, true});
  ASSERT_TRUE(text) << diagnostics.format();
  EXPECT_NE(text->find("('camera') weighed by their collision shapes at the density of water"), std::string::npos) << *text;
  std::size_t camera = text->find("[[rigid_bodies]]\nname = \"camera\"");
  ASSERT_NE(camera, std::string::npos) << *text;
  double shapes = 1000 * 0.06 * 0.06 * 0.08;
  EXPECT_NEAR(std::stod(text->substr(text->find("mass = \"", camera) + 8)), shapes, 1e-14 * shapes) << text->substr(camera, 200);

  std::string finger = flanged_arm;
  finger.replace(finger.find("  <link name=\"tool0\"/>"), 0,
                 "  <link name=\"finger\"><collision><geometry><box size=\"0.01 0.01 0.05\"/></geometry></collision></link>\n");
  finger.replace(finger.find("</robot>"), 0,
                 "  <joint name=\"pinch\" type=\"prismatic\">\n    <parent link=\"fore\"/><child link=\"finger\"/><axis xyz=\"0 1 0\"/>\n"
                 "    <limit lower=\"0\" upper=\"0.04\" effort=\"20\" velocity=\"0.2\"/>\n  </joint>\n");
  std::string finger_path = write_file("finger_arm.urdf", finger);
  Diagnostics refused;
  EXPECT_FALSE(imported_model_text(finger_path, refused, false));
  EXPECT_NE(refused.format().find("joint 'pinch' moves no body with mass"), std::string::npos) << refused.format();
  EXPECT_NE(refused.format().find("or import with --masses-from-shapes"), std::string::npos) << refused.format();
  Diagnostics weighed;
  EXPECT_TRUE(imported_model_text(finger_path, weighed, false, {}, {false, true})) << weighed.format();
}

// a link of mass 0 that states a moment of inertia (Bolt's feet, at the end of a leg): URDF readers
// keep the moment, and so does the import (a rigid body of mass 0, unphysical_inertia); MuJoCo reading
// the file with its fixed links kept agrees
const char* const footed_leg = R"(<?xml version="1.0"?>
<robot name="footed_leg">
  <link name="hip"/>
  <link name="thigh">
    <inertial><origin xyz="0 0.01 -0.1"/><mass value="0.15"/><inertia ixx="4e-4" ixy="0" ixz="0" iyy="4e-4" iyz="-5e-5" izz="3e-5"/></inertial>
  </link>
  <link name="shank">
    <inertial><origin xyz="0 0.008 -0.11"/><mass value="0.03"/><inertia ixx="1.1e-4" ixy="0" ixz="0" iyy="1.2e-4" iyz="-2e-6" izz="1.2e-5"/></inertial>
  </link>
  <link name="foot">
    <inertial><origin xyz="0 0 0.00036"/><mass value="0.0"/><inertia ixx="5.7e-5" ixy="0" ixz="0" iyy="8.4e-5" iyz="0" izz="5.3e-5"/></inertial>
  </link>
  <joint name="hip_joint" type="revolute">
    <parent link="hip"/><child link="thigh"/><axis xyz="1 0 0"/>
    <limit lower="-3" upper="3" effort="2" velocity="9"/>
  </joint>
  <joint name="knee_joint" type="revolute">
    <parent link="thigh"/><child link="shank"/><origin xyz="0 0.02 -0.16"/><axis xyz="1 0 0"/>
    <limit lower="-3" upper="3" effort="2" velocity="9"/>
  </joint>
  <joint name="ankle" type="fixed">
    <parent link="shank"/><child link="foot"/><origin xyz="0 0.01 -0.16"/>
  </joint>
</robot>
)";

TEST(UrdfImport, AMasslessLinksMomentOfInertiaIsKept) {
  std::string path = write_file("footed_leg.urdf", footed_leg);
  Diagnostics diagnostics;
  auto text = imported_model_text(path, diagnostics, false);
  ASSERT_TRUE(text) << diagnostics.format();
  EXPECT_NE(text->find("name = \"foot\"\nframe = \"foot\"\nmass = \"0\""), std::string::npos) << *text;
  EXPECT_NE(text->find("unphysical_inertia = true  # a moment of inertia without mass"), std::string::npos) << *text;
  Equations e = derive_text(*text, "footed_leg.toml");
  ASSERT_EQ(e.num_velocities(), 2u);
  std::string kept = temporary_directory() + "/footed_leg_kept.urdf";
  std::ofstream(kept) << with_static_links_kept(footed_leg);
  char error[1000] = "";
  std::unique_ptr<mjModel, void (*)(mjModel*)> m(mj_loadXML(kept.c_str(), nullptr, error, sizeof error), mj_deleteModel);
  ASSERT_TRUE(m) << error;
  with_stated_urdf_inertias(m.get(), kept);
  expect_mujoco_dynamics(e, m.get(), {"hip_joint", "knee_joint"}, 9, 1e-15, 1e-12);
  // without the flag, a rigid body of mass 0 is refused as a mistake, with the fix named
  std::string flagged = "unphysical_inertia = true  # a moment of inertia without mass, as the robot file states it\n";
  std::string unflagged = *text;
  unflagged.erase(unflagged.find(flagged), flagged.size());
  Derivation refused = derive_model_text(unflagged, "unflagged.toml");
  EXPECT_FALSE(refused.equations);
  EXPECT_NE(refused.diagnostics.format().find("a rigid body of no mass but a moment of inertia"), std::string::npos)
      << refused.diagnostics.format();
}

// on a floating base (--free-base) the foot stays a link of its own, with its moment of inertia and
// no mass, as on the fixed base: the import sets the base free itself, where MuJoCo's reader would
// fuse every fixed link into its parent; the free base adds its 7 coordinates and 6 velocities
TEST(UrdfImport, AMasslessLinksMomentOfInertiaIsKeptOnAFloatingBase) {
  // the hip given mass and inertia: massless, it would turn about the hip joint's axis as freely as
  // the thigh, and M would be singular
  std::string weighed = footed_leg;
  weighed.replace(weighed.find("<link name=\"hip\"/>"), 18,
                  "<link name=\"hip\"><inertial><mass value=\"1\"/><inertia ixx=\"0.01\" ixy=\"0\" ixz=\"0\" "
                  "iyy=\"0.01\" iyz=\"0\" izz=\"0.01\"/></inertial></link>");
  std::string path = write_file("footed_leg.urdf", weighed);
  Diagnostics diagnostics;
  auto text = imported_model_text(path, diagnostics, false, {}, {true});
  ASSERT_TRUE(text) << diagnostics.format();
  EXPECT_NE(text->find("name = \"foot\"\nframe = \"foot\"\nmass = \"0\""), std::string::npos) << *text;
  EXPECT_NE(text->find("unphysical_inertia = true  # a moment of inertia without mass"), std::string::npos) << *text;
  EXPECT_EQ(text->find("fused"), std::string::npos) << *text;
  Equations e = derive_text(*text, "footed_leg.toml");
  EXPECT_EQ(e.num_velocities(), 8u);
  EXPECT_EQ(e.symbols.coordinate_names.size(), 9u);
}

// a joint's <mimic> (MuJoCo's URDF reader ignores it) follows the coordinate it mimics
// (joint_follower_import_test.cpp checks the dynamics); one that mimics a follower (a chain) follows
// the chain's head, the multipliers and offsets composed, on a fixed base and on a floating one
// (where the fixed links are named as fused when the file has its own floating joint: MuJoCo must
// fuse them there; not when --free-base sets the base free)
const char* const gripper = R"(<?xml version="1.0"?>
<robot name="gripper">
  <link name="palm"/>
  <link name="left">
    <inertial><origin xyz="0 0 0.03"/><mass value="0.1"/><inertia ixx="0.0001" ixy="0" ixz="0" iyy="0.0001" iyz="0" izz="0.00002"/></inertial>
  </link>
  <link name="right">
    <inertial><origin xyz="0 0 0.03"/><mass value="0.1"/><inertia ixx="0.0001" ixy="0" ixz="0" iyy="0.0001" iyz="0" izz="0.00002"/></inertial>
  </link>
  <link name="thumb">
    <inertial><origin xyz="0 0 0.02"/><mass value="0.05"/><inertia ixx="0.00005" ixy="0" ixz="0" iyy="0.00005" iyz="0" izz="0.00001"/></inertial>
  </link>
  <joint name="left_finger" type="prismatic">
    <parent link="palm"/><child link="left"/><origin xyz="0 0.02 0"/><axis xyz="0 1 0"/>
    <limit lower="0" upper="0.04" effort="20" velocity="0.2"/>
  </joint>
  <joint name="right_finger" type="prismatic">
    <parent link="palm"/><child link="right"/><origin xyz="0 -0.02 0"/><axis xyz="0 1 0"/>
    <limit lower="-0.04" upper="0" effort="20" velocity="0.2"/>
    <mimic joint="left_finger" multiplier="-1" offset="0.001"/>
  </joint>
  <joint name="thumb_joint" type="revolute">
    <parent link="palm"/><child link="thumb"/><origin xyz="0.02 0 0"/><axis xyz="1 0 0"/>
    <limit lower="-1" upper="1" effort="20" velocity="0.2"/>
    <mimic joint="right_finger" multiplier="30"/>
  </joint>
</robot>
)";

TEST(UrdfImport, AMimicJointFollowsItsCoordinateAndAChainOfThemItsHead) {
  auto mimics = urdf_mimics(gripper);
  ASSERT_EQ(mimics.size(), 2u);
  EXPECT_EQ(mimics[0].joint, "right_finger");
  EXPECT_EQ(mimics[0].mimicked, "left_finger");
  EXPECT_EQ(mimics[0].multiplier, -1);
  EXPECT_EQ(mimics[0].offset, 0.001);
  EXPECT_EQ(mimics[0].line, 17);
  EXPECT_EQ(mimics[1].multiplier, 30);
  EXPECT_EQ(mimics[1].offset, 0);
  std::string path = temporary_directory() + "/gripper.urdf";
  std::ofstream(path) << gripper;
  Diagnostics diagnostics;
  auto text = imported_model_text(path, diagnostics, false);
  ASSERT_TRUE(text) << diagnostics.format();
  // the thumb: 30 (−left + 0.001) = −30 left + 0.03
  for (const char* line : {"coordinate = \"left_finger\", multiplier = -1, offset = 0.001 }",
                           "coordinate = \"left_finger\", multiplier = -30, offset = 0.03 }"})
    EXPECT_NE(text->find(line), std::string::npos) << line << " in\n" << *text;
  EXPECT_EQ(text->find("[[constraints]]"), std::string::npos) << *text;
  Equations e = derive_text(*text, "gripper.toml");
  EXPECT_EQ(e.symbols.coordinate_names, (std::vector<std::string>{"left_finger"}));
  EXPECT_EQ(urdf_joint_count(gripper, "prismatic"), 2);
  std::string floating = gripper;
  floating.replace(floating.find("<link name=\"palm\"/>"), 19,
                   "<link name=\"base\"/><link name=\"palm\"><inertial><mass value=\"1\"/><inertia ixx=\"0.01\" ixy=\"0\" "
                   "ixz=\"0\" iyy=\"0.01\" iyz=\"0\" izz=\"0.01\"/></inertial></link><joint name=\"root\" "
                   "type=\"floating\"><parent link=\"base\"/><child link=\"palm\"/></joint><link name=\"tool\"/><joint "
                   "name=\"flange\" type=\"fixed\"><parent link=\"palm\"/><child link=\"tool\"/></joint>");
  std::ofstream(path) << floating;
  text = imported_model_text(path, diagnostics, false);
  ASSERT_TRUE(text) << diagnostics.format();
  EXPECT_NE(text->find("coordinate = \"left_finger\", multiplier = -30, offset = 0.03 }"), std::string::npos) << *text;
  EXPECT_EQ(text->find("mimics"), std::string::npos) << "no mimic is left out:\n" << *text;
  EXPECT_EQ(text->find("[[constraints]]"), std::string::npos) << *text;
  EXPECT_NE(text->find("# not carried: 1 fixed joint(s): their links are fused into their parents"), std::string::npos) << *text;
  Equations floating_equations = derive_text(*text, "floating_gripper.toml");
  EXPECT_EQ(floating_equations.symbols.coordinate_names.size(), 8u) << "7 of the free joint and the left finger";
  // set free by --free-base instead: the same followers, and nothing fused
  std::ofstream(path) << gripper;
  text = imported_model_text(path, diagnostics, false, {}, {true});
  ASSERT_TRUE(text) << diagnostics.format();
  EXPECT_NE(text->find("coordinate = \"left_finger\", multiplier = -30, offset = 0.03 }"), std::string::npos) << *text;
  EXPECT_EQ(text->find("[[constraints]]"), std::string::npos) << *text;
  EXPECT_EQ(text->find("fused"), std::string::npos) << *text;
  EXPECT_EQ(derive_text(*text, "freed_gripper.toml").symbols.coordinate_names.size(), 8u);
}

// --joint-torques: an input tau_JOINT per hinge, the generalized force on its own coordinate alone
// (∂f/∂u the identity), its effort limit beside it, none for the gripper's fingers that mimic
// another, and the file's own dynamics otherwise (f at u = 0 unchanged)
TEST(UrdfImport, JointTorquesDriveEachHingeByItsOwnInput) {
  std::string arm = std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/urdf/two_link_arm.urdf";
  Diagnostics diagnostics;
  RobotReading torques;
  torques.joint_torques = true;
  auto driven = imported_model_text(arm, diagnostics, false, "driven", torques);
  auto plain = imported_model_text(arm, diagnostics, false, "driven");
  ASSERT_TRUE(driven && plain) << diagnostics.format();
  Equations e = derive_text(*driven, "driven.toml"), e0 = derive_text(*plain, "plain.toml");
  ASSERT_EQ(e.symbols.inputs.size(), 2u);
  EXPECT_NE(driven->find("tau_shoulder = 0  # effort limit 50 in the file: not enforced\ntau_elbow = 0\n"), std::string::npos)
      << "the revolute shoulder's <limit effort>, the continuous elbow without one:\n" << *driven;
  EXPECT_EQ(e.symbols.inputs[0].get_name(), "tau_shoulder");
  EXPECT_EQ(e.symbols.inputs[1].get_name(), "tau_elbow");
  GiNaC::exmap at_rest;
  for (const GiNaC::realsymbol& u : e.symbols.inputs) at_rest[u] = 0;
  for (std::size_t i = 0; i < 2; ++i) {
    for (std::size_t j = 0; j < 2; ++j)
      EXPECT_EQ(GiNaC::ex(e.forcing[i].diff(e.symbols.inputs[j]) - (i == j ? 1 : 0)).expand(), 0) << i << ", " << j;
    std::ostringstream with_inputs_at_zero, without;
    with_inputs_at_zero << e.forcing[i].subs(at_rest);
    without << e0.forcing[i];
    EXPECT_EQ(with_inputs_at_zero.str(), without.str()) << i << " (the two derivations' intermediates are other symbols)";
  }
  std::string path = temporary_directory() + "/gripper.urdf";
  std::ofstream(path) << gripper;
  auto gripped = imported_model_text(path, diagnostics, false, {}, torques);
  ASSERT_TRUE(gripped) << diagnostics.format();
  EXPECT_NE(gripped->find("tau_left_finger = 0"), std::string::npos) << *gripped;
  EXPECT_EQ(gripped->find("tau_right_finger"), std::string::npos) << "a mimic has no input:\n" << *gripped;
}

// mimics in a cycle have no head to follow: they stay constraints (Lagrange I)
TEST(UrdfImport, MimicsInACycleStayConstraints) {
  std::string cycle = gripper;
  cycle.replace(cycle.find("<limit lower=\"0\" upper=\"0.04\" effort=\"20\" velocity=\"0.2\"/>"), 56,
                "<limit lower=\"0\" upper=\"0.04\" effort=\"20\" velocity=\"0.2\"/><mimic joint=\"thumb_joint\" multiplier=\"0.5\"/>");
  std::string path = temporary_directory() + "/cycle.urdf";
  std::ofstream(path) << cycle;
  Diagnostics diagnostics;
  auto text = imported_model_text(path, diagnostics, false);
  ASSERT_TRUE(text) << diagnostics.format();
  for (const char* line : {"method = \"lagrange1\"", "name = \"left_finger_mimics_thumb_joint\"",
                           "name = \"right_finger_mimics_left_finger\"", "name = \"thumb_joint_mimics_right_finger\""})
    EXPECT_NE(text->find(line), std::string::npos) << line << " in\n" << *text;
  EXPECT_EQ(text->find("multiplier ="), std::string::npos) << *text;
}

// a URDF from a ROS package names meshes MuJoCo 2.2.2 cannot read (COLLADA, package:// paths, files
// not beside it): the robot is read again without them, its dynamics unchanged, and says so
TEST(UrdfImport, MeshesThatCannotBeReadAreLeftOutAndNamed) {
  std::string plain = flanged_arm, meshed = flanged_arm;
  const std::string upper = "<link name=\"upper\">\n";
  meshed.insert(meshed.find(upper) + upper.size(),
                "    <visual><geometry><mesh filename=\"package://arm/meshes/upper.dae\"/></geometry></visual>\n"
                "    <collision>\n      <geometry><mesh filename=\"upper.stl\" scale=\"0.001 0.001 0.001\"/></geometry>\n    </collision>\n"
                "    <visual><geometry><box size=\"0.05 0.05 0.3\"/></geometry></visual>\n");
  plain.insert(plain.find(upper) + upper.size(), "\n\n\n\n    <visual><geometry><box size=\"0.05 0.05 0.3\"/></geometry></visual>\n");
  int left_out = 0;
  std::string without = without_mesh_geometry(meshed, left_out);
  EXPECT_EQ(left_out, 2);
  EXPECT_EQ(line_breaks(without), line_breaks(meshed)) << "line numbers stay the file's";
  EXPECT_EQ(without.find("<mesh"), std::string::npos) << without;
  EXPECT_NE(without.find("<box size=\"0.05 0.05 0.3\"/>"), std::string::npos) << "a shape that is no mesh stays";
  std::string path = temporary_directory() + "/meshed_arm.urdf", plain_path = temporary_directory() + "/plain_arm.urdf";
  std::ofstream(path) << meshed;
  std::ofstream(plain_path) << plain;
  Diagnostics diagnostics, plain_diagnostics;
  auto text = imported_model_text(path, diagnostics, false);
  auto plain_text = imported_model_text(plain_path, plain_diagnostics, false);
  ASSERT_TRUE(text) << diagnostics.format();
  ASSERT_TRUE(plain_text) << plain_diagnostics.format();
  const std::string note = "# not carried: 2 <visual> or <collision> mesh(es) not read (";
  std::size_t at = text->find(note);
  ASSERT_NE(at, std::string::npos) << *text;
  std::string rest = *text;
  rest.erase(at, rest.find('\n', at) + 1 - at);
  rest.replace(rest.find("meshed_arm.urdf"), 15, "plain_arm.urdf");
  EXPECT_EQ(rest, *plain_text) << "the same model but for the note";
  // what stops the file without its meshes is said of it: here a joint axis of length zero
  std::string impossible = meshed;
  impossible.replace(impossible.find("<axis xyz=\"0 1 0\"/>"), 19, "<axis xyz=\"0 0 0\"/>");
  std::ofstream(path) << impossible;
  Diagnostics refused;
  EXPECT_FALSE(imported_model_text(path, refused, false));
  EXPECT_NE(refused.format().find("(read without its 2 mesh(es), which MuJoCo could not read)"), std::string::npos) << refused.format();
}

// a robot whose joints are all fixed has nothing to move: the import says so, and writes nothing
TEST(UrdfImport, ARobotThatNothingMovesIsRefused) {
  std::string path = write_file("bolted.urdf", "<robot name=\"bolted\">\n  <link name=\"base\"/>\n  <link name=\"sensor\">\n"
                         "    <inertial><mass value=\"0.3\"/><inertia ixx=\"1e-4\" ixy=\"0\" ixz=\"0\" iyy=\"1e-4\" iyz=\"0\" izz=\"1e-4\"/></inertial>\n"
                         "  </link>\n  <joint name=\"mount\" type=\"fixed\">\n    <parent link=\"base\"/>\n    <child link=\"sensor\"/>\n"
                         "  </joint>\n</robot>\n");
  Diagnostics diagnostics;
  EXPECT_FALSE(imported_model_text(path, diagnostics, false));
  EXPECT_NE(diagnostics.format().find("no joint of the robot moves"), std::string::npos) << diagnostics.format();
  EXPECT_NE(diagnostics.format().find("fixed ones do not"), std::string::npos) << diagnostics.format();
  EXPECT_NE(diagnostics.format().find("imports with --free-base"), std::string::npos) << diagnostics.format();
}

}  // namespace
}  // namespace eomgen::test
