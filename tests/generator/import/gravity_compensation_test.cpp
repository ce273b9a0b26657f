// MuJoCo 2.3's gravcomp (generator/import/gravity_compensation.hpp): read from the file's text, since
// MuJoCo 2.2.2 reads the file without it, and carried as a force at each body's centre of mass, or
// not where gravity or the passive forces are off, or where an unnamed body cannot be placed. Against
// MuJoCo's motion: MujocoImport.GravityCompensationIsAForceAtEachCentreOfMass.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "import/gravity_compensation.hpp"
#include "import/model_writer.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

TEST(GravityCompensation, TheBodiesPartsAreReadByNameAndPlace) {
  GravityCompensations found;
  read_gravity_compensations("<worldbody>\n  <!-- <body name=\"old\" gravcomp=\"1\"/> -->\n  <body name=\"a\" gravcomp=\"0.5\">\n"
                             "    <body gravcomp='2'><bodyx gravcomp=\"3\"/></body>\n    <body name=\"c\" gravcomp=\"0\"/>\n"
                             "    <body name=\"d\"/>\n  </body>\n</worldbody>\n",
                             0, found);
  ASSERT_EQ(found.bodies.size(), 2u) << "commented, zero and absent parts, and other elements, are none";
  EXPECT_EQ(found.bodies[0].body, "a");
  EXPECT_EQ(found.bodies[0].ordinal, 0);
  EXPECT_EQ(found.bodies[0].part, 0.5);
  EXPECT_EQ(found.bodies[1].body, "");
  EXPECT_EQ(found.bodies[1].ordinal, 1);
  EXPECT_EQ(found.bodies[1].part, 2.0);
  EXPECT_EQ(found.body_elements, 4);
  EXPECT_FALSE(found.includes);
  read_gravity_compensations("<body name=\"e\" gravcomp=\"1\"/>", 1, found);
  EXPECT_TRUE(found.includes);
  EXPECT_EQ(found.bodies.back().source, 1u);
  EXPECT_EQ(found.body_elements, 4) << "the count is the file's own";
}

// a hinged rod whose body is half compensated, under `option`; `tip` a body below it
std::string compensated_rod(const std::string& option, const std::string& name = "name=\"rod\" ", const std::string& tip = "") {
  return "<mujoco model=\"rod\">\n  " + option + R"(
  <worldbody>
    <body )" + name + R"(pos="0 0 1" gravcomp="0.5">
      <joint name="swing" axis="0 1 0"/>
      <inertial pos="0.3 0 0" mass="2" diaginertia="0.01 0.01 0.001"/>)" + tip + R"(
    </body>
  </worldbody>
</mujoco>
)";
}

// a tip below the rod that takes off none of its weight
const char* const tip = R"(
      <body name="tip" pos="0.6 0 0"><joint name="bend" axis="0 1 0"/><inertial pos="0.1 0 0" mass="0.5" diaginertia="0.001 0.001 0.001"/></body>)";

std::string imported_rod(const std::string& folder_name, const std::string& file, Diagnostics& diagnostics) {
  std::string folder = temporary_directory() + "/" + folder_name;
  std::filesystem::create_directories(folder);
  std::ofstream(folder + "/rod.xml") << file;
  return imported_model_text(folder + "/rod.xml", diagnostics, false).value_or("");
}

