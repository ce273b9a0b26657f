// Coupled joints, closed loops and welds in MJCF (equality joint, connect and weld) imported as
// Lagrange I constraints. A weld is three connects: at its anchor and at the tips of unit vectors
// along two of its axes; a welded chain then moves as MuJoCo's chain with those joints removed. A connect: two points, one
// in each body, and one holonomic constraint per independent world component of their distance
// (MuJoCo's own Jacobian at the initial state decides which: a planar loop keeps x and y). The
// imported four-bar (tests/crosscheck/mjcf/four_bar.xml, its bodies placed at the closed
// configuration) has the equations of models/four_bar_linkage.toml, written by hand over frames,
// with its angles offset by the placement: M, f, the constraints, C and γ agree at random states.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <variant>

#include <Eigen/Dense>
#include <mujoco/mujoco.h>

#include <fmt/format.h>

#include "import/mjcf_reader.hpp"
#include "import/model_writer.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

const std::string source = EOMGEN_SOURCE_DIR;

TEST(LoopImport, AConnectBecomesTheConstraintsOfItsIndependentComponents) {
  auto read = read_with_mujoco(source + "/tests/crosscheck/mjcf/four_bar.xml");
  ASSERT_TRUE(std::holds_alternative<Robot>(read)) << std::get<UnreadableRobot>(read).message;
  const Robot& r = std::get<Robot>(read);
  ASSERT_EQ(r.loops.size(), 1u);
  EXPECT_EQ(r.loops[0].name, "pin");
  EXPECT_EQ(r.loops[0].kept, (std::array<bool, 3>{true, true, false}));
  EXPECT_NEAR(r.loops[0].anchor2[0], 0.4, 1e-15) << "MuJoCo puts the second anchor on the rocker's end";
  for (const RobotWarning& w : r.warnings) EXPECT_NE(w.section, "equality") << w.text;
  Diagnostics diagnostics;
  auto text = imported_model_text(source + "/tests/crosscheck/mjcf/four_bar.xml", diagnostics, false);
  ASSERT_TRUE(text) << diagnostics.format();
  for (const char* line : {"method = \"lagrange1\"", "name = \"pin_1\"\nframe = \"coupler_link\"", "name = \"pin_2\"\nframe = \"rocker_link\"",
                           "holonomic = \"pin_1.x - pin_2.x\"", "holonomic = \"pin_1.y - pin_2.y\"", "its z component follows"})
    EXPECT_NE(text->find(line), std::string::npos) << line << " in\n" << *text;
}

TEST(LoopImport, TheImportedFourBarHasTheHandWrittenEquations) {
  Diagnostics diagnostics;
  auto text = imported_model_text(source + "/tests/crosscheck/mjcf/four_bar.xml", diagnostics, false);
  ASSERT_TRUE(text) << diagnostics.format();
  Equations imported = derive_text(*text, "four_bar.toml");
  std::ifstream file(source + "/models/four_bar_linkage.toml");
  std::stringstream written;
  written << file.rdbuf();
  Equations hand = derive_text(written.str(), "four_bar_linkage.toml");
  const std::vector<std::string> names{"crank", "coupler", "rocker"};
  // the MJCF places the bodies at the hand-written model's initial angles
  const std::vector<double>& closed = hand.symbols.initial_coordinates;
  ASSERT_EQ(imported.constraints.size(), 2u);
  std::mt19937 random(17);
  std::uniform_real_distribution<double> angle(-2, 2), rate(-3, 3);
  for (int point = 0; point < 10; ++point) {
    std::map<std::string, double> by_hand{{"a", 0.2}, {"b", 0.5}, {"c", 0.4}, {"d", 0.45}, {"g", 9.81}}, by_import;
    for (std::size_t k = 0; k < 3; ++k) {
      double q = angle(random), v = rate(random);
      by_hand[names[k]] = q, by_hand["der(" + names[k] + ")"] = v;
      by_import[names[k]] = q - closed[k], by_import["der(" + names[k] + ")"] = v;
    }
    GiNaC::exmap at = point_by_name(imported, by_import), full = point_by_name(hand, by_hand);
    auto near = [](double x, double y, const std::string& what) {
      EXPECT_NEAR(x, y, 1e-12 * std::max({1.0, std::abs(x), std::abs(y)})) << what;
    };
    for (unsigned j = 0; j < 3; ++j) {
      near(value_at(imported.forcing[j], at), value_at(hand.forcing[j], full), fmt::format("f[{}]", j));
      for (unsigned k = 0; k < 3; ++k)
        near(value_at(imported.mass_matrix(j, k), at), value_at(hand.mass_matrix(j, k), full), fmt::format("M[{}][{}]", j, k));
    }
    for (unsigned i = 0; i < 2; ++i) {
      near(value_at(imported.constraints.position[i], at), value_at(hand.constraints.position[i], full), fmt::format("g[{}]", i));
      near(value_at(imported.constraints.acceleration_bias[i], at), value_at(hand.constraints.acceleration_bias[i], full),
           fmt::format("gamma[{}]", i));
      for (unsigned j = 0; j < 3; ++j)
        near(value_at(imported.constraints.jacobian(i, j), at), value_at(hand.constraints.jacobian(i, j), full),
             fmt::format("C[{}][{}]", i, j));
    }
  }
}

