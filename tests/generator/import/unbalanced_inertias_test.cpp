// Inertias that no rigid body has (generator/import/unbalanced_inertias.hpp): MuJoCo's compiler
// refuses a URDF link whose principal moments break A + B >= C, and with balanceinertia would
// average them; the import takes them as the file states them, and a valid link's too (MuJoCo's
// principal axes turn a full tensor). The imported tensors are checked against the
// stated ones turned by rpy by hand, and the imported arm's M against the stated tensor.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <variant>

#include <mujoco/mujoco.h>

#include "import/mjcf_reader.hpp"
#include "import/model_writer.hpp"
#include "import/unbalanced_inertias.hpp"
#include "model/model.hpp"
#include "parse/model_file.hpp"
#include "pipeline.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

// R diag(moments) Rᵀ, R the quaternion's rotation: the tensor in the body's frame
std::array<double, 9> body_frame_tensor(const Triple& moments, const Quaternion& axes) {
  mjtNum q[4] = {axes[0], axes[1], axes[2], axes[3]}, R[9];
  mju_quat2Mat(R, q);
  std::array<double, 9> I{};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) I[std::size_t(3 * r + c)] += R[3 * r + k] * moments[std::size_t(k)] * R[3 * c + k];
  return I;
}

std::string one_link_urdf(const std::string& inertial) {
  return "<robot name=\"unbalanced\">\n  <link name=\"base\"/>\n  <link name=\"arm\">\n    <inertial>\n" + inertial +
         "    </inertial>\n  </link>\n  <joint name=\"swing\" type=\"continuous\">\n    <parent link=\"base\"/>\n"
         "    <child link=\"arm\"/>\n    <origin xyz=\"0 0 0\"/>\n    <axis xyz=\"0 0 1\"/>\n  </joint>\n</robot>\n";
}

std::array<double, 9> product(const std::array<double, 9>& a, const std::array<double, 9>& b) {
  std::array<double, 9> c{};
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j) c[std::size_t(3 * r + j)] += a[std::size_t(3 * r + k)] * b[std::size_t(3 * k + j)];
  return c;
}

// URDF's rpy as a matrix, R = Rz(yaw) Ry(pitch) Rx(roll), each factor written out
std::array<double, 9> rpy_matrix(double roll, double pitch, double yaw) {
  double cr = std::cos(roll), sr = std::sin(roll), cp = std::cos(pitch), sp = std::sin(pitch), cy = std::cos(yaw), sy = std::sin(yaw);
  std::array<double, 9> Rz{cy, -sy, 0, sy, cy, 0, 0, 0, 1}, Ry{cp, 0, sp, 0, 1, 0, -sp, 0, cp}, Rx{1, 0, 0, 0, cr, -sr, 0, sr, cr};
  return product(product(Rz, Ry), Rx);
}

// R I Rᵀ for that R
std::array<double, 9> turned_by_rpy(const std::array<double, 9>& I, double roll, double pitch, double yaw) {
  std::array<double, 9> R = rpy_matrix(roll, pitch, yaw), Rt{};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) Rt[std::size_t(3 * r + c)] = R[std::size_t(3 * c + r)];
  return product(product(R, I), Rt);
}

// the URDF with its link `root` hung from the world by a floating joint of its own, whose fixed
// links MuJoCo then fuses (a free joint goes at the top level only); `eomgen import --free-base`
// keeps them, so the fused bodies' inertias are those of such a file
std::string with_floating_joint(std::string urdf, const std::string& root) {
  std::size_t robot = urdf.find('>', urdf.find("<robot")) + 1;
  urdf.insert(robot, "<link name=\"world\"/><joint name=\"root\" type=\"floating\"><parent link=\"world\"/><child link=\"" +
                         root + "\"/></joint>");
  return urdf;
}

// the body `name`, the root link, of the URDF text read on a floating base of its own (written to
// `file`), or nothing
std::optional<RobotBody> floating_body(const std::string& file, const std::string& urdf, const std::string& name) {
  auto read = read_with_mujoco(write_file(file, with_floating_joint(urdf, name)));
  if (const auto* failure = std::get_if<UnreadableRobot>(&read)) {
    ADD_FAILURE() << failure->message;
    return std::nullopt;
  }
  for (const RobotBody& b : std::get<Robot>(read).bodies)
    if (b.name == name) return b;
  return std::nullopt;
}

