// Lagrange I on a tree of frames with recursive kinematics (the default for frames with joints):
// a constraint written in points of the frames gets its Jacobian C through the frames' partial
// velocities and its γ = g̈ (q̈ = 0) from the frames' velocities and bias accelerations
// (RecursiveKinematics::rate_along_motion). Against the expanded derivation of the same model
// (every position multiplied out, constraints differentiated by GiNaC): g, C, b, γ, M and f at
// random states, for holonomic constraints linear and nonlinear in the points' coordinates and a
// nonholonomic one whose coefficients are; and the 7-joint arm with a point held at a height,
// which took 70 s expanded, derives in well under a second.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <random>

#include <fmt/format.h>

#include "pipeline.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

const char* loop = R"toml([model]
name = "loop"
method = "lagrange1"

[parameters]
l = 0.4
g = 9.81

[coordinates]
a = 0.3
b = -0.4
c = 0.7
d = 0.2

[[frames]]
name = "base"
origin = ["0", "0", "l"]
rotation = "rot_x(0.3)"
joint = { type = "revolute", axis = ["1", "2", "2"], anchor = ["0.1", "-0.2", "0.05"], coordinate = "a" }

[[frames]]
name = "arm"
parent = "base"
origin = ["l", "0", "0"]
joint = { type = "revolute", axis = ["0", "0", "-1"], anchor = ["0", "0.1", "0"], coordinate = "b" }

[[frames]]
name = "hand"
parent = "arm"
origin = ["0.3", "0", "0"]
joint = { type = "revolute", axis = ["0", "1", "1"], anchor = ["0.05", "0", "0"], coordinate = "c" }

[[frames]]
name = "side"
parent = "base"
origin = ["0", "0.2", "0"]
joint = { type = "prismatic", axis = ["3", "0", "4"], coordinate = "d" }

[[points]]
name = "tip"
frame = "hand"
position = ["0.2", "0.01", "-0.03"]

[[points]]
name = "knob"
frame = "side"
position = ["0.05", "0", "0.1"]

[[rigid_bodies]]
name = "base_link"
mass = "1.3"
frame = "base"
center = ["0.05", "0.02", "l/2"]
inertia = [["0.03", "0.002", "-0.001"], ["0.002", "0.028", "0.003"], ["-0.001", "0.003", "0.012"]]

[[rigid_bodies]]
name = "arm_link"
mass = "0.7"
frame = "arm"
center = ["l/2", "0", "0.01"]
inertia = ["0.002", "0.011", "0.012"]

[[rigid_bodies]]
name = "hand_link"
mass = "0.5"
frame = "hand"
center = ["0.04", "-0.02", "0.03"]
inertia = [["0.0015", "0.0002", "-0.0001"], ["0.0002", "0.0018", "0.0003"], ["-0.0001", "0.0003", "0.0012"]]

[[particles]]
name = "slider"
mass = "0.4"
frame = "side"
position = ["0", "0.03", "0"]

[[constraints]]
name = "height"
holonomic = "tip.z - 0.3*tip.x + 0.1*knob.y - 0.5"

[[constraints]]
name = "reach"
holonomic = "(tip.x - knob.x)^2 + tip.y*knob.z - a*d - 0.05"

[[constraints]]
name = "rolling"
nonholonomic = "tip.y*der(a) + knob.x*der(c) - der(d)"

[gravity]
acceleration = ["0", "0", "-g"]
)toml";