bool states(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(GravityCompensation, OnePartForEveryMovingBodyScalesGravity) {
  Diagnostics diagnostics;
  std::string text = imported_rod("scaled", compensated_rod("<option gravity=\"0 0 -10\"/>"), diagnostics);
  ASSERT_FALSE(text.empty()) << diagnostics.format();
  EXPECT_TRUE(states(text, "acceleration = [\"0\", \"0\", \"-5\"]")) << text;
  EXPECT_FALSE(states(text, "[[forces]]")) << text;
  EXPECT_TRUE(states(text, "every moving body takes off 0.5 of its weight, so that gravity is 0.5 of the file's")) << text;
  // a body welded to the world gives its weight to the world, whatever its part
  std::string welded = compensated_rod("<option gravity=\"0 0 -10\"/>");
  welded.replace(welded.find("  <worldbody>\n") + 14, 0, "    <body name=\"stand\"><inertial pos=\"0 0 0\" mass=\"9\" diaginertia=\"1 1 1\"/></body>\n");
  EXPECT_TRUE(states(imported_rod("welded", welded, diagnostics), "acceleration = [\"0\", \"0\", \"-5\"]"));
}

TEST(GravityCompensation, UnequalPartsAreForcesAtTheCentresOfMass) {
  Diagnostics diagnostics;
  std::string text = imported_rod("half", compensated_rod("<option gravity=\"0 0 -10\"/>", "name=\"rod\" ", tip), diagnostics);
  ASSERT_FALSE(text.empty()) << diagnostics.format();
  EXPECT_TRUE(states(text, "acceleration = [\"0\", \"0\", \"-10\"]")) << text;
  EXPECT_TRUE(states(text, "[[points]]\nname = \"rod_center_of_mass\"\nframe = \"rod\"\nposition = [\"0.3\", \"0\", \"0\"]\n")) << text;
  EXPECT_TRUE(states(text, "[[forces]]  # gravcomp = 0.5\nat = \"rod_center_of_mass\"\nforce = [\"0\", \"0\", \"10\"]\n")) << text;
  EXPECT_FALSE(states(text, "tip_center_of_mass")) << text;
  EXPECT_TRUE(states(text, "# note: gravity compensation (MuJoCo 2.3's gravcomp, read from the file's text): 1 body(ies)")) << text;
  EXPECT_FALSE(states(text, "# not carried: 'gravcomp'")) << text;
  std::string unnamed = imported_rod("unnamed", compensated_rod("<option gravity=\"0 0 -10\"/>", "", tip), diagnostics);
  EXPECT_TRUE(states(unnamed, "force = [\"0\", \"0\", \"10\"]")) << "an unnamed body by its place: " << unnamed;
}

TEST(GravityCompensation, WithoutGravityOrPassiveForcesItDoesNothing) {
  Diagnostics diagnostics;
  std::string weightless = imported_rod("weightless", compensated_rod("<option><flag gravity=\"disable\"/></option>"), diagnostics);
  EXPECT_FALSE(states(weightless, "[[forces]]")) << weightless;
  EXPECT_TRUE(states(weightless, "gravity compensation (gravcomp) of 1 body(ies) does nothing here: there is no gravity")) << weightless;
  std::string passive = imported_rod("passive", compensated_rod("<option><flag spring=\"disable\" damper=\"disable\"/></option>"), diagnostics);
  EXPECT_FALSE(states(passive, "[[forces]]")) << passive;
  EXPECT_TRUE(states(passive, "does nothing here: the passive forces are switched off")) << passive;
  std::string springs = imported_rod("springs", compensated_rod("<option><flag spring=\"disable\"/></option>"), diagnostics);
  EXPECT_TRUE(states(springs, "gravity is 0.5 of the file's")) << "one flag leaves the passive forces on: " << springs;
}

TEST(GravityCompensation, AnUnnamedBodyOfAnIncludedFileIsWarnedOf) {
  std::string folder = temporary_directory() + "/included";
  std::filesystem::create_directories(folder);
  std::string rod = compensated_rod("", "", tip);
  std::size_t body = rod.find("  <worldbody>"), end = rod.find("</mujoco>");
  std::ofstream(folder + "/body.xml") << "<mujoco>\n" + rod.substr(body, end - body) + "</mujoco>\n";
  std::ofstream(folder + "/scene.xml") << "<mujoco model=\"scene\">\n  <include file=\"body.xml\"/>\n</mujoco>\n";
  Diagnostics diagnostics;
  std::string text = imported_model_text(folder + "/scene.xml", diagnostics, false).value_or("");
  ASSERT_FALSE(text.empty()) << diagnostics.format();
  EXPECT_FALSE(states(text, "[[forces]]")) << text;
  EXPECT_TRUE(states(text, "# not carried: the gravity compensation (gravcomp) of 1 unnamed body(ies)")) << text;
}

}  // namespace
}  // namespace eomgen::test
