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
  auto frc = newer_mjcf_refused("Error: Schema violation: unrecognized attribute: 'actuatorfrcrange'\nElement 'joint', line 3\n");
  ASSERT_TRUE(frc);
  EXPECT_EQ(frc->name, "actuatorfrcrange");
  EXPECT_TRUE(frc->enters_equations);
  auto integrator = newer_mjcf_refused("Error: invalid keyword: 'implicitfast'\nElement 'option', line 2\n");
  ASSERT_TRUE(integrator);
  EXPECT_FALSE(integrator->enters_equations);
  EXPECT_FALSE(newer_mjcf_refused("Error: Schema violation: unrecognized attribute: 'dampin'\nElement 'joint', line 3\n"))
      << "a typo is no newer attribute";
  EXPECT_FALSE(newer_mjcf_refused("Error: invalid keyword: 'hing'\nElement 'joint', line 3\n"));
}

TEST(NewerMjcf, OnlyTheAttributeGoesAndTheLinesStay) {
  std::string text = "<body gravcomp=\"1\" name='b'>\n  <joint actuatorgravcomp='true' actuatorfrcrange = \"-1 1\"\n"
                     "         damping=\"0.2\"/>\n<option integrator=\"implicitfast\"/>\n";
  NewerMjcf frc{"actuatorfrcrange", true, ""}, gravcomp{"gravcomp", true, ""}, fast{"implicitfast", false, ""};
  EXPECT_EQ(without_newer_mjcf(text, frc), "<body gravcomp=\"1\" name='b'>\n  <joint actuatorgravcomp='true' \n"
                                                "         damping=\"0.2\"/>\n<option integrator=\"implicitfast\"/>\n");
  EXPECT_EQ(without_newer_mjcf(text, gravcomp), "<body  name='b'>\n  <joint actuatorgravcomp='true' actuatorfrcrange = \"-1 1\"\n"
                                                     "         damping=\"0.2\"/>\n<option integrator=\"implicitfast\"/>\n")
      << "actuatorgravcomp is another attribute";
  EXPECT_NE(without_newer_mjcf(text, fast).find("<option integrator=\"implicit\"/>"), std::string::npos);
}

