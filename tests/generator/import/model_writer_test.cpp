// The model file `eomgen import` writes (generator/import/model_writer.hpp), from a robot given as
// plain data: names taken from the robot and made unique, one frame per joint (two hinges in one
// body become two frames), quaternions written as quat(...), ball damping as ½ d |ω|² in the
// quaternion's rates, motors as inputs with gain × u and servos with their bias in q and q', keyframes
// as scenes; numbers in their shortest
// exact form. The
// text derives, and its M is the robot's: for a free body, diag(m, m, m, I).
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <variant>

#include "import/mjcf_reader.hpp"
#include "import/model_writer.hpp"
#include "import/warning_lines.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

Robot two_armed_robot() {
  Robot r;
  r.name = "two-armed robot";
  r.reader = "a test";
  r.initial_state = "qpos0";
  RobotBody base;
  base.name = "base";
  base.mass = 3.5;
  base.principal_inertia = {0.1, 0.2, 0.25};
  RobotJoint root;
  root.name = "root";
  root.type = "free";
  root.initial_position = {0, 0, 1, 1, 0, 0, 0};
  root.initial_velocity = {0, 0, 0, 0, 0, 0.5};
  root.armature = 0.02;
  base.joints.push_back(root);
  RobotBody arm;
  arm.name = "arm";
  arm.parent = 0;
  arm.position = {0.1, 0, 0.2};
  arm.orientation = {0.5, 0.5, 0.5, 0.5};
  arm.mass = 0.7;
  arm.center = {0, 0, -0.1};
  arm.principal_inertia = {0.01, 0.01, 0.002};
  for (const char* name : {"pitch", "yaw"}) {
    RobotJoint hinge;
    hinge.name = name;
    hinge.type = "hinge";
    hinge.axis = {0, 1, 0};
    hinge.armature = 0.05;
    hinge.damping = 0.3;
    hinge.stiffness = 2;
    hinge.spring_reference = {0.25};
    hinge.initial_position = {0.1};
    hinge.initial_velocity = {0};
    hinge.limited = true;
    hinge.range = {-1, 1};
    arm.joints.push_back(hinge);
  }
  RobotBody hand;
  hand.name = "arm";  // a second body of the same name
  hand.parent = 1;
  hand.mass = 0.2;
  hand.principal_inertia = {0.001, 0.001, 0.001};
  RobotJoint wrist;
  wrist.name = "wrist";
  wrist.type = "ball";
  wrist.damping = 0.4;
  wrist.armature = 0.03;
  wrist.initial_position = {1, 0, 0, 0};
  wrist.initial_velocity = {0, 0, 0};
  hand.joints.push_back(wrist);
  r.bodies = {base, arm, hand};
  r.actuators.push_back({"pitch motor", 1, 0, 25, true, {-1, 1}});
  r.actuators.push_back({"yaw", 1, 1, 10, false, {0, 0}});  // named after its joint, as robot files often do
  r.sites.push_back({"tip", 2, {0, 0, -0.05}});
  r.warnings.push_back({"1 tendon(s): not carried", "tendon", "", 0});
  // qpos: root (7), pitch, yaw, wrist (4); qvel: root (6), pitch, yaw, wrist (3)
  r.keyframes.push_back({"stand", {0, 0, 1, 1, 0, 0, 0, 0.2, -0.1, 1, 0, 0, 0}, {0, 0, 0, 0, 0, 0.5, 1, 0, 0, 0, 2}});
  return r;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(ModelWriter, WritesWhatTheRobotIsInItsOwnNames) {
  std::string text = model_file_text(two_armed_robot(), "two_armed", "robot.xml");
  EXPECT_TRUE(has(text, "# not carried: 1 tendon(s): not carried")) << text;
  EXPECT_TRUE(has(text, "pitch_motor = 0  # control range [-1, 1]: clamped, as MuJoCo clamps it")) << text;
  EXPECT_TRUE(has(text, "pitch = 0.1  # range [-1, 1] in the file: not enforced")) << text;
  EXPECT_TRUE(has(text, "name = \"arm_pitch\"\nparent = \"base\"\norigin = [\"0.1\", \"0\", \"0.2\"]\n"
                        "rotation = \"quat(1, 1, 1, 1)\"\njoint = { type = \"revolute\"")) << text;
  EXPECT_TRUE(has(text, "name = \"arm\"\nparent = \"arm_pitch\"\njoint = { type = \"revolute\"")) << text;
  EXPECT_TRUE(has(text, "name = \"arm_2\"\nparent = \"arm\"\njoint = { type = \"ball\"")) << text;
  EXPECT_TRUE(has(text, "joint = { type = \"free\", position = [\"root_x\", \"root_y\", \"root_z\"], quaternion = "
                        "[\"root_qw\", \"root_qx\", \"root_qy\", \"root_qz\"], angular_velocity = [\"root_wx\", \"root_wy\", "
                        "\"root_wz\"], initial_angular_velocity = [0, 0, 0.5] }")) << text;
  // MuJoCo's armature a of each velocity: a free joint's ½ a|v|² + ½ a|ω|², a ball's ½ a|ω|², with
  // |ω|² = 4|q'|² at unit length
  EXPECT_TRUE(has(text, "kinetic = \"(0.02*(der(root_x)^2 + der(root_y)^2 + der(root_z)^2) + 0.08*(der(root_qw)^2 + "
                        "der(root_qx)^2 + der(root_qy)^2 + der(root_qz)^2) + 0.05*der(pitch)^2 + 0.05*der(yaw)^2 + "
                        "0.12*(der(wrist_qw)^2 + der(wrist_qx)^2 + der(wrist_qy)^2 + der(wrist_qz)^2))/2\"")) << text;
  EXPECT_FALSE(has(text, "armature")) << "carried, not warned of: " << text;
  EXPECT_TRUE(has(text, "1.6*(der(wrist_qw)^2 + der(wrist_qx)^2 + der(wrist_qy)^2 + der(wrist_qz)^2)")) << text;
  EXPECT_TRUE(has(text, "potential = \"(2*(pitch - 0.25)^2 + 2*(yaw - 0.25)^2)/2\"")) << text;
  EXPECT_TRUE(has(text, "generalized = { pitch = \"25*clamp(pitch_motor, -1, 1)\", yaw = \"10*yaw_motor\" }")) << text;
  EXPECT_TRUE(has(text, "\nyaw_motor = 0\n")) << "a motor named after its joint: " << text;
  EXPECT_TRUE(has(text, "[[points]]\nname = \"tip\"\nframe = \"arm_2\"\nposition = [\"0\", \"0\", \"-0.05\"]")) << text;
  EXPECT_EQ(identifier_of("2nd link-b"), "_2nd_link_b");
  // a keyframe is a scene's initial state, a quaternion's rates from ω: q' = ½ q ⊗ (0, ω)
  EXPECT_TRUE(has(text, "[scenes.stand]\ninitial = { \"root_x\" = 0, \"der(root_x)\" = 0")) << text;
  EXPECT_TRUE(has(text, "\"root_qz\" = 0, \"der(root_qz)\" = 0.25")) << text;
  EXPECT_TRUE(has(text, "\"pitch\" = 0.2, \"der(pitch)\" = 1, \"yaw\" = -0.1, \"der(yaw)\" = 0")) << text;
  EXPECT_TRUE(has(text, "\"wrist_qz\" = 0, \"der(wrist_qz)\" = 1 }")) << text;
}

TEST(ModelWriter, AServoPullsItsJointTowardItsControl) {
  // MJCF: force = gain u + b0 + b1 (gear q) + b2 (gear q'), generalized force gear × force
  Robot r = two_armed_robot();
  r.actuators = {{"yaw", 1, 1, 2 * 80, false, {0, 0}, {0.5, -80, -4}, 2}};
  std::string text = model_file_text(r, "two_armed", "robot.xml");
  EXPECT_TRUE(has(text, "generalized = { yaw = \"160*yaw_servo + 1 - 320*yaw - 16*der(yaw)\" }")) << text;
  // forcelimited: gear × clamp(force, lo, hi), the force before the gear
  r.actuators[0].force_limited = true;
  r.actuators[0].force_range = {-30, 20};
  text = model_file_text(r, "two_armed", "robot.xml");
  EXPECT_TRUE(has(text, "generalized = { yaw = \"2*clamp(80*yaw_servo + 0.5 - 160*yaw - 8*der(yaw), -30, 20)\" }")) << text;
}

TEST(WarningLines, TheSubjectOfAWarningIsFoundInTheFile) {
  // MuJoCo's compiled model has no source lines: the element is found in the text
  std::string xml = "<mujoco>\n  <tendon>\n    <fixed name=\"split\"/>\n  </tendon>\n  <equality>\n"
                    "    <!-- the fingers move together -->\n    <joint joint1=\"a\" joint2=\"b\"/>\n"
                    "    <connect name=\"loop\" body1=\"c\" body2=\"d\" anchor=\"0 0 0\"/>\n  </equality>\n"
                    "  <actuator>\n    <motor name=\"knee\" joint=\"knee\"/>\n    <cylinder joint=\"z\"/>\n"
                    "  </actuator>\n</mujoco>\n";
  EXPECT_EQ(warning_line(xml, {"1 tendon(s)", "tendon", "", 0}), 2);
  EXPECT_EQ(warning_line(xml, {"equality constraint 1 of 2", "equality", "", 1}), 7);
  EXPECT_EQ(warning_line(xml, {"equality constraint 'loop'", "equality", "loop", 2}), 8);
  EXPECT_EQ(warning_line(xml, {"actuator 'knee'", "actuator", "knee", 1}), 11);
  EXPECT_EQ(warning_line(xml, {"actuator 'actuator1'", "actuator", "", 2}), 12) << "an unnamed one by its place";
  EXPECT_EQ(warning_line(xml, {"1 actuator(s) with a control range", "actuator", "", 0}), 10);
  EXPECT_EQ(warning_line(xml, {"3 geom(s) that make contacts", "", "", 0}), 0) << "no one place";
  EXPECT_EQ(warning_line(xml, {"actuator 'elsewhere'", "actuator", "elsewhere", 3}), 0) << "from an <include>d file";
}

TEST(WarningLines, AWarningAboutAnIncludedElementNamesThatFile) {
  std::vector<std::pair<std::string, std::string>> sources{
      {"robot.xml", "<mujoco>\n  <include file=\"parts/arm.xml\"/>\n  <include file=\"parts/hand.xml\"/>\n"
                    "  <tendon>\n    <fixed name=\"split\"/>\n  </tendon>\n</mujoco>\n"},
      {"parts/arm.xml", "<mujoco>\n  <actuator>\n    <motor name=\"knee\" joint=\"knee\"/>\n"
                        "    <cylinder joint=\"z\"/>\n  </actuator>\n</mujoco>\n"},
      {"parts/hand.xml", "<mujoco>\n  <equality>\n    <joint joint1=\"a\" joint2=\"b\"/>\n  </equality>\n"
                         "  <equality>\n    <joint name=\"grip\" joint1=\"c\" joint2=\"d\"/>\n  </equality>\n</mujoco>\n"}};
  auto expect_place = [&](const RobotWarning& w, const std::string& file, int line) {
    WarningPlace place = warning_place(sources, w);
    EXPECT_EQ(place.file, file) << w.text;
    EXPECT_EQ(place.line, line) << w.text;
  };
  expect_place({"1 tendon(s)", "tendon", "", 0}, "robot.xml", 4);
  expect_place({"actuator 'knee'", "actuator", "knee", 1}, "parts/arm.xml", 3);
  expect_place({"actuator 'actuator2'", "actuator", "", 2}, "parts/arm.xml", 4);
  expect_place({"1 actuator(s) with a control range", "actuator", "", 0}, "parts/arm.xml", 2);
  expect_place({"equality constraint 'grip'", "equality", "grip", 2}, "parts/hand.xml", 6);
  expect_place({"equality constraint 1", "equality", "", 1}, "parts/hand.xml", 3);
  expect_place({"actuator 'nowhere'", "actuator", "nowhere", 3}, "", 0);
  // the robot file has a section of its own: an unnamed element's place may count across files
  sources[0].second.insert(sources[0].second.find("  <tendon>"), "  <actuator>\n    <motor joint=\"hip\"/>\n  </actuator>\n");
  expect_place({"actuator 'actuator3'", "actuator", "", 3}, "", 0);
  expect_place({"actuator 'knee'", "actuator", "knee", 2}, "parts/arm.xml", 3);
}

// `eomgen import`'s warnings name the included file and the line of the element they are about
TEST(WarningLines, ImportLocatesAWarningInAnIncludedFile) {
  std::string dir = temporary_directory();
  std::filesystem::create_directories(dir + "/parts");
  std::ofstream(dir + "/robot.xml") << "<mujoco model=\"pendulum\">\n  <worldbody>\n    <body name=\"link\">\n"
                                       "      <joint name=\"swing\" type=\"hinge\" axis=\"0 1 0\"/>\n"
                                       "      <geom type=\"capsule\" fromto=\"0 0 0 0 0 -0.5\" size=\"0.02\" mass=\"1\"/>\n"
                                       "    </body>\n  </worldbody>\n  <include file=\"parts/drive.xml\"/>\n</mujoco>\n";
  std::ofstream(dir + "/parts/drive.xml") << "<mujoco>\n  <actuator>\n    <motor name=\"push\" joint=\"swing\"/>\n"
                                             "    <cylinder name=\"piston\" joint=\"swing\"/>\n  </actuator>\n</mujoco>\n";
  Diagnostics diagnostics;
  testing::internal::CaptureStderr();
  auto text = imported_model_text(dir + "/robot.xml", diagnostics, false);
  std::string err = testing::internal::GetCapturedStderr();
  ASSERT_TRUE(text) << diagnostics.format();
  EXPECT_NE(err.find(dir + "/parts/drive.xml:4:1: warning: actuator 'piston'"), std::string::npos) << err;
}

TEST(ModelWriter, TheWrittenModelDerivesWithTheRobotsMassMatrix) {
  Robot r = two_armed_robot();
  r.bodies.resize(1);  // the free base alone
  r.actuators.clear();
  r.sites.clear();
  Equations e = derive_text(model_file_text(r, "base_alone", "robot.xml"));
  ASSERT_EQ(e.num_velocities(), 6u);
  ASSERT_EQ(e.symbols.num_coordinates(), 7u);
  EXPECT_EQ(e.method, "appell");
  GiNaC::exmap at = point_by_name(e, {{"root_x", 0.3}, {"root_y", -0.2}, {"root_z", 1}, {"root_qw", 0.5}, {"root_qx", 0.5},
                                      {"root_qy", -0.5}, {"root_qz", 0.5}, {"der(root_x)", 0.1},
                                      {"der(root_y)", 0.2}, {"der(root_z)", 0.3}, {"root_wx", 1}, {"root_wy", 2}, {"root_wz", 3}});
  // m and the principal inertias, each with the root's armature 0.02, as MuJoCo's M has it (the quaternion of unit length)
  const double diagonal[6] = {3.52, 3.52, 3.52, 0.12, 0.22, 0.27};
  for (unsigned i = 0; i < 6; ++i)
    for (unsigned j = 0; j < 6; ++j)
      EXPECT_NEAR(value_at(e.mass_matrix(i, j), at), i == j ? diagonal[i] : 0.0, 1e-14) << i << ", " << j;
}

// MuJoCo's spring on a free joint: ½ k |p − p_s|² and ½ k θ² of the turn conj(q_s) ⊗ q from its rest
// q_s (here a turn by 0.6 about y), whose force in ω is −k θ·axis; on a ball joint, ½ k θ² of the turn
// from its rest, written as the product's components in the joint's coordinates
TEST(ModelWriter, AFreeAndABallJointsSpringsPullTowardsTheirRest) {
  Robot r = two_armed_robot();
  r.bodies[0].joints[0].stiffness = 5;
  r.bodies[0].joints[0].spring_reference = {0.1, 0, 1, std::cos(0.3), 0, std::sin(0.3), 0};
  r.bodies[2].joints[0].stiffness = 3;
  r.bodies[2].joints[0].spring_reference = {0, 0, 0, 1};  // a half turn about z: conj(q_s) ⊗ q = (qz, qy, −qx, −qw)
  std::string text = model_file_text(r, "two_armed", "robot.xml");
  EXPECT_TRUE(has(text, "3*rotation_angle(wrist_qz, wrist_qy, -wrist_qx, -wrist_qw)^2")) << text;
  EXPECT_TRUE(has(text, "5*((root_x - 0.1)^2 + root_y^2 + (root_z - 1)^2)")) << text;
  EXPECT_FALSE(has(text, "stiffness")) << "carried, not warned of: " << text;
  Robot unstated = r;  // a rest the robot does not state: the unturned pose
  unstated.bodies[2].joints[0].spring_reference.clear();
  EXPECT_TRUE(has(model_file_text(unstated, "two_armed", "robot.xml"), "3*rotation_angle(wrist_qw, wrist_qx, wrist_qy, wrist_qz)^2"));
  r.bodies.resize(1);  // the free base alone
  r.actuators.clear();
  r.sites.clear();
  Equations e = derive_text(model_file_text(r, "base_alone", "robot.xml"));
  Eigen::Quaterniond rest(std::cos(0.3), 0, std::sin(0.3), 0), q(0.5, 0.1, -0.7, 0.5);
  q.normalize();
  Eigen::AngleAxisd turn(rest.conjugate() * q);
  Eigen::Vector3d pull = -5 * turn.angle() * turn.axis();
  auto force_at = [&](double x) {
    GiNaC::exmap at = point_by_name(e, {{"root_x", x}, {"root_y", -0.2}, {"root_z", 1}, {"root_qw", q.w()}, {"root_qx", q.x()},
                                        {"root_qy", q.y()}, {"root_qz", q.z()}, {"der(root_x)", 0}, {"der(root_y)", 0},
                                        {"der(root_z)", 0}, {"root_wx", 0}, {"root_wy", 0}, {"root_wz", 0}});
    std::vector<double> f;
    for (const GiNaC::ex& entry : e.forcing) f.push_back(value_at(entry, at));
    return f;
  };
  std::vector<double> f = force_at(0.4), at_rest = force_at(0.1);
  EXPECT_NEAR(f[0] - at_rest[0], -5 * 0.3, 1e-14) << "the position's spring";
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(f[3 + std::size_t(i)], pull[i], 1e-14) << "the turn's spring, ω_" << i;
}

// the reader in-process: a nameless model (MuJoCo calls it "MuJoCo Model") takes the file's name, a
// body's joints come in order with MuJoCo's normalized axes, degrees are radians, a motor's gain is
// gear × gainprm, a keyframe is read whole
TEST(MjcfReader, ReadsWhatMujocoCompiled) {
  std::string path = temporary_directory() + "/nameless.xml";
  std::ofstream(path) << R"xml(<mujoco>
  <compiler angle="degree"/>
  <worldbody>
    <body name="link" pos="0 0 1" euler="90 0 0">
      <joint name="a" type="hinge" axis="0 0 2" range="-45 45" limited="true"/>
      <joint name="b" type="slide" axis="1 0 0"/>
      <geom type="sphere" size="0.1" mass="2"/>
    </body>
  </worldbody>
  <actuator><motor joint="a" gear="3"/></actuator>
  <keyframe><key name="bent" qpos="0.5 0.1"/></keyframe>
</mujoco>)xml";
  auto read = read_with_mujoco(path);
  ASSERT_TRUE(std::holds_alternative<Robot>(read)) << std::get<UnreadableRobot>(read).message;
  const Robot& r = std::get<Robot>(read);
  EXPECT_EQ(r.name, "");
  ASSERT_EQ(r.bodies.size(), 1u);
  const RobotBody& b = r.bodies[0];
  ASSERT_EQ(b.joints.size(), 2u);
  EXPECT_EQ(b.joints[0].type, "hinge");
  EXPECT_EQ(b.joints[1].type, "slide");
  EXPECT_EQ(b.joints[0].axis, (Triple{0, 0, 1}));
  EXPECT_NEAR(b.joints[0].range[1], M_PI / 4, 1e-15);
  EXPECT_NEAR(b.orientation[0], std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(b.mass, 2, 1e-15);
  ASSERT_EQ(r.actuators.size(), 1u);
  EXPECT_EQ(r.actuators[0].gain, 3);
  ASSERT_EQ(r.keyframes.size(), 1u);
  EXPECT_EQ(r.keyframes[0].positions, (std::vector<double>{0.5, 0.1}));
  EXPECT_EQ(r.initial_state, "keyframe 'bent'");
  Diagnostics diagnostics;
  auto text = imported_model_text(path, diagnostics, false);
  ASSERT_TRUE(text) << diagnostics.format();
  EXPECT_NE(text->find("name = \"nameless\""), std::string::npos) << *text;
}

// friction loss the model cannot carry: one warning per value, naming each joint once (a ball
// joint's three dofs are one joint), not one per dof
TEST(MjcfReader, FrictionLossIsOneWarningPerValue) {
  std::string path = temporary_directory() + "/frictional.xml";
  std::ofstream(path) << R"xml(<mujoco>
  <worldbody>
    <body name="upper">
      <joint name="shoulder" type="ball" frictionloss="0.2"/>
      <geom type="sphere" size="0.1" mass="1"/>
      <body name="lower" pos="0 0 -0.5">
        <joint name="elbow" type="hinge" axis="0 1 0" frictionloss="0.2"/>
        <joint name="wrist" type="hinge" axis="1 0 0" frictionloss="0.5"/>
        <joint name="free_spin" type="hinge" axis="0 0 1"/>
        <geom type="sphere" size="0.1" mass="1"/>
      </body>
    </body>
  </worldbody>
</mujoco>)xml";
  auto read = read_with_mujoco(path);
  ASSERT_TRUE(std::holds_alternative<Robot>(read)) << std::get<UnreadableRobot>(read).message;
  std::vector<std::string> friction;
  for (const RobotWarning& w : std::get<Robot>(read).warnings)
    if (w.text.find("friction") != std::string::npos) friction.push_back(w.text);
  ASSERT_EQ(friction.size(), 2u);
  EXPECT_EQ(friction[0], "2 joint(s) with friction loss 0.2 (shoulder, elbow): dry friction is not carried");
  EXPECT_EQ(friction[1], "1 joint(s) with friction loss 0.5 (wrist): dry friction is not carried");
}