// A link MuJoCo reads without complaint takes its tensor as stated too: MuJoCo's compiler leaves
// its principal axes of a turned full tensor off the stated one (2e-11 on these moments of about
// 0.03, measured once), the import's are the stated tensor's to rounding
TEST(UnbalancedInertias, AValidLinksInertiaIsTheTextsNotMujocosPrincipalAxes) {
  std::string urdf = one_link_urdf(
      "      <origin xyz=\"0.1 -0.02 0.03\" rpy=\"0.3 -0.7 1.1\"/>\n      <mass value=\"1.5\"/>\n"
      "      <inertia ixx=\"0.02\" ixy=\"0.003\" ixz=\"-0.002\" iyy=\"0.025\" iyz=\"0.004\" izz=\"0.03\"/>\n");
  const std::array<double, 9> stated = turned_by_rpy({0.02, 0.003, -0.002, 0.003, 0.025, 0.004, -0.002, 0.004, 0.03}, 0.3, -0.7, 1.1);
  std::vector<LinkInertia> links = urdf_link_inertias(urdf);
  ASSERT_EQ(links.size(), 1u);
  EXPECT_EQ(links[0].link, "arm");
  EXPECT_EQ(links[0].mass, 1.5);
  EXPECT_FALSE(links[0].unbalanced);
  std::string path = write_file("valid.urdf", urdf);
  auto read = read_with_mujoco(path);
  ASSERT_TRUE(std::holds_alternative<Robot>(read)) << std::get<UnreadableRobot>(read).message;
  const RobotBody* arm = nullptr;
  for (const RobotBody& b : std::get<Robot>(read).bodies)
    if (b.name == "arm") arm = &b;
  ASSERT_NE(arm, nullptr);
  std::array<double, 9> imported = body_frame_tensor(arm->principal_inertia, arm->inertia_axes);
  // the eigen-decomposition and R diag Rᵀ again round: 2e-15 of the largest diagonal entry
  double largest = std::max({stated[0], stated[4], stated[8]});
  for (std::size_t k = 0; k < 9; ++k) EXPECT_NEAR(imported[k], stated[k], 2e-15 * largest) << k;
}

TEST(UnbalancedInertias, AnArmWhoseMomentsBreakTheTriangleKeepsThemAsStated) {
  // about the link's frame, turned by rpy = (0, 0, π/2): I' = R I Rᵀ has I'xx = Iyy, I'yy = Ixx,
  // I'xy = −Ixy, I'xz = −Iyz, I'yz = Ixz, I'zz = Izz; the moments 0.00085, 0.00215, 0.01 break A + B ≥ C
  std::string urdf = one_link_urdf(
      "      <origin xyz=\"0.1 0 0\" rpy=\"0 0 1.5707963267948966\"/>\n      <mass value=\"1\"/>\n"
      "      <inertia ixx=\"0.001\" ixy=\"0.0005\" ixz=\"0.0003\" iyy=\"0.002\" iyz=\"0\" izz=\"0.01\"/>\n");
  const std::array<double, 9> stated{0.002, -0.0005, 0, -0.0005, 0.001, 0.0003, 0, 0.0003, 0.01};
  std::string path = write_file("unbalanced.urdf", urdf);
  auto read = read_with_mujoco(path);
  ASSERT_TRUE(std::holds_alternative<Robot>(read)) << std::get<UnreadableRobot>(read).message;
  const Robot& robot = std::get<Robot>(read);
  std::array<double, 9> restored{};
  for (const RobotBody& b : robot.bodies)
    if (b.name == "arm") restored = body_frame_tensor(b.principal_inertia, b.inertia_axes);
  for (std::size_t k = 0; k < 9; ++k) EXPECT_NEAR(restored[k], stated[k], 1e-17) << k;
  bool warned = false;
  for (const RobotWarning& w : robot.warnings) warned = warned || (w.name == "arm" && w.text.find("no rigid body has") != std::string::npos);
  EXPECT_TRUE(warned);
  // M = I'zz + m |c|² about the hinge through the link's origin: 0.02, where MuJoCo's balanced
  // moments would give 0.013/3 + 0.01
  Diagnostics diagnostics;
  auto text = imported_model_text(path, diagnostics, false);
  ASSERT_TRUE(text) << diagnostics.format();
  EXPECT_NE(text->find("unphysical_inertia = true"), std::string::npos) << *text;
  Equations e = derive_text(*text);
  ASSERT_EQ(e.num_velocities(), 1u);
  EXPECT_NEAR(value_at(e.mass_matrix(0, 0), point_by_name(e, {{"swing", 0.7}, {"der(swing)", 0.3}, {"g", 9.81}})), 0.02, 1e-15);
}