// MuJoCo's joint coupling q1 − q1₀ = c0 + c1 d + … + c4 d⁴, d = q2 − q2₀ (q1 − q1₀ = c0 alone), with
// q₀ the joints' qpos0 (here a reference of 0.2°), becomes a holonomic constraint in the coordinates
TEST(LoopImport, CoupledJointsBecomeAConstraintInTheirCoordinates) {
  std::string path = temporary_directory() + "/coupled.xml";
  std::ofstream(path) << R"xml(<mujoco model="coupled">
  <worldbody>
    <body name="left" pos="0 0 1">
      <joint name="a" type="hinge" axis="0 1 0" ref="0.2"/>
      <geom type="capsule" fromto="0 0 0 0 0 -0.3" size="0.02" mass="1" contype="0" conaffinity="0"/>
    </body>
    <body name="right" pos="0.5 0 1">
      <joint name="b" type="hinge" axis="0 1 0"/>
      <geom type="capsule" fromto="0 0 0 0 0 -0.3" size="0.02" mass="1" contype="0" conaffinity="0"/>
    </body>
    <body name="slider" pos="1 0 1">
      <joint name="s" type="slide" axis="1 0 0"/>
      <geom type="sphere" size="0.05" mass="0.5" contype="0" conaffinity="0"/>
    </body>
  </worldbody>
  <equality>
    <joint name="gear" joint1="a" joint2="b" polycoef="0.1 -2 0.5 0 0"/>
    <joint joint1="s" polycoef="0.05 0 0 0 0"/>
  </equality>
</mujoco>)xml";
  Diagnostics diagnostics;
  auto text = imported_model_text(path, diagnostics, false);
  ASSERT_TRUE(text) << diagnostics.format();
  EXPECT_EQ(text->find("not carried"), std::string::npos) << *text;
  for (const char* line : {"method = \"lagrange1\"", "name = \"gear\"\nholonomic = \"a - 0.003490658503988659 - 0.1 + 2*b - 0.5*b^2\"",
                           "name = \"coupling2\"\nholonomic = \"s - 0.05\""})
    EXPECT_NE(text->find(line), std::string::npos) << line << " in\n" << *text;
  Equations e = derive_text(*text, "coupled.toml");
  ASSERT_EQ(e.constraints.size(), 2u);
  GiNaC::exmap at = point_by_name(e, {{"a", 0.4}, {"b", 0.3}, {"s", 0.2}, {"der(a)", 1}, {"der(b)", -2}, {"der(s)", 0.5}});
  EXPECT_NEAR(value_at(e.constraints.jacobian(0, 0), at), 1, 1e-15);
  EXPECT_NEAR(value_at(e.constraints.jacobian(0, 1), at), 2 - 0.3, 1e-15);
  // γ = g̈ at q̈ = 0: the −0.5 b² term gives −ḃ², with ḃ = −2
  EXPECT_NEAR(value_at(e.constraints.acceleration_bias[0], at), -4, 1e-14);
}

const char* const welded_chain = R"xml(<mujoco model="welded">
  <compiler angle="radian"/>
  <worldbody>
    <body name="a" pos="0 0 1">
      <JOINT1 name="j1" type="hinge" axis="0 1 0"/>
      <inertial pos="0.1 0 -0.2" mass="1" fullinertia="0.02 0.025 0.015 0.001 0.002 0.0005"/>
      <body name="b" pos="0 0.1 -0.4" euler="0.3 0.2 0.1">
        <JOINT2 name="j2" type="hinge" axis="1 0 0"/>
        <inertial pos="0 0.05 -0.1" mass="0.7" diaginertia="0.004 0.005 0.006"/>
        <body name="c" pos="0.05 0 -0.3" euler="-0.2 0.4 0">
          <JOINT3 name="j3" type="hinge" axis="0 0.6 0.8"/>
          <inertial pos="0.02 0.01 -0.1" mass="0.4" diaginertia="0.001 0.002 0.003"/>
        </body>
      </body>
    </body>
  </worldbody>
  <equality>
    WELD
  </equality>
</mujoco>)xml";

// the welded chain's text: `weld` the equality, each joint kept (a <joint>) or removed (a comment)
std::string welded_chain_text(const std::string& weld, const std::array<bool, 3>& kept) {
  std::string text = welded_chain;
  for (std::size_t j = 0; j < 3; ++j) {
    std::string tag = fmt::format("JOINT{}", j + 1);
    std::size_t at = text.find("<" + tag);
    text.replace(at, tag.size() + 1, kept[j] ? "<joint" : "<!-- joint");
    if (!kept[j]) text.replace(text.find("/>", at), 2, "/ -->");
  }
  text.replace(text.find("WELD"), 4, weld);
  return text;
}