// g, b, γ, C, M and f of the two derivations at random states
void expect_expanded_constraints(const std::string& text) {
  Equations recursive = derive_text(text), expanded = derive_text(text, "model.toml", model_written_out());
  ASSERT_FALSE(recursive.intermediates.empty()) << "frames with joints take the recursive kinematics under Lagrange I";
  const unsigned m = unsigned(recursive.constraints.size()), n = unsigned(recursive.forcing.size());
  ASSERT_EQ(m, expanded.constraints.size());
  std::mt19937 random(11);
  std::uniform_real_distribution<double> angle(-2, 2), rate(-3, 3);
  for (int point = 0; point < 12; ++point) {
    std::map<std::string, double> values{{"l", 0.4}, {"g", 9.81}};
    for (const std::string& q : recursive.symbols.coordinate_names) values[q] = angle(random), values["der(" + q + ")"] = rate(random);
    GiNaC::exmap at = point_by_name(recursive, values), full = point_by_name(expanded, values);
    auto near = [](double x, double y, const std::string& what) {
      EXPECT_NEAR(x, y, 1e-11 * std::max({1.0, std::abs(x), std::abs(y)})) << what;
    };
    const ConstraintSet &r = recursive.constraints, &e = expanded.constraints;
    for (unsigned i = 0; i < m; ++i) {
      near(value_at(r.position[i], at), value_at(e.position[i], full), fmt::format("g[{}]", i));
      near(value_at(r.bias[i], at), value_at(e.bias[i], full), fmt::format("b[{}]", i));
      near(value_at(r.acceleration_bias[i], at), value_at(e.acceleration_bias[i], full), fmt::format("gamma[{}]", i));
      for (unsigned j = 0; j < n; ++j)
        near(value_at(r.jacobian(i, j), at), value_at(e.jacobian(i, j), full), fmt::format("C[{}][{}]", i, j));
    }
    for (unsigned j = 0; j < n; ++j) {
      near(value_at(recursive.forcing[j], at), value_at(expanded.forcing[j], full), fmt::format("f[{}]", j));
      for (unsigned k = 0; k < n; ++k)
        near(value_at(recursive.mass_matrix(j, k), at), value_at(expanded.mass_matrix(j, k), full), fmt::format("M[{}][{}]", j, k));
    }
  }
}

TEST(TreeConstraints, ThroughTheFramesTheyAreThoseOfTheExpandedDerivation) {
  ASSERT_EQ(derive_text(loop).constraints.size(), 3u);
  expect_expanded_constraints(loop);
}

// the hand's joint following the base's coordinate (−1.5 a + 0.2, a mimic), the constraint on
// reach left out: its partial velocities and bias accelerations through the frames carry the multiplier
TEST(TreeConstraints, AJointThatFollowsACoordinateGivesTheExpandedConstraints) {
  auto following = [](std::string text) {
    text.replace(text.find("coordinate = \"c\""), 16, "coordinate = \"a\", multiplier = -1.5, offset = 0.2");
    text.replace(text.find("c = 0.7\n"), 8, "");
    text.replace(text.find("knob.x*der(c)"), 13, "knob.x*der(b)");
    std::size_t reach = text.find("[[constraints]]\nname = \"reach\"");  // two constraints on three coordinates
    text.erase(reach, text.find("[[constraints]]", reach + 1) - reach);
    return text;
  };
  ASSERT_EQ(derive_text(following(loop)).forcing.size(), 3u);
  expect_expanded_constraints(following(loop));
}

TEST(TreeConstraints, ADependentConstraintIsFoundThroughTheFrames) {
  std::string text = loop;
  std::size_t rolling = text.find("[[constraints]]\nname = \"rolling\"");
  text.replace(rolling, text.find("[gravity]") - rolling,
               "[[constraints]]\nname = \"twice\"\nholonomic = \"2*tip.z - 0.6*tip.x + 0.2*knob.y - 1\"\n\n");
  Diagnostics d;
  ModelFile file = parse_model_text(text, "loop.toml", d);
  Model model = build_model(file, d);
  ASSERT_TRUE(d.empty()) << d.format();
  EXPECT_FALSE(derive_built_model(model, {}, d));
  EXPECT_NE(d.format().find("'twice' depends on the constraints before it"), std::string::npos) << d.format();
  // the hint that goes with a dependent constraint, not the one for a derivation that stopped
  EXPECT_NE(d.format().find("remove a dependent constraint"), std::string::npos) << d.format();
  EXPECT_EQ(d.format().find("the symbolic derivation stopped"), std::string::npos) << d.format();
}

}  // namespace
}  // namespace eomgen::test