// A floating base with a sensor fixed to it (MuJoCo fuses the two into one body): the body's mass,
// centre and tensor are the two links' as stated, combined by hand here (Steiner's theorem), and
// MuJoCo's own fused body agrees with them to its principal axes' rounding (a wrong order of the
// fixed joint's turn and shift, or of roll, pitch and yaw, would be off in the second digit)
TEST(UnbalancedInertias, LinksFixedToAFloatingBaseAreOneBodyAsStated) {
  std::string urdf = R"(<robot name="floating_sensor">
  <link name="base">
    <inertial><origin xyz="0.01 -0.02 0.03" rpy="0.2 0.1 -0.3"/><mass value="3.0"/>
      <inertia ixx="0.05" ixy="0.002" ixz="-0.001" iyy="0.06" iyz="0.003" izz="0.07"/></inertial>
  </link>
  <link name="sensor">
    <inertial><origin xyz="0.02 0 0.01" rpy="0.4 -0.2 0.5"/><mass value="0.7"/>
      <inertia ixx="0.004" ixy="0.0005" ixz="0.0002" iyy="0.005" iyz="-0.0003" izz="0.006"/></inertial>
  </link>
  <link name="arm">
    <inertial><origin xyz="0 0 -0.1"/><mass value="1.0"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.002"/></inertial>
  </link>
  <joint name="mount" type="fixed"><parent link="base"/><child link="sensor"/><origin xyz="0.1 0.05 -0.02" rpy="0.3 0.6 -0.9"/></joint>
  <joint name="swing" type="continuous"><parent link="base"/><child link="arm"/><origin xyz="0 0 -0.1"/><axis xyz="0 1 0"/></joint>
</robot>
)";
  std::optional<RobotBody> base = floating_body("floating_sensor.urdf", urdf, "base");
  ASSERT_TRUE(base);
  // the sensor in the base's frame: its centre E c + p and tensor E (R I Rᵀ) Eᵀ, E the mount's turn
  std::array<double, 9> E = rpy_matrix(0.3, 0.6, -0.9);
  const double c2[3] = {0.02, 0, 0.01}, p[3] = {0.1, 0.05, -0.02};
  const double m1 = 3.0, m2 = 0.7, m = m1 + m2;
  std::array<double, 3> centers[2] = {{0.01, -0.02, 0.03}, {}};
  for (int r = 0; r < 3; ++r) centers[1][std::size_t(r)] = E[std::size_t(3 * r)] * c2[0] + E[std::size_t(3 * r + 1)] * c2[1] + E[std::size_t(3 * r + 2)] * c2[2] + p[r];
  std::array<double, 9> tensors[2] = {
      turned_by_rpy({0.05, 0.002, -0.001, 0.002, 0.06, 0.003, -0.001, 0.003, 0.07}, 0.2, 0.1, -0.3),
      turned_by_rpy({0.004, 0.0005, 0.0002, 0.0005, 0.005, -0.0003, 0.0002, -0.0003, 0.006}, 0.4, -0.2, 0.5)};
  tensors[1] = turned_by_rpy(tensors[1], 0.3, 0.6, -0.9);
  std::array<double, 3> center{};
  for (std::size_t k = 0; k < 3; ++k) center[k] = (m1 * centers[0][k] + m2 * centers[1][k]) / m;
  std::array<double, 9> combined{};
  const double masses[2] = {m1, m2};
  for (int part = 0; part < 2; ++part) {
    double d[3], dd = 0;
    for (std::size_t k = 0; k < 3; ++k) d[k] = centers[part][k] - center[k], dd += d[k] * d[k];
    for (std::size_t r = 0; r < 3; ++r)
      for (std::size_t c = 0; c < 3; ++c)
        combined[3 * r + c] += tensors[part][3 * r + c] + masses[part] * ((r == c ? dd : 0.0) - d[r] * d[c]);
  }
  EXPECT_NEAR(base->mass, m, 1e-15);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(base->center[k], center[k], 1e-16) << k;
  std::array<double, 9> imported = body_frame_tensor(base->principal_inertia, base->inertia_axes);
  double largest = std::max({combined[0], combined[4], combined[8]});
  for (std::size_t k = 0; k < 9; ++k) EXPECT_NEAR(imported[k], combined[k], 2e-15 * largest) << k;
  // MuJoCo's own fused body, from the same file with a free joint
  std::string floating = urdf;
  floating.replace(floating.find("<link name=\"base\">"), 18,
                   "<link name=\"world\"/><joint name=\"root\" type=\"floating\"><parent link=\"world\"/><child link=\"base\"/></joint>"
                   "<link name=\"base\">");
  std::string path = write_file("floating_sensor_free.urdf", floating);
  char error[1000] = "";
  std::unique_ptr<mjModel, void (*)(mjModel*)> mj(mj_loadXML(path.c_str(), nullptr, error, sizeof error), mj_deleteModel);
  ASSERT_TRUE(mj) << error;
  int b = mj_name2id(mj.get(), mjOBJ_BODY, "base");
  ASSERT_GT(b, 0);
  EXPECT_NEAR(mj->body_mass[b], m, 1e-15);
  std::array<double, 9> mujoco = body_frame_tensor({mj->body_inertia[3 * b], mj->body_inertia[3 * b + 1], mj->body_inertia[3 * b + 2]},
                                                   {mj->body_iquat[4 * b], mj->body_iquat[4 * b + 1], mj->body_iquat[4 * b + 2], mj->body_iquat[4 * b + 3]});
  for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(mj->body_ipos[3 * b + k], center[k], 1e-12) << k;
  for (std::size_t k = 0; k < 9; ++k) EXPECT_NEAR(mujoco[k], combined[k], 1e-6 * largest) << k;
}

