// `eomgen import --free-base` (generator/import/free_base.hpp): a URDF's root link (or the link a
// fixed joint mounts on the world) set free by a free joint, and an MJCF robot's base body; the
// robots it cannot set free refused with the line and what to do; the imported floating arm's M: its
// translational block is the robot's whole mass (MuJoCo's layout: the base's linear velocity in
// world axes), its joints' block that of the same arm on a fixed base; and its fixed links kept.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <vector>

#include "import/free_base.hpp"
#include "import/model_writer.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

const char* const two_links = R"(<?xml version="1.0"?>
<robot name="arm">
  <link name="base"/>
  <link name="upper"/>
  <joint name="shoulder" type="revolute">
    <parent link="base"/><child link="upper"/>
  </joint>
</robot>
)";

TEST(FreeBase, TheRootLinkFloatsByAJointNamedRoot) {
  FreeBase freed = free_base_of(two_links);
  ASSERT_TRUE(freed.problem.empty()) << freed.problem;
  EXPECT_EQ(freed.link, "base");
  EXPECT_EQ(freed.joint, "root");
  EXPECT_TRUE(freed.note.empty()) << freed.note;
  std::string named_root = two_links;
  named_root.replace(named_root.find("\"shoulder\""), 10, "\"root\"");
  EXPECT_EQ(free_base_of(named_root).joint, "root_2") << "a name no joint has";
}

TEST(FreeBase, WhatCannotBeSetFreeIsRefusedWithItsLine) {
  std::string floating = two_links;
  floating.replace(floating.find("revolute"), 8, "floating");
  FreeBase already = free_base_of(floating);
  EXPECT_EQ(already.line, 5);
  EXPECT_NE(already.problem.find("'shoulder' already makes the robot's base float"), std::string::npos) << already.problem;
  std::string welded = two_links;
  welded.replace(welded.find("<link name=\"base\"/>"), 19, "<link name=\"world\"/>");
  welded.replace(welded.find("<parent link=\"base\"/>"), 21, "<parent link=\"world\"/>");
  FreeBase world = free_base_of(welded);
  EXPECT_EQ(world.line, 5);
  EXPECT_NE(world.hint.find("make joint 'shoulder' type=\"floating\""), std::string::npos) << world.hint;
  std::string two = two_links;
  two.insert(two.find("</robot>"), "  <link name=\"loose\"/>\n");
  FreeBase loose = free_base_of(two);
  EXPECT_NE(loose.problem.find("2 root links ('base' and 'loose')"), std::string::npos) << loose.problem;
}

// a robot fixed to a link named world (a UR arm's world -> base_link) floats by that fixed joint
TEST(FreeBase, ARobotFixedToTheWorldFloatsByThatJoint) {
  std::string welded = two_links;
  welded.replace(welded.find("<link name=\"base\"/>"), 19, "<link name=\"world\"/><link name=\"base\"/>");
  welded.insert(welded.find("</robot>"), "  <joint name=\"mount\" type=\"fixed\"><parent link=\"world\"/><child "
                                         "link=\"base\"/><origin xyz=\"0 0 1.5\"/></joint>\n");
  FreeBase freed = free_base_of(welded);
  ASSERT_TRUE(freed.problem.empty()) << freed.problem;
  EXPECT_EQ(freed.link, "base");
  EXPECT_EQ(freed.joint, "mount");
  EXPECT_NE(freed.note.find("joint 'mount', which fixed link 'base' to the world, is floating instead"), std::string::npos)
      << freed.note;
  std::string two_held = welded;
  two_held.insert(two_held.find("</robot>"), "  <link name=\"table\"/><joint name=\"legs\" type=\"fixed\"><parent "
                                             "link=\"world\"/><child link=\"table\"/></joint>\n");
  FreeBase ambiguous = free_base_of(two_held);
  EXPECT_NE(ambiguous.problem.find("which holds 2 links ('base' and 'table')"), std::string::npos) << ambiguous.problem;
}

