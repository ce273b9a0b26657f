// MJCF whose texture and skin files MuJoCo cannot read (generator/import/missing_textures.hpp), as
// dm_control's dog.xml copied without its pictures: read as plain textures and without the skins,
// the robot being the file's without them, and the files named once in a comment.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "import/missing_textures.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

TEST(MissingTextures, MujocosMessageNamesTheElementTheNameAndTheFile) {
  auto jpg = unreadable_drawing("Error: could not open texture file 'pictures/a.jpg'\nObject name = grid, id = 2, line = 7\n");
  ASSERT_TRUE(jpg);
  EXPECT_EQ(jpg->element, "texture");
  EXPECT_EQ(jpg->name, "grid");
  EXPECT_EQ(jpg->file, "pictures/a.jpg");
  auto png = unreadable_drawing("Error: PNG file load error 'x' in texture id = 3\nObject name = , id = 3, line = 9\n");
  ASSERT_TRUE(png);
  EXPECT_EQ(png->element, "texture");
  EXPECT_EQ(png->name, "") << "an unnamed texture";
  auto skin = unreadable_drawing("Error: could not open SKN file 'dog_skin.skn'\nObject name = skin, id = 0, line = 330\n");
  ASSERT_TRUE(skin);
  EXPECT_EQ(skin->element, "skin");
  EXPECT_EQ(skin->file, "dog_skin.skn");
  EXPECT_FALSE(unreadable_drawing("Error: could not open STL file 'assets/link1.stl'\nObject name = link1, id = 0\n"))
      << "a mesh is missing_meshes.hpp's";
}

TEST(MissingTextures, ATextureIsMadePlainAndASkinIsTakenOut) {
  std::vector<std::pair<std::string, std::string>> sources = {
      {"a.xml", R"(<texture name="grid" type="2d" file="grid.png"/><texture name="sky" builtin="gradient" width="4" height="4"/>)"},
      {"b.xml", R"(<skin name="coat" file="coat.skn" material="fur"/><skin name="other" file="other.skn"/>)"}};
  std::vector<std::string> files;
  EXPECT_TRUE(without_unreadable_drawing(sources, {"texture", "grid", "grid.png"}, files));
  EXPECT_EQ(sources[0].second, R"(<texture builtin="flat" width="8" height="8" name="grid" type="2d" file="grid.png"/>)"
                               R"(<texture name="sky" builtin="gradient" width="4" height="4"/>)");
  EXPECT_TRUE(without_unreadable_drawing(sources, {"skin", "coat", "coat.skn"}, files));
  EXPECT_EQ(sources[1].second, R"(<skin name="other" file="other.skn"/>)");
  EXPECT_EQ(files, (std::vector<std::string>{"grid.png", "coat.skn"}));
  EXPECT_FALSE(without_unreadable_drawing(sources, {"texture", "grid", "grid.png"}, files))
      << "a texture already plain is not changed again: the loop that asks MuJoCo ends";
}

TEST(MissingTextures, AnUnnamedTextureIsFoundByItsFile) {
  std::vector<std::pair<std::string, std::string>> sources = {
      {"a.xml", R"(<texture type="cube" builtin="checker" width="8" height="8"/><texture type="cube" fileup="up.png" width="16"/>)"}};
  std::vector<std::string> files;
  EXPECT_TRUE(without_unreadable_drawing(sources, {"texture", "", ""}, files));
  EXPECT_EQ(sources[0].second, R"(<texture type="cube" builtin="checker" width="8" height="8"/>)"
                               R"(<texture builtin="flat" height="8" type="cube" fileup="up.png" width="16"/>)");
  EXPECT_EQ(files, (std::vector<std::string>{"up.png"}));
  sources = {{"a.xml", R"(<texture type="2d" file="pictures/marble.png"/>)"}};
  EXPECT_TRUE(without_unreadable_drawing(sources, {"texture", "marble", "pictures/marble.png"}, files))
      << "MuJoCo names an unnamed texture after its file";
  EXPECT_EQ(sources[0].second, R"(<texture builtin="flat" width="8" height="8" type="2d" file="pictures/marble.png"/>)");
}

// a two-link arm drawn with textures and a skin; DRAWING is what the file has of them
const char* const drawn_arm = R"xml(<mujoco model="drawn">
  <asset>DRAWING
    <texture name="sky" type="skybox" builtin="gradient" rgb1="1 1 1" rgb2="0 0 0" width="16" height="16"/>
  </asset>
  <worldbody>
    <body name="a" pos="0 0 1">
      <joint name="j1" type="hinge" axis="0 1 0" damping="0.3"/>
      <geom type="capsule" fromto="0 0 0 0 0 -0.4" size="0.05" material="fur"/>
      <body name="b" pos="0 0 -0.4">
        <joint name="j2" type="hinge" axis="1 0 0"/>
        <geom type="capsule" fromto="0 0 0 0 0 -0.3" size="0.02"/>
      </body>
    </body>
  </worldbody>
</mujoco>
)xml";

std::string drawn(const std::string& drawing) {
  std::string text = drawn_arm;
  text.replace(text.find("DRAWING"), 7, drawing);
  return text;
}

TEST(MissingTextures, ARobotWithoutItsPicturesIsTheRobotWithPlainOnes) {
  const std::string pictures = R"(
    <texture name="fur" type="2d" file="fur.png"/>
    <texture type="skybox" file="sky.png"/>
    <texture type="2d" file="pictures/marble.png"/>
    <material name="fur" texture="fur"/>
    <skin name="coat" file="coat.skn" material="fur"/>)";
  const std::string plain = R"(
    <texture name="fur" type="2d" builtin="flat" width="8" height="8"/>
    <texture type="skybox" builtin="flat" width="8" height="8"/>
    <texture name="marble" type="2d" builtin="flat" width="8" height="8"/>
    <material name="fur" texture="fur"/>)";
  Diagnostics diagnostics;
  auto with_pictures = imported_robot("drawn.xml", drawn(pictures), diagnostics);
  ASSERT_TRUE(with_pictures) << diagnostics.format();
  EXPECT_NE(with_pictures->find("# not carried: 4 texture or skin file(s) MuJoCo cannot read ('coat.skn', 'fur.png', 'sky.png' "
                                "and 1 more): read as plain textures and without the skins, which draw the robot and never act"),
            std::string::npos)
      << "MuJoCo 2.2.2 reads the skins first, then the textures in order\n" << *with_pictures;
  auto without = imported_robot("drawn.xml", drawn(plain), diagnostics);
  ASSERT_TRUE(without) << diagnostics.format();
  EXPECT_EQ(without_lines_starting(*with_pictures, "#"), without_lines_starting(*without, "#"));
}

}  // namespace
}  // namespace eomgen::test