// A floating base's root link without mass, its body fixed to it (Romeo's base_link and body): the
// fused body's inertia is the body's as stated, turned into the root's frame, where MuJoCo's own
// principal axes of it turned the tensor by 8e-7 of its size (Romeo's accelerations by 1.8e-7)
TEST(UnbalancedInertias, AMasslessRootTakesItsFixedBodysTensorAsStated) {
  std::string urdf = R"(<robot name="carried_body">
  <link name="base_link"/>
  <link name="body">
    <inertial><origin xyz="0.01 -0.02 0.03" rpy="0.2 0.1 -0.3"/><mass value="4.2"/>
      <inertia ixx="0.05" ixy="0.002" ixz="-0.001" iyy="0.06" iyz="0.003" izz="0.07"/></inertial>
  </link>
  <link name="arm">
    <inertial><origin xyz="0 0 -0.1"/><mass value="1.0"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.002"/></inertial>
  </link>
  <joint name="carried" type="fixed"><parent link="base_link"/><child link="body"/><origin xyz="0.1 0.05 -0.02" rpy="0.3 0.6 -0.9"/></joint>
  <joint name="swing" type="continuous"><parent link="body"/><child link="arm"/><origin xyz="0 0 -0.1"/><axis xyz="0 1 0"/></joint>
</robot>
)";
  std::optional<RobotBody> base = floating_body("carried_body.urdf", urdf, "base_link");
  ASSERT_TRUE(base);
  // the body in the root's frame: centre E c + p, tensor E (R I Rᵀ) Eᵀ, E the fixed joint's turn
  std::array<double, 9> E = rpy_matrix(0.3, 0.6, -0.9);
  const double c[3] = {0.01, -0.02, 0.03}, p[3] = {0.1, 0.05, -0.02};
  std::array<double, 9> tensor =
      turned_by_rpy(turned_by_rpy({0.05, 0.002, -0.001, 0.002, 0.06, 0.003, -0.001, 0.003, 0.07}, 0.2, 0.1, -0.3), 0.3, 0.6, -0.9);
  EXPECT_NEAR(base->mass, 4.2, 1e-15);
  for (std::size_t r = 0; r < 3; ++r)
    EXPECT_NEAR(base->center[r], E[3 * r] * c[0] + E[3 * r + 1] * c[1] + E[3 * r + 2] * c[2] + p[r], 1e-16) << r;
  std::array<double, 9> imported = body_frame_tensor(base->principal_inertia, base->inertia_axes);
  double largest = std::max({tensor[0], tensor[4], tensor[8]});
  for (std::size_t k = 0; k < 9; ++k) EXPECT_NEAR(imported[k], tensor[k], 2e-15 * largest) << k;
}