// q'' of the imported Lagrange I model, [M Cᵀ; C 0] [q''; −λ] = [f; γ], against MuJoCo's qacc of
// the chain without the welded joints, at states that hold the weld (the welded joints at qpos0)
void expect_motion_of_the_chain_without(const std::string& weld, const std::array<bool, 3>& moving, std::size_t constraints) {
  std::string path = temporary_directory() + "/welded.xml", reduced = temporary_directory() + "/reduced.xml";
  std::ofstream(path) << welded_chain_text(weld, {true, true, true});
  std::ofstream(reduced) << welded_chain_text("", moving);
  Diagnostics diagnostics;
  auto text = imported_model_text(path, diagnostics, false);
  ASSERT_TRUE(text) << diagnostics.format();
  EXPECT_EQ(text->find("not carried"), std::string::npos) << *text;
  Equations e = derive_text(*text, "welded.toml");
  ASSERT_EQ(e.constraints.size(), constraints) << *text;
  char error[1000] = "";
  std::unique_ptr<mjModel, void (*)(mjModel*)> m(mj_loadXML(reduced.c_str(), nullptr, error, sizeof error), mj_deleteModel);
  ASSERT_TRUE(m) << error;
  std::unique_ptr<mjData, void (*)(mjData*)> d(mj_makeData(m.get()), mj_deleteData);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> angle(-2, 2), rate(-3, 3);
  for (int point = 0; point < 5; ++point) {
    std::map<std::string, double> at;
    for (std::size_t j = 0, v = 0; j < 3; ++j) {
      double q = moving[j] ? angle(random) : 0, dq = moving[j] ? rate(random) : 0;
      at[fmt::format("j{}", j + 1)] = q, at[fmt::format("der(j{})", j + 1)] = dq;
      if (moving[j]) d->qpos[v] = q, d->qvel[v++] = dq;
    }
    mj_forward(m.get(), d.get());
    GiNaC::exmap x = point_by_name(e, at);
    std::size_t k = constraints;
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(3 + long(k), 3 + long(k));
    Eigen::VectorXd b(3 + long(k));
    for (unsigned i = 0; i < 3; ++i) {
      b(i) = value_at(e.forcing[i], x);
      for (unsigned j = 0; j < 3; ++j) A(i, j) = value_at(e.mass_matrix(i, j), x);
    }
    for (unsigned c = 0; c < k; ++c) {
      EXPECT_NEAR(value_at(e.constraints.position[c], x), 0, 1e-14) << "the weld holds";
      b(3 + c) = value_at(e.constraints.acceleration_bias[c], x);
      for (unsigned j = 0; j < 3; ++j) A(3 + c, j) = A(j, 3 + c) = value_at(e.constraints.jacobian(c, j), x);
    }
    Eigen::VectorXd solution = A.fullPivLu().solve(b);
    for (std::size_t j = 0, v = 0; j < 3; ++j) {
      double expected = moving[j] ? d->qacc[v++] : 0;
      EXPECT_NEAR(solution(long(j)), expected, 1e-12 * std::max(1.0, std::abs(expected))) << "q''" << j + 1 << " at " << point;
    }
  }
}

TEST(LoopImport, AWeldBetweenBodiesMakesThemMoveAsOne) {
  // c held to a: j2 and j3 stop, and the chain swings on j1 as MuJoCo's chain without them
  expect_motion_of_the_chain_without(R"(<weld name="lock" body1="c" body2="a"/>)", {true, false, false}, 2);
}

TEST(LoopImport, AWeldToTheWorldHoldsTheBody) {
  // b held to the world: only c swings, on j3
  expect_motion_of_the_chain_without(R"(<weld name="hold" body1="b"/>)", {false, false, true}, 2);
}

TEST(LoopImport, AWeldWritesPointsAtItsAnchorAndAxisTips) {
  std::string path = temporary_directory() + "/welded.xml";
  std::ofstream(path) << welded_chain_text(R"(<weld name="lock" body1="c" body2="a"/>)", {true, true, true});
  Diagnostics diagnostics;
  auto text = imported_model_text(path, diagnostics, false);
  ASSERT_TRUE(text) << diagnostics.format();
  for (const char* line : {"name = \"lock_1\"\nframe = \"c\"", "name = \"lock_2\"\nframe = \"a\"\nposition = [\"0\", \"0\", \"0\"]",
                           "name = \"lock_ex_2\"\nframe = \"a\"\nposition = [\"1\", \"0\", \"0\"]",
                           "name = \"lock_ey_2\"\nframe = \"a\"\nposition = [\"0\", \"1\", \"0\"]"})
    EXPECT_NE(text->find(line), std::string::npos) << line << " in\n" << *text;
}

}  // namespace
}  // namespace eomgen::test