// a name as common as a light's `type` is known on that element alone, and left out of its tags alone
TEST(NewerMjcf, ALightsTypeGoesFromTheLightsAlone) {
  auto light = newer_mjcf_refused("Error: Schema violation: unrecognized attribute: 'type'\nElement 'light', line 3\n");
  ASSERT_TRUE(light);
  EXPECT_EQ(light->element, "light");
  EXPECT_FALSE(light->enters_equations);
  EXPECT_FALSE(newer_mjcf_refused("Error: Schema violation: unrecognized attribute: 'type'\nElement 'tendon', line 3\n"));
  auto viewer = newer_mjcf_refused("Error: Schema violation: unrecognized attribute: 'realtime'\nElement 'global', line 3\n");
  ASSERT_TRUE(viewer);
  EXPECT_TRUE(viewer->element.empty());
  EXPECT_EQ(without_newer_mjcf("<light type=\"spot\" pos=\"0 0 1\"/>\n<joint type=\"slide\"/>\n", *light),
            "<light  pos=\"0 0 1\"/>\n<joint type=\"slide\"/>\n");
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

// MuJoCo 3's sensors (Unitree's files have a jointactuatorfrc for every joint): 2.2.2's schema
// refuses the element, and a sensor never acts, so each such sensor is left out of the <sensor>
// sections, with a warning; the same name elsewhere (a <contact> section) and a typo stay
TEST(NewerMjcf, ASensorOfMujoco3IsLeftOutOfTheSensorSections) {
  auto sensor = newer_mjcf_refused("Error: XML Error: Schema violation: unrecognized element\nElement 'jointactuatorfrc', line 12\n");
  ASSERT_TRUE(sensor);
  EXPECT_EQ(sensor->name, "jointactuatorfrc");
  EXPECT_TRUE(sensor->sensor);
  EXPECT_FALSE(sensor->enters_equations);
  EXPECT_FALSE(newer_mjcf_refused("Error: XML Error: Schema violation: unrecognized element\nElement 'jointactuatorfrcs', line 12\n"));
  std::string text = "<contact>\n  <contact name=\"kept\"/>\n</contact>\n<sensor>\n  <jointpos joint=\"j1\"/>\n"
                     "  <contact name=\"c\"\n          geom1=\"g\"/>\n  <contact name=\"d\"><!-- x --></contact>\n</sensor>\n";
  NewerMjcf contact{"contact", false, "", true};
  EXPECT_EQ(without_newer_mjcf(text, contact),
            "<contact>\n  <contact name=\"kept\"/>\n</contact>\n<sensor>\n  <jointpos joint=\"j1\"/>\n  \n\n  \n</sensor>\n");
}

TEST(NewerMjcf, AFileWithSensorsOfMujoco3IsReadWithoutThem) {
  std::string older = pendulum;
  older.replace(older.find("</mujoco>"), 9, "  <sensor>\n    <jointpos joint=\"j1\"/>\n  </sensor>\n</mujoco>");
  std::string newer = older;
  newer.replace(newer.find("    <jointpos"), 0, "    <jointactuatorfrc name=\"f1\" joint=\"j1\"/>\n    <e_kinetic name=\"T\"/>\n");
  Diagnostics newer_diagnostics, older_diagnostics;
  auto newer_text = imported_robot("sensing.xml", newer, newer_diagnostics);
  auto older_text = imported_robot("sensed.xml", older, older_diagnostics);
  ASSERT_TRUE(newer_text) << newer_diagnostics.format();
  ASSERT_TRUE(older_text) << older_diagnostics.format();
  for (const char* name : {"'jointactuatorfrc'", "'e_kinetic'"})
    EXPECT_NE(newer_text->find(std::string("# not carried: ") + name), std::string::npos) << name << " in\n" << *newer_text;
  std::string without_notes = *newer_text;
  for (std::size_t at = without_notes.find("a sensor ("); at != std::string::npos; at = without_notes.find("a sensor (")) {
    std::size_t line = without_notes.rfind('\n', at) + 1;
    without_notes.erase(line, without_notes.find('\n', at) + 1 - line);
  }
  EXPECT_EQ(without_notes.replace(without_notes.find("sensing.xml"), 11, "sensed.xml"), *older_text);
}

// an element of MuJoCo 3 that eomgen does not carry stays MuJoCo's error, with a hint that says so
TEST(NewerMjcf, AnElementThatIsNotCarriedSaysWhatToDo) {
  auto hint = newer_element_hint("Error: XML Error: Schema violation: unrecognized element\nElement 'replicate', line 27\n");
  ASSERT_TRUE(hint);
  EXPECT_NE(hint->find("write its copies out as bodies"), std::string::npos) << *hint;
  EXPECT_FALSE(newer_element_hint("Error: XML Error: Schema violation: unrecognized element\nElement 'bodies', line 3\n"));
  EXPECT_FALSE(newer_element_hint("Error: Schema violation: unrecognized attribute: 'replicate'\nElement 'body', line 3\n"));
  std::string replicated = pendulum;
  replicated.replace(replicated.find("  </worldbody>"), 0,
                     "    <replicate count=\"3\" offset=\"0.5 0 0\">\n      <body name=\"c\"><joint/><geom size=\"0.1\"/></body>\n"
                     "    </replicate>\n");
  Diagnostics diagnostics;
  EXPECT_FALSE(imported_robot("replicated.xml", replicated, diagnostics));
  EXPECT_NE(diagnostics.format().find("hint: MuJoCo 3's <replicate> is not carried"), std::string::npos) << diagnostics.format();
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
