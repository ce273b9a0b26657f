// Coupled joints and a closed loop in MJCF (equality joint and connect) imported as Lagrange I
// constraints. A connect: two points, one
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

}  // namespace
}  // namespace eomgen::test