// a floating link without mass or inertia that carries one link: the free joint's turn about the
// joint's axis moves nothing (M singular), refused at the link's line; a second link below it, or
// the link given mass, and it is not
TEST(FreeBase, AMasslessFloatingLinkAboveOneJointIsRefused) {
  std::string upper_weighed = two_links;
  upper_weighed.replace(upper_weighed.find("<link name=\"upper\"/>"), 20,
                        "<link name=\"upper\"><inertial><origin xyz=\"0 0 -0.2\"/><mass value=\"1\"/><inertia ixx=\"0.01\" "
                        "ixy=\"0\" ixz=\"0\" iyy=\"0.01\" iyz=\"0\" izz=\"0.002\"/></inertial></link>");
  std::string path = temporary_directory() + "/massless_base.urdf";
  std::ofstream(path) << upper_weighed;
  Diagnostics diagnostics;
  EXPECT_FALSE(imported_model_text(path, diagnostics, false, "", {true}));
  EXPECT_NE(diagnostics.format().find("massless_base.urdf:3:1: error: link 'base' set free has no mass and no moment of "
                                      "inertia and carries one link, 'upper': the free joint's motion along joint "
                                      "'shoulder' moves nothing, so that M is singular"),
            std::string::npos)
      << diagnostics.format();
  EXPECT_NE(diagnostics.format().find("hint: give link 'base' its <inertial>"), std::string::npos) << diagnostics.format();
  std::string two_arms = upper_weighed;
  two_arms.insert(two_arms.find("</robot>"),
                  "  <link name=\"other\"><inertial><mass value=\"1\"/><inertia ixx=\"0.01\" ixy=\"0\" ixz=\"0\" "
                  "iyy=\"0.01\" iyz=\"0\" izz=\"0.002\"/></inertial></link>\n  <joint name=\"elbow\" type=\"revolute\">"
                  "<parent link=\"base\"/><child link=\"other\"/><axis xyz=\"0 1 0\"/></joint>\n");
  std::ofstream(path) << two_arms;
  Diagnostics two_diagnostics;
  EXPECT_TRUE(imported_model_text(path, two_diagnostics, false, "", {true})) << two_diagnostics.format();
}