// MuJoCo keeps half sizes and turns a fromto capsule onto its segment: the shapes are full lengths
// along the segment, at its middle
TEST(ModelWriter, GeomsBecomeTheBodysShapes) {
  std::string path = temporary_directory() + "/shapes.xml";
  std::ofstream(path) << R"xml(<mujoco>
  <worldbody>
    <body name="link">
      <joint name="a" type="hinge" axis="0 1 0"/>
      <geom type="capsule" fromto="0 0 0 0.4 0 0" size="0.02" mass="1"/>
      <geom type="box" size="0.1 0.2 0.3" pos="0 0 0.5" mass="1"/>
      <geom type="sphere" size="0.05" group="3" mass="1"/>
      <geom type="ellipsoid" size="0.1 0.2 0.3" quat="0 1 0 0" mass="1"/>
    </body>
  </worldbody>
</mujoco>)xml";
  Diagnostics diagnostics;
  auto text = imported_model_text(path, diagnostics, false);
  ASSERT_TRUE(text) << diagnostics.format();
  EXPECT_NE(text->find("shape = [{ type = \"capsule\", size = [\"0.02\", \"0.4\"], offset = [\"0.2\", \"0\", \"0\"], axis = "),
            std::string::npos) << *text;
  EXPECT_NE(text->find("{ type = \"box\", size = [\"0.2\", \"0.4\", \"0.6\"], offset = [\"0\", \"0\", \"0.5\"] }"),
            std::string::npos) << *text;
  EXPECT_NE(text->find("{ type = \"ellipsoid\", size = [\"0.1\", \"0.2\", \"0.3\"], rotation = \"quat(0, 1, 0, 0)\" }"),
            std::string::npos) << "a turned ellipsoid keeps its turn\n" << *text;
  Equations e = derive_text(*text, "shapes.toml");
  EXPECT_EQ(e.drawing[0].shapes.back().type, Shape::Type::ellipsoid);
  EXPECT_EQ(text->find("\"sphere\""), std::string::npos) << "a group-3 geom is hidden, as in MuJoCo's viewer";
}

TEST(ModelWriter, MujocosMessagesBecomeALineAndAMessage) {
  UnreadableRobot a = unreadable_robot("XML Error: problem reading attribute 'pos'\nElement 'body', line 5\n");
  EXPECT_EQ(a.line, 5);
  EXPECT_EQ(a.message, "problem reading attribute 'pos' (element <body>)");
  UnreadableRobot b = unreadable_robot("Error: axis too small in joint 'q' (id = 0)\nObject name = q, id = 0, line = 6, column = -1\n");
  EXPECT_EQ(b.line, 6);
  EXPECT_EQ(b.message, "axis too small in joint 'q' (id = 0)");
  UnreadableRobot c = unreadable_robot("XML Error: Unrecognized XML model type: 'html'");
  EXPECT_EQ(c.line, 0);
  UnreadableRobot d = unreadable_robot("Error: mass and inertia of moving bodies must be larger than mjMINVAL\n"
                                       "Object name = link, id = 1, line = 0, column = -1");
  EXPECT_EQ(d.line, 0);
  EXPECT_EQ(d.message, "mass and inertia of moving bodies must be larger than mjMINVAL ('link')") << "no line: the name finds it";
}

}  // namespace
}  // namespace eomgen::test