// A floating base whose fixed links are point masses in a line (iCub's head on its neck) and one
// with a moment below zero: MuJoCo refuses to fuse them ("inertia must have positive eigenvalues"),
// so the import reads them restated and gives the fused body the inertia the file states: about
// the line's centre of mass, Σ m d² across it and zero along it (the rounding-size moment gone)
TEST(UnbalancedInertias, PointMassesFixedInALineToAFloatingBaseAreFusedAsStated) {
  std::string urdf = R"(<robot name="neck_and_head">
  <link name="base"><inertial><mass value="1.0"/><inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial></link>
  <link name="neck"><inertial><origin xyz="0 0 0.1"/><mass value="0.5"/>
    <inertia ixx="0" ixy="0" ixz="2.4e-35" iyy="0" iyz="0" izz="0"/></inertial></link>
  <link name="head"><inertial><origin xyz="0 0 0.1"/><mass value="2.0"/>
    <inertia ixx="-5.4e-20" ixy="0" ixz="0" iyy="-5.4e-20" iyz="0" izz="0"/></inertial></link>
  <link name="arm"><inertial><origin xyz="0 0 -0.1"/><mass value="1.0"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.002"/></inertial></link>
  <joint name="neck_mount" type="fixed"><parent link="base"/><child link="neck"/><origin xyz="0 0 0.2"/></joint>
  <joint name="head_mount" type="fixed"><parent link="neck"/><child link="head"/><origin xyz="0 0 0.1"/></joint>
  <joint name="swing" type="continuous"><parent link="base"/><child link="arm"/><axis xyz="0 1 0"/></joint>
</robot>
)";
  auto read = read_with_mujoco(write_file("neck_and_head.urdf", with_floating_joint(urdf, "base")));
  ASSERT_TRUE(std::holds_alternative<Robot>(read)) << std::get<UnreadableRobot>(read).message;
  const RobotBody* base = nullptr;
  for (const RobotBody& b : std::get<Robot>(read).bodies)
    if (b.name == "base") base = &b;
  ASSERT_NE(base, nullptr);
  // the masses 1, 0.5 and 2 at heights 0, 0.3 and 0.4 on the base's z axis
  const double masses[3] = {1.0, 0.5, 2.0}, heights[3] = {0.0, 0.3, 0.4}, m = 3.5;
  double center = 0, across = 0;
  for (int k = 0; k < 3; ++k) center += masses[k] * heights[k] / m;
  for (int k = 0; k < 3; ++k) across += masses[k] * (heights[k] - center) * (heights[k] - center);
  EXPECT_NEAR(base->mass, m, 1e-15);
  EXPECT_NEAR(base->center[0], 0, 1e-16);
  EXPECT_NEAR(base->center[1], 0, 1e-16);
  EXPECT_NEAR(base->center[2], center, 1e-15);
  std::array<double, 9> imported = body_frame_tensor(base->principal_inertia, base->inertia_axes);
  const std::array<double, 9> stated{across, 0, 0, 0, across, 0, 0, 0, 0};
  for (std::size_t k = 0; k < 9; ++k) EXPECT_NEAR(imported[k], stated[k], 1e-15 * across) << k;
  EXPECT_TRUE(std::any_of(std::get<Robot>(read).warnings.begin(), std::get<Robot>(read).warnings.end(),
                          [](const auto& w) { return w.text.find("taken as the file states it") != std::string::npos; }));
}

