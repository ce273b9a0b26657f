// MJCF whose mesh files MuJoCo cannot read (generator/import/missing_meshes.hpp): read with
// placeholders when every body's inertia is its <inertial>, the robot then being the file's
// without the meshes; refused, naming the body, when a body takes its inertia from its geoms.
#include <gtest/gtest.h>

#include <string>

#include "import/missing_meshes.hpp"
#include "import/model_writer.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

TEST(MissingMeshes, MujocosMessageNamesTheFileAndItsFormat) {
  auto stl = unreadable_mesh("Error: could not open STL file 'assets/link1.stl'\nObject name = link1, id = 0\n");
  ASSERT_TRUE(stl);
  EXPECT_EQ(stl->file, "assets/link1.stl");
  EXPECT_EQ(stl->format, "STL");
  auto obj = unreadable_mesh("Error: could not parse OBJ file 'meshes/hand.obj': \nno vertices\n");
  ASSERT_TRUE(obj);
  EXPECT_EQ(obj->format, "OBJ");
  EXPECT_FALSE(unreadable_mesh("Error: Schema violation: unrecognized attribute: 'dampin'"));
  auto placeholder = placeholder_mesh(*stl, 0.01);
  ASSERT_TRUE(placeholder);
  EXPECT_EQ(placeholder->first, "link1.stl") << "MuJoCo's virtual files are found by their names without a path";
  EXPECT_EQ(placeholder->second.size(), 84u + 4 * 50) << "a binary STL of four triangles";
  EXPECT_FALSE(placeholder_mesh({"x.msh", "MSH"}, 0.01));
}

// a two-link arm whose link meshes are not there: MESHES is what the second body has besides them
const char* const meshy_arm = R"xml(<mujoco model="meshy">
  <compiler meshdir="assets"/>
  <asset>
    <mesh name="link1" file="link1.stl"/>
    <mesh name="link2" file="link2.obj"/>
  </asset>
  <worldbody>
    <body name="a" pos="0 0 1">
      <joint name="j1" type="hinge" axis="0 1 0"/>
      <inertial pos="0.1 0 -0.2" mass="1" diaginertia="0.02 0.025 0.015"/>
      <geom type="mesh" mesh="link1"/>
      <body name="b" pos="0 0 -0.4">
        <joint name="j2" type="hinge" axis="1 0 0"/>MESHES
        <geom type="capsule" fromto="0 0 0 0 0 -0.3" size="0.02"/>
      </body>
    </body>
  </worldbody>
</mujoco>
)xml";

std::string arm(const std::string& second_body, bool with_assets = true) {
  std::string text = meshy_arm;
  text.replace(text.find("MESHES"), 6, second_body);
  if (!with_assets) {
    text.erase(text.find("  <compiler"), text.find("<worldbody>") - text.find("  <compiler"));
    text.erase(text.find("      <geom type=\"mesh\" mesh=\"link1\"/>\n"), 38);
  }
  return text;
}

// the model file without its comments, which name what was left out
std::string without_comments(const std::string& text) { return without_lines_starting(text, "#"); }

std::optional<std::string> imported(const std::string& xml, Diagnostics& diagnostics) {
  return imported_robot("meshy.xml", xml, diagnostics);
}

TEST(MissingMeshes, ABodyWithItsInertialIsReadWithoutItsMeshes) {
  const std::string inertial = "\n        <inertial pos=\"0 0 -0.15\" mass=\"0.7\" diaginertia=\"0.004 0.005 0.006\"/>";
  Diagnostics diagnostics;
  auto text = imported(arm(inertial + "\n        <geom type=\"mesh\" mesh=\"link2\"/>\n        <geom type=\"box\" mesh=\"link2\"/>"),
                       diagnostics);
  ASSERT_TRUE(text) << diagnostics.format();
  EXPECT_NE(text->find("# not carried: 2 mesh file(s) MuJoCo cannot read ('assets/link1.stl', 'assets/link2.obj'): every body's "
                       "mass and inertia come from its <inertial> (checked)"),
            std::string::npos) << *text;
  auto plain = imported(arm(inertial, false), diagnostics);
  ASSERT_TRUE(plain) << diagnostics.format();
  EXPECT_EQ(without_comments(*text), without_comments(*plain))
      << "the robot is the file's without its meshes; the box fitted to a mesh is not drawn either";
}

// a mesh drawn in millimetres (scale 0.001, as Robotiq's gripper files have it) on a body without an
// <inertial>: the placeholder scaled with it keeps a volume MuJoCo accepts (one of a centimetre's
// edge had 1e-16 m³, and MuJoCo's "mesh volume is too small" hid the reason), so that the body is
// refused by name
TEST(MissingMeshes, AMeshScaledFromMillimetresStillNamesTheBodyThatNeedsIt) {
  std::string millimetres = arm("\n        <geom type=\"mesh\" mesh=\"link2\"/>");
  millimetres.replace(millimetres.find("file=\"link2.obj\""), 16, "file=\"link2.obj\" scale=\"0.001 0.001 0.001\"");
  Diagnostics diagnostics;
  EXPECT_FALSE(imported(millimetres, diagnostics));
  EXPECT_NE(diagnostics.format().find("body 'b' takes its mass and inertia from its geoms, a mesh among them"), std::string::npos)
      << diagnostics.format();
}

TEST(MissingMeshes, ABodyThatTakesItsInertiaFromAMeshIsRefusedByName) {
  Diagnostics diagnostics;
  EXPECT_FALSE(imported(arm("\n        <geom type=\"mesh\" mesh=\"link2\"/>"), diagnostics));
  std::string said = diagnostics.format();
  EXPECT_NE(said.find("meshy.xml:12:1: error: body 'b' takes its mass and inertia from its geoms, a mesh among them, and "
                      "MuJoCo cannot read the mesh file(s) 'assets/link1.stl', 'assets/link2.obj'"),
            std::string::npos) << said;
  EXPECT_NE(said.find("hint: put the mesh files where the file names them, or give the body an <inertial>"), std::string::npos)
      << said;
}

}  // namespace
}  // namespace eomgen::test