// tests/crosscheck's seven-joint arm (an MJCF arm whose first link hangs from the world by a hinge),
// its links put in a base body without joints, with the file's text after `base_opens` in that body
std::string arm_on_a_base(const std::string& base_opens) {
  std::string arm = read_file(std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/mjcf/seven_joint_arm.xml");
  arm.replace(arm.find("<worldbody>"), 11,
              "<worldbody>\n    <body name=\"base\" pos=\"0.1 -0.2 0.5\" quat=\"0.8 0 0.6 0\">" + base_opens +
                  "\n      <inertial pos=\"0.01 0 -0.05\" mass=\"4\" diaginertia=\"0.05 0.06 0.07\"/>");
  arm.replace(arm.find("</worldbody>"), 12, "</body>\n  </worldbody>");
  return arm;
}

std::string written(const std::string& name, const std::string& text) {
  std::string path = temporary_directory() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

// without the comments, which name the file read
std::string without_comment_lines(const std::string& model_text) {
  std::string kept;
  for (std::size_t at = 0; at < model_text.size();) {
    std::size_t end = model_text.find('\n', at);
    if (end == std::string::npos) end = model_text.size();
    if (model_text[at] != '#') kept += model_text.substr(at, end - at) + "\n";
    at = end + 1;
  }
  return kept;
}

// --free-base on an MJCF arm on a base body without joints: the model file of the same file with
// <freejoint name="root"/> in that body, but a note; M's translational block the whole mass
TEST(FreeBase, AnMjcfRobotOnAFixedBaseFloatsAsItsFreeJointWouldFloatIt) {
  std::string fixed = written("arm_on_a_base.xml", arm_on_a_base(""));
  std::string floating = written("arm_on_a_free_base.xml", arm_on_a_base("\n      <freejoint name=\"root\"/>"));
  Diagnostics set_free_diagnostics, floating_diagnostics;
  std::optional<std::string> set_free = imported_model_text(fixed, set_free_diagnostics, false, "arm", {true});
  std::optional<std::string> as_written = imported_model_text(floating, floating_diagnostics, false, "arm");
  ASSERT_TRUE(set_free && as_written) << set_free_diagnostics.format() << floating_diagnostics.format();
  EXPECT_EQ(without_comment_lines(*set_free), without_comment_lines(*as_written));
  EXPECT_NE(set_free->find("root_x = 0.1"), std::string::npos) << "starts where the file places the base:\n" << *set_free;
  Equations e = derive_text(*set_free);
  ASSERT_EQ(e.mass_matrix.rows(), 13u);
  double mass = 0;  // the file's masses
  std::string text = arm_on_a_base("");
  std::regex stated("mass=\"([0-9.]+)\"");
  for (auto m = std::sregex_iterator(text.begin(), text.end(), stated); m != std::sregex_iterator(); ++m) mass += std::stod((*m)[1]);
  ASSERT_GT(mass, 4.0);
  std::map<std::string, double> values;
  for (const std::string& name : e.symbols.coordinate_names) values[name] = name == "root_qw" ? 1.0 : 0.3;
  for (const GiNaC::realsymbol& v : e.symbols.velocities) values[v.get_name()] = 0;
  GiNaC::exmap at = point_by_name(e, values);
  for (unsigned r = 0; r < 3; ++r)
    for (unsigned c = 0; c < 3; ++c) EXPECT_NEAR(value_at(e.mass_matrix(r, c), at), r == c ? mass : 0.0, 1e-13) << r << ", " << c;
}

// an MJCF robot that cannot be set free: the line of its body and what to do
TEST(FreeBase, AnMjcfRobotWithoutABaseToSetFreeIsToldWhatToDo) {
  auto refusal = [](const std::string& path) {
    Diagnostics diagnostics;
    EXPECT_FALSE(imported_model_text(path, diagnostics, false, "", {true}));
    return diagnostics.format();
  };
  std::string hinged = refusal(std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/mjcf/seven_joint_arm.xml");
  EXPECT_NE(hinged.find("seven_joint_arm.xml:7:1: error: body 'link1' at the top of the robot is held to the world by its "
                        "hinge 'q1'"),
            std::string::npos)
      << hinged;
  EXPECT_NE(hinged.find("hint: put the robot in a <body> without joints (its base) to set that free, or give 'link1' a "
                        "<freejoint/>"),
            std::string::npos)
      << hinged;
  std::string floating = refusal(written("arm_floating.xml", arm_on_a_base("\n      <freejoint name=\"float\"/>")));
  EXPECT_NE(floating.find("arm_floating.xml:7:1: error: body 'base' floats already, by its free joint 'float'"), std::string::npos)
      << floating;
  std::string two = arm_on_a_base("");
  two.replace(two.find("</worldbody>"), 12,
              "<body name=\"cart\"><inertial pos=\"0 0 0\" mass=\"1\" diaginertia=\"1 1 1\"/><body name=\"wheel\">"
              "<joint name=\"axle\" type=\"hinge\"/><inertial pos=\"0 0 0\" mass=\"1\" diaginertia=\"1 1 1\"/></body>"
              "</body>\n  </worldbody>");
  std::string ambiguous = refusal(written("two_bases.xml", two));
  EXPECT_NE(ambiguous.find("2 bodies in <worldbody> carry joints without having one ('base' and 'cart'): which one floats "
                           "is not clear"),
            std::string::npos)
      << ambiguous;
}

// M with the shoulder at 0.4, the elbow at −0.7 and the base at the origin, unturned
std::vector<std::vector<double>> mass_matrix_at_rest(const std::string& model_text) {
  Equations e = derive_text(model_text);
  std::map<std::string, double> values{{"shoulder", 0.4}, {"elbow", -0.7}};
  for (const std::string& name : e.symbols.coordinate_names) values.emplace(name, name == "root_qw" ? 1.0 : 0.0);
  for (const GiNaC::realsymbol& v : e.symbols.velocities) values[v.get_name()] = 0;
  GiNaC::exmap at = point_by_name(e, values);
  std::vector<std::vector<double>> M(e.mass_matrix.rows(), std::vector<double>(e.mass_matrix.cols()));
  for (unsigned r = 0; r < e.mass_matrix.rows(); ++r)
    for (unsigned c = 0; c < e.mass_matrix.cols(); ++c) M[r][c] = value_at(e.mass_matrix(r, c), at);
  return M;
}

// the two floating arms' M at rest (8×8: the free joint's 6 velocities and the two hinges'), entry by entry
void expect_same_mass_matrix_at_rest(const std::string& model_text, const std::string& expected_text) {
  std::vector<std::vector<double>> M = mass_matrix_at_rest(model_text), expected = mass_matrix_at_rest(expected_text);
  ASSERT_EQ(M.size(), 8u);
  ASSERT_EQ(expected.size(), 8u);
  for (std::size_t r = 0; r < 8; ++r)
    for (std::size_t c = 0; c < 8; ++c) EXPECT_NEAR(M[r][c], expected[r][c], 1e-14) << r << ", " << c;
}

TEST(FreeBase, TheFloatingArmCarriesItsWholeMassAndItsJointsInertia) {
  std::string urdf = std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/urdf/two_link_arm.urdf";
  Diagnostics free_diagnostics, fixed_diagnostics;
  std::optional<std::string> floating = imported_model_text(urdf, free_diagnostics, false, "floating_arm", {true});
  std::optional<std::string> fixed = imported_model_text(urdf, fixed_diagnostics, false, "fixed_arm");
  ASSERT_TRUE(floating && fixed) << free_diagnostics.format() << fixed_diagnostics.format();
  EXPECT_NE(floating->find("joint = { type = \"free\", position = [\"root_x\", \"root_y\", \"root_z\"], quaternion = "
                           "[\"root_qw\", \"root_qx\", \"root_qy\", \"root_qz\"]"),
            std::string::npos)
      << *floating;
  std::vector<std::vector<double>> M = mass_matrix_at_rest(*floating), M_fixed = mass_matrix_at_rest(*fixed);
  ASSERT_EQ(M.size(), 8u);
  ASSERT_EQ(M_fixed.size(), 2u);
  const double mass = 2.0 + 1.2 + 0.8;  // the three links' <mass>
  for (std::size_t r = 0; r < 3; ++r)
    for (std::size_t c = 0; c < 3; ++c) EXPECT_NEAR(M[r][c], r == c ? mass : 0.0, 1e-14) << r << ", " << c;
  for (std::size_t r = 0; r < 2; ++r)
    for (std::size_t c = 0; c < 2; ++c) EXPECT_NEAR(M[6 + r][6 + c], M_fixed[r][c], 1e-14) << r << ", " << c;
}

// the arm mounted on a link named world by a fixed joint, a tool flange fixed to its last link:
// --free-base floats the mount, the model is the one a new root joint gives (the flange is
// massless), but starting where the mount held the base, and the flange keeps its name
TEST(FreeBase, AnArmMountedOnTheWorldFloatsAsIfHungFromIt) {
  std::string urdf = std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/urdf/two_link_arm.urdf";
  std::string mounted = read_file(urdf);
  mounted.insert(mounted.find("</robot>"), "  <link name=\"world\"/><joint name=\"root\" type=\"fixed\"><parent "
                                           "link=\"world\"/><child link=\"base\"/><origin xyz=\"0 0 1.5\"/></joint>\n"
                                           "  <link name=\"tool\"/><joint name=\"flange\" type=\"fixed\"><parent "
                                           "link=\"fore\"/><child link=\"tool\"/><origin xyz=\"0 0 0.3\"/></joint>\n");
  std::string path = temporary_directory() + "/mounted_arm.urdf";
  std::ofstream(path) << mounted;
  Diagnostics diagnostics, hung_diagnostics;
  std::optional<std::string> floating = imported_model_text(path, diagnostics, false, "mounted_arm", {true});
  std::optional<std::string> hung = imported_model_text(urdf, hung_diagnostics, false, "mounted_arm", {true});
  ASSERT_TRUE(floating && hung) << diagnostics.format() << hung_diagnostics.format();
  EXPECT_NE(floating->find("# note: --free-base: joint 'root', which fixed link 'base' to the world"), std::string::npos)
      << *floating;
  EXPECT_NE(floating->find("root_z = 1.5"), std::string::npos) << *floating;
  EXPECT_NE(floating->find("name = \"tool\""), std::string::npos) << "the fixed link keeps its name:\n" << *floating;
  EXPECT_EQ(floating->find("fused"), std::string::npos) << *floating;
  EXPECT_NE(hung->find("root_z = 0"), std::string::npos) << *hung;
  expect_same_mass_matrix_at_rest(*floating, *hung);
}

// a file that asks MuJoCo to fuse static bodies (its own <compiler fusestatic="true">) is read with
// them kept when set free: fused, its root link would join the world and leave the free joint no
// body; eomgen folds fixed links itself, so M is the file's as read without the setting
TEST(FreeBase, AFileThatFusesStaticBodiesIsSetFreeAllTheSame) {
  std::string urdf = std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/urdf/two_link_arm.urdf";
  std::string fusing = read_file(urdf);
  fusing.replace(fusing.find("<robot name=\"two_link_arm\">"), 26,
                 "<robot name=\"two_link_arm\"><mujoco><compiler fusestatic=\"true\"/></mujoco>");
  std::string path = temporary_directory() + "/fusing_arm.urdf";
  std::ofstream(path) << fusing;
  Diagnostics diagnostics, plain_diagnostics;
  std::optional<std::string> floating = imported_model_text(path, diagnostics, false, "arm", {true});
  std::optional<std::string> plain = imported_model_text(urdf, plain_diagnostics, false, "arm", {true});
  ASSERT_TRUE(floating && plain) << diagnostics.format() << plain_diagnostics.format();
  expect_same_mass_matrix_at_rest(*floating, *plain);
}

}  // namespace
}  // namespace eomgen::test
