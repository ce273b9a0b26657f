// MuJoCo 3's <frame> element (generator/import/frame_elements.hpp), which MuJoCo 2.2.2 refuses: read
// as a body welded to its parent. Checked against MuJoCo 2.2.2 reading the same robot with the frame
// composed into its contents by hand (a 90° turn about z and an offset): the same masses and the same
// qacc, whether the body around the frame states its <inertial> (the frame's geoms weigh nothing) or
// takes its inertia from its geoms (they weigh what they weigh).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>

#include <mujoco/mujoco.h>

#include "import/frame_elements.hpp"
#include "import/model_writer.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

// an arm on a hinge whose geom and second link sit in a frame turned 90° about z (FRAMED), or the
// same composed by hand (COMPOSED); INERTIAL is the first link's <inertial> or nothing
const char* const framed_arm = R"xml(<mujoco model="framed">
  <worldbody>
    <body name="upper" pos="0 0 1">
      <joint name="shoulder" axis="0 1 0"/>INERTIAL
      <geom type="capsule" fromto="0 0 0 0 0 -0.3" size="0.03"/>
FRAMED
    </body>
  </worldbody>
</mujoco>
)xml";

const char* const in_a_frame = R"xml(      <frame name="mount" pos="0 0 -0.3" euler="0 0 90">
        <geom type="box" size="0.05 0.02 0.01"/>
        <body name="lower" pos="0.2 0 0">
          <joint name="elbow" axis="1 0 0"/>
          <geom type="capsule" fromto="0 0 0 0 0 -0.25" size="0.02"/>
        </body>
      </frame>)xml";

// x of the frame's axes is y of the body's, y is −x: the box at (0, 0, −0.3), the elbow at (0, 0.2,
// −0.3), both turned 90° about z. (The box on the first link's axis, so that the first link's inertia
// from its geoms stays diagonal: MuJoCo's principal axes of a full one are good to about 1e-12 alone.)
const char* const composed = R"xml(      <geom type="box" pos="0 0 -0.3" euler="0 0 90" size="0.05 0.02 0.01"/>
      <body name="lower" pos="0 0.2 -0.3" euler="0 0 90">
        <joint name="elbow" axis="1 0 0"/>
        <geom type="capsule" fromto="0 0 0 0 0 -0.25" size="0.02"/>
      </body>)xml";

std::string arm_text(const std::string& inertial, const std::string& contents) {
  std::string text = framed_arm;
  text.replace(text.find("INERTIAL"), 8, inertial);
  text.replace(text.find("FRAMED"), 6, contents);
  return text;
}

using Model = std::unique_ptr<mjModel, void (*)(mjModel*)>;

Model loaded(const std::string& name, const std::string& text) {
  std::string path = write_file(name + ".xml", text);
  char error[500] = "";
  Model m(mj_loadXML(path.c_str(), nullptr, error, sizeof error), mj_deleteModel);
  EXPECT_TRUE(m) << error << "\n" << text;
  return m;
}

// MuJoCo's qacc of both at random states, and their moving mass
void expect_same_motion(const mjModel* a, const mjModel* b) {
  ASSERT_EQ(a->nv, b->nv);
  double mass_a = 0, mass_b = 0;
  for (int k = 1; k < a->nbody; ++k) mass_a += a->body_mass[k];
  for (int k = 1; k < b->nbody; ++k) mass_b += b->body_mass[k];
  EXPECT_NEAR(mass_a, mass_b, 1e-12 * mass_b);
  std::unique_ptr<mjData, void (*)(mjData*)> da(mj_makeData(a), mj_deleteData), db(mj_makeData(b), mj_deleteData);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> value(-1.5, 1.5);
  for (int state = 0; state < 10; ++state) {
    for (int k = 0; k < a->nq; ++k) da->qpos[k] = db->qpos[k] = value(random);
    for (int k = 0; k < a->nv; ++k) da->qvel[k] = db->qvel[k] = value(random);
    mj_forward(a, da.get());
    mj_forward(b, db.get());
    for (int k = 0; k < a->nv; ++k) EXPECT_NEAR(da->qacc[k], db->qacc[k], 1e-12 * (1 + std::fabs(db->qacc[k]))) << k;
  }
}

TEST(FrameElements, AFrameIsAWeldedBodyThatWeighsAsInMujoco3) {
  EXPECT_TRUE(refuses_frame_element("Error: XML Error: Schema violation: unrecognized element\nElement 'frame', line 7\n"));
  EXPECT_FALSE(refuses_frame_element("Error: XML Error: Schema violation: unrecognized element\nElement 'frames', line 7\n"));
  const std::string inertial = "\n      <inertial pos=\"0 0 -0.15\" mass=\"1.2\" diaginertia=\"0.01 0.012 0.002\"/>";
  for (const std::string& stated : {inertial, std::string()}) {
    std::string framed = arm_text(stated, in_a_frame);
    EXPECT_EQ(frame_elements(framed), 1);
    std::optional<std::string> welded = with_frames_as_bodies(framed);
    ASSERT_TRUE(welded);
    EXPECT_EQ(welded->find("<frame"), std::string::npos);
    EXPECT_EQ(welded->find("mount"), std::string::npos) << "the frame's name is dropped";
    EXPECT_EQ(welded->find("mass=\"0\"") != std::string::npos, !stated.empty()) << *welded;
    Model a = loaded("welded", *welded), b = loaded("composed", arm_text(stated, composed));
    ASSERT_TRUE(a && b);
    expect_same_motion(a.get(), b.get());
  }
  std::string joint_in_frame = arm_text("", "      <frame pos=\"0 0 -0.3\">\n        <joint name=\"slide\" type=\"slide\"/>\n      </frame>");
  EXPECT_FALSE(with_frames_as_bodies(joint_in_frame)) << "a joint would move the welded body";
}

TEST(FrameElements, AFileWithFramesIsImported) {
  Diagnostics diagnostics;
  auto text = imported_robot("framed.xml", arm_text("", in_a_frame), diagnostics);
  ASSERT_TRUE(text) << diagnostics.format();
  EXPECT_NE(text->find("# note: 1 <frame> element(s) (MuJoCo 3) read as bodies welded to their parents"), std::string::npos) << *text;
  EXPECT_NE(text->find("elbow"), std::string::npos) << *text;
}

}  // namespace
}  // namespace eomgen::test