TEST(UnbalancedInertias, ADummyLinksRankOneInertiaHasTwoZeroMoments) {
  std::vector<LinkInertia> links = urdf_link_inertias(one_link_urdf(
      "      <mass value=\"1e-6\"/>\n      <inertia ixx=\"1e-6\" ixy=\"1e-6\" ixz=\"1e-6\" iyy=\"1e-6\" iyz=\"1e-6\" izz=\"1e-6\"/>\n"));
  ASSERT_EQ(links.size(), 1u);
  Triple m = links[0].principal;
  std::sort(m.begin(), m.end());
  EXPECT_EQ(m[0], 0.0);
  EXPECT_EQ(m[1], 0.0);
  EXPECT_NEAR(m[2], 3e-6, 1e-20);
  EXPECT_TRUE(links[0].unbalanced);
}

TEST(UnbalancedInertias, OnlyTheRefusalTurnsBalancingOn) {
  EXPECT_TRUE(refuses_unbalanced_inertia("Error: inertia must satisfy A + B >= C; use 'balanceinertia' to fix\nObject name = arm"));
  EXPECT_FALSE(refuses_unbalanced_inertia("Error: mass and inertia cannot be negative"));
  EXPECT_TRUE(refuses_to_fuse_singular_inertias("Error: error 'inertia must have positive eigenvalues' in fusing static body inertias"));
  EXPECT_FALSE(refuses_to_fuse_singular_inertias("Error: inertia must have positive eigenvalues\nObject name = arm"));
  EXPECT_EQ(with_balanced_inertias("<robot name=\"r\"><mujoco><compiler fusestatic=\"false\"/></mujoco></robot>"),
            "<robot name=\"r\"><mujoco><compiler balanceinertia=\"true\" fusestatic=\"false\"/></mujoco></robot>");
  std::string own = "<robot name=\"r\"><mujoco><compiler balanceinertia=\"false\"/></mujoco></robot>";
  EXPECT_EQ(with_balanced_inertias(own), own) << "a file's own choice stands";
}

// a pendulum about z whose body has the moments given: what the model file says of them
std::string pendulum_with_moments(const std::string& moments, const std::string& flag) {
  return "[model]\nname = \"pendulum\"\n\n[parameters]\ng = 9.81\n\n[coordinates]\nphi = { initial = 0.1, rate = 0 }\n\n"
         "[[rigid_bodies]]\nname = \"bob\"\nmass = \"2\"\ncenter = [\"0.3*sin(phi)\", \"-0.3*cos(phi)\", \"0\"]\n"
         "rotation = \"rot_z(phi)\"\ninertia = " + moments + "\n" + flag + "\n[gravity]\nacceleration = [\"0\", \"-g\", \"0\"]\n";
}

std::string pendulum_model_errors(const std::string& text) {
  Diagnostics d;
  ModelFile file = parse_model_text(text, "pendulum.toml", d);
  if (d.empty()) build_model(file, d);
  return d.format();
}

TEST(UnbalancedInertias, TheModelFileTakesAnUnphysicalInertiaOnlyWhenToldTo) {
  const std::string unbalanced = "[\"0.006\", \"0.006\", \"0.06\"]", negative = "[\"0.006\", \"-1e-9\", \"0.006\"]";
  EXPECT_NE(pendulum_model_errors(pendulum_with_moments(unbalanced, "")).find("no rigid body has this inertia"), std::string::npos);
  EXPECT_NE(pendulum_model_errors(pendulum_with_moments(negative, "")).find("must not be negative"), std::string::npos);
  EXPECT_EQ(pendulum_model_errors(pendulum_with_moments(unbalanced, "unphysical_inertia = true")), "");
  EXPECT_EQ(pendulum_model_errors(pendulum_with_moments(negative, "unphysical_inertia = true")), "");
  EXPECT_NE(pendulum_model_errors(pendulum_with_moments(unbalanced, "unphysical_inertia = \"yes\"")).find("expected true or false"), std::string::npos);
  // M = Izz + m s² about the pivot, the moments as written
  Equations e = derive_text(pendulum_with_moments(unbalanced, "unphysical_inertia = true"));
  EXPECT_NEAR(value_at(e.mass_matrix(0, 0), point_by_name(e, {{"phi", 0.4}, {"der(phi)", 0.2}, {"g", 9.81}})), 0.06 + 2 * 0.09, 1e-15);
}

}  // namespace
}  // namespace eomgen::test
