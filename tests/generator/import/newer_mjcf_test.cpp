// MJCF written for a later MuJoCo (generator/import/newer_mjcf.hpp): the known attributes that
// MuJoCo 2.2.2 refuses are left out one by one, each with a warning of what it costs, and the robot
// read is the one of the file without them; an attribute that is not known (a typo) stays an error.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "import/model_writer.hpp"
#include "import/newer_mjcf.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

TEST(NewerMjcf, TheRefusedAttributeIsNamedWhenItIsKnown) {
  auto frc = newer_attribute_refused("Error: Schema violation: unrecognized attribute: 'actuatorfrcrange'\nElement 'joint', line 3\n");
  ASSERT_TRUE(frc);
  EXPECT_EQ(frc->name, "actuatorfrcrange");
  EXPECT_TRUE(frc->enters_equations);
  auto integrator = newer_attribute_refused("Error: invalid keyword: 'implicitfast'\nElement 'option', line 2\n");
  ASSERT_TRUE(integrator);
  EXPECT_FALSE(integrator->enters_equations);
  EXPECT_FALSE(newer_attribute_refused("Error: Schema violation: unrecognized attribute: 'dampin'\nElement 'joint', line 3\n"))
      << "a typo is no newer attribute";
  EXPECT_FALSE(newer_attribute_refused("Error: invalid keyword: 'hing'\nElement 'joint', line 3\n"));
}

TEST(NewerMjcf, OnlyTheAttributeGoesAndTheLinesStay) {
  std::string text = "<body gravcomp=\"1\" name='b'>\n  <joint actuatorgravcomp='true' actuatorfrcrange = \"-1 1\"\n"
                     "         damping=\"0.2\"/>\n<option integrator=\"implicitfast\"/>\n";
  NewerAttribute frc{"actuatorfrcrange", true, ""}, gravcomp{"gravcomp", true, ""}, fast{"implicitfast", false, ""};
  EXPECT_EQ(without_newer_attribute(text, frc), "<body gravcomp=\"1\" name='b'>\n  <joint actuatorgravcomp='true' \n"
                                                "         damping=\"0.2\"/>\n<option integrator=\"implicitfast\"/>\n");
  EXPECT_EQ(without_newer_attribute(text, gravcomp), "<body  name='b'>\n  <joint actuatorgravcomp='true' actuatorfrcrange = \"-1 1\"\n"
                                                     "         damping=\"0.2\"/>\n<option integrator=\"implicitfast\"/>\n")
      << "actuatorgravcomp is another attribute";
  EXPECT_NE(without_newer_attribute(text, fast).find("<option integrator=\"implicit\"/>"), std::string::npos);
}

const char* const pendulum = R"(<mujoco model="newer">
  <option integrator="implicitfast" ls_iterations="5"/>
  <default><joint actuatorfrcrange="-10 10" damping="0.5"/></default>
  <worldbody>
    <body name="a" pos="0 0 1" gravcomp="0">
      <joint name="j1" axis="0 1 0"/>
      <inertial pos="0 0 -0.2" mass="1" diaginertia="0.01 0.01 0.001"/>
      <body name="b" pos="0 0 -0.4">
        <joint name="j2" axis="1 0 0"/>
        <inertial pos="0 0 -0.2" mass="0.5" diaginertia="0.005 0.005 0.001"/>
      </body>
    </body>
  </worldbody>
</mujoco>
)";

TEST(NewerMjcf, AFileOfMujoco3IsReadWithoutItsNewerAttributes) {
  std::string newer = pendulum, older = pendulum;
  for (const char* attribute : {" integrator=\"implicitfast\"", " ls_iterations=\"5\"", "actuatorfrcrange=\"-10 10\" ", " gravcomp=\"0\""})
    older.erase(older.find(attribute), std::string(attribute).size());
  std::string newer_path = temporary_directory() + "/newer.xml", older_path = temporary_directory() + "/older.xml";
  std::ofstream(newer_path) << newer;
  std::ofstream(older_path) << older;
  Diagnostics newer_diagnostics, older_diagnostics;
  auto newer_text = imported_model_text(newer_path, newer_diagnostics, false);
  auto older_text = imported_model_text(older_path, older_diagnostics, false);
  ASSERT_TRUE(newer_text) << newer_diagnostics.format();
  ASSERT_TRUE(older_text) << older_diagnostics.format();
  for (const char* name : {"'implicitfast'", "'ls_iterations'"})
    EXPECT_NE(newer_text->find(std::string("# not carried: ") + name), std::string::npos) << name << " in\n" << *newer_text;
  EXPECT_EQ(newer_text->find("'gravcomp'"), std::string::npos) << "gravcomp is carried (gravity_compensation_test.cpp)";
  EXPECT_EQ(newer_text->find("'actuatorfrcrange'"), std::string::npos) << "carried (joint_force_limits_test.cpp)";
  auto without_notes = [](std::string text) {
    for (const char* kind : {"# not carried: ", "# note: "})
      for (std::size_t at = text.find(kind); at != std::string::npos; at = text.find(kind, at))
        text.erase(at, text.find('\n', at) + 1 - at);
    return text.replace(text.find("newer.xml"), 9, "older.xml");
  };
  EXPECT_EQ(without_notes(*newer_text), *older_text) << "the same robot but for the notes";
  std::string typo = older;
  typo.replace(typo.find("damping="), 8, "dampin=");
  std::ofstream(newer_path) << typo;
  Diagnostics refused;
  EXPECT_FALSE(imported_model_text(newer_path, refused, false));
  EXPECT_NE(refused.format().find("unrecognized attribute: 'dampin'"), std::string::npos) << refused.format();
}

// mujoco_menagerie's scene.xml includes the robot's file, whose attributes are MuJoCo 3's
TEST(NewerMjcf, AnIncludedFileIsReadWithoutItsNewerAttributesToo) {
  EXPECT_EQ(included_files("<mujoco>\n<!-- <include file=\"no.xml\"/> -->\n  <include file=\"robot.xml\"/>\n"
                           "<include  file='parts/arm.xml' />\n<includes file=\"no.xml\"/>\n</mujoco>\n"),
            (std::vector<std::string>{"robot.xml", "parts/arm.xml"}));
  std::string folder = temporary_directory() + "/scene";
  std::filesystem::create_directories(folder);
  std::string robot = pendulum;
  robot.erase(robot.find("  <option"), robot.find("/>\n") + 3 - robot.find("  <option"));
  std::ofstream(folder + "/robot.xml") << robot;
  std::ofstream(folder + "/scene.xml") << "<mujoco model=\"scene\">\n  <option integrator=\"implicitfast\"/>\n"
                                          "  <include file=\"robot.xml\"/>\n</mujoco>\n";
  Diagnostics diagnostics;
  auto text = imported_model_text(folder + "/scene.xml", diagnostics, false);
  ASSERT_TRUE(text) << diagnostics.format();
  EXPECT_NE(text->find("# not carried: 'implicitfast'"), std::string::npos) << *text;
  EXPECT_NE(text->find("# note: the actuator force ranges (MuJoCo 3's actuatorfrcrange) of 2 joint(s)"), std::string::npos)
      << "read in the included file: " << *text;
  EXPECT_NE(text->find("der(j1)"), std::string::npos) << *text;
}

}  // namespace
}  // namespace eomgen::test
