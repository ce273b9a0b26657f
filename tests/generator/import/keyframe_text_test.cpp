// Keyframe arrays that end in white space (generator/import/keyframe_text.hpp), which MuJoCo 2.2.2
// refuses and MuJoCo 3 reads: the file is read with the space taken out, and imports as the same
// file written on one line.
#include <gtest/gtest.h>

#include <string>

#include "import/keyframe_text.hpp"
#include "import/model_writer.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

TEST(KeyframeText, TrailingWhiteSpaceOfAKeysValuesGoes) {
  EXPECT_TRUE(refuses_keyframe_length("Error: key 0: invalid qpos size, expected length 27\nObject name = stand, id = 0\n"));
  EXPECT_FALSE(refuses_keyframe_length("Error: Schema violation: unrecognized attribute: 'qpos'\n"));
  EXPECT_EQ(with_keyframe_values_trimmed("<body pos=\"0 0 1 \"/>\n<key name=\"k\" qpos=\"\n   0.1\n   0.2\n   \" ctrl='1 '/>\n"),
            "<body pos=\"0 0 1 \"/>\n<key name=\"k\" qpos=\"\n   0.1\n   0.2\"\n ctrl='1'/>\n")
      << "the line breaks stay, behind the quote";
}

// two hinges and a motor, with a keyframe whose qpos is `qpos` and ctrl `ctrl`
std::string keyed_arm(const std::string& qpos, const std::string& ctrl) {
  return R"(<mujoco model="keyed">
  <worldbody>
    <body name="a" pos="0 0 1">
      <joint name="j1" axis="0 1 0"/>
      <inertial pos="0 0 -0.2" mass="1" diaginertia="0.01 0.01 0.001"/>
      <body name="b" pos="0 0 -0.4">
        <joint name="j2" axis="1 0 0"/>
        <inertial pos="0 0 -0.2" mass="0.5" diaginertia="0.005 0.005 0.001"/>
      </body>
    </body>
  </worldbody>
  <actuator><motor name="m" joint="j2"/></actuator>
  <keyframe><key name="bent" qpos=")" + qpos + R"(" ctrl=")" + ctrl + R"("/></keyframe>
</mujoco>
)";
}

TEST(KeyframeText, AKeyWrittenOverSeveralLinesIsRead) {
  Diagnostics several_diagnostics, one_diagnostics;
  auto several_text = imported_robot("several.xml", keyed_arm("\n      0.3\n      -0.7\n    ", "0.5 "), several_diagnostics);
  auto one_text = imported_robot("oneline.xml", keyed_arm("0.3 -0.7", "0.5"), one_diagnostics);
  ASSERT_TRUE(several_text) << several_diagnostics.format();
  ASSERT_TRUE(one_text) << one_diagnostics.format();
  EXPECT_NE(one_text->find("bent"), std::string::npos) << *one_text;
  EXPECT_EQ(several_text->replace(several_text->find("several.xml"), 11, "oneline.xml"), *one_text);
}

}  // namespace
}  // namespace eomgen::test
