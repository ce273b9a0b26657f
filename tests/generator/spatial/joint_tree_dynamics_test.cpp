// The spatial recursions over a tree of joints (generator/spatial/joint_tree_dynamics.hpp)
// against the expanded derivation of the same model (Lagrange's equations from the positions
// multiplied out): a branched tree with a revolute joint about an oblique axis through an
// offset anchor, a prismatic joint, a fixed frame, a particle and rigid bodies with full
// inertia tensors turned in their frames. M and f agree at random states; the inverse dynamics
// τ(q, q̇, q̈) of the recursion (the code jacobian_state differentiates) is M q̈ − f at random q̈, and
// its derivatives in closed form are those of M q̈ − f differentiated symbolically;
// and a model that is not such a tree keeps the frame recursion, with its reason.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <fstream>
#include <random>

#include <fmt/format.h>

#include "emit/cpp_header.hpp"
#include "model/model.hpp"
#include "parse/model_file.hpp"
#include "pipeline.hpp"
#include "spatial/joint_tree_dynamics.hpp"
#include "support/expanded_oracle.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

using GiNaC::ex;

const char* tree = R"toml([model]
name = "tree"

[parameters]
m = 1.3
l = 0.4
g = 9.81

[coordinates]
a = 0.3
b = -0.4
s = 0.1
c = 0.7

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
name = "slide"
parent = "base"
origin = ["0", "0.2", "0"]
rotation = "rot_z(Pi/2)"
joint = { type = "prismatic", axis = ["3", "0", "4"], coordinate = "s" }

[[frames]]
name = "bracket"
parent = "slide"
origin = ["0.1", "0", "0"]
joint = { type = "fixed" }

[[frames]]
name = "hand"
parent = "bracket"
joint = { type = "revolute", axis = ["0", "1", "1"], anchor = ["0.05", "0", "0"], coordinate = "c" }

[[rigid_bodies]]
name = "base_link"
mass = "m"
frame = "base"
center = ["0.05", "0.02", "l/2"]
inertia = [["0.03", "0.002", "-0.001"], ["0.002", "0.028", "0.003"], ["-0.001", "0.003", "0.012"]]

[[rigid_bodies]]
name = "arm_link"
mass = "0.7"
frame = "arm"
center = ["l/2", "0", "0.01"]
rotation = "rot_y(0.4)"
inertia = ["0.002", "0.011", "0.012"]

[[particles]]
name = "weight"
mass = "0.4"
frame = "bracket"
position = ["0", "0.03", "0"]

[[rigid_bodies]]
name = "hand_link"
mass = "0.5"
frame = "hand"
center = ["0.04", "-0.02", "0.03"]
inertia = [["0.0015", "0.0002", "-0.0001"], ["0.0002", "0.0018", "0.0003"], ["-0.0001", "0.0003", "0.0012"]]

[gravity]
acceleration = ["0", "0", "-g"]

[energy]
potential = "20*s^2"
dissipation = "0.3*der(a)^2/2"
)toml";

TEST(JointTree, RecursionsGiveTheExpandedEquations) {
  expect_expanded_equations(tree, 4);
}

// A head that pans and tilts, carrying a camera on a turned fixed frame and a lens below that
// (fixed by its constant placement): both fold into the head's link as one body with its own
// (joint_tree_dynamics.cpp, fold_fixed_links), M and f are still the expanded derivation's, and
// M and f's code forms nothing of the camera or the lens
const char* sensor_head = R"toml([model]
name = "sensor_head"

[parameters]
g = 9.81

[coordinates]
pan = 0.3
tilt = -0.2

[[frames]]
name = "neck"
origin = ["0", "0", "0.5"]
joint = { type = "revolute", axis = ["0", "0", "1"], coordinate = "pan" }

[[frames]]
name = "head"
parent = "neck"
origin = ["0", "0", "0.1"]
joint = { type = "revolute", axis = ["0", "1", "0"], anchor = ["0.02", "0", "0"], coordinate = "tilt" }

[[frames]]
name = "camera"
parent = "head"
origin = ["0.08", "0.01", "0.05"]
rotation = "rot_z(0.4)*rot_x(-0.3)"
joint = { type = "fixed" }

[[frames]]
name = "lens"
parent = "camera"
origin = ["0.03", "0", "0"]
rotation = "rot_y(0.2)"

[[rigid_bodies]]
name = "neck_link"
mass = "1.2"
frame = "neck"
center = ["0.01", "0", "0.04"]
inertia = [["0.004", "0.0002", "0"], ["0.0002", "0.005", "0.0001"], ["0", "0.0001", "0.003"]]

[[rigid_bodies]]
name = "head_link"
mass = "0.8"
frame = "head"
center = ["0.03", "-0.01", "0.02"]
inertia = [["0.002", "0.0001", "-0.0002"], ["0.0001", "0.0025", "0.0003"], ["-0.0002", "0.0003", "0.0018"]]

[[rigid_bodies]]
name = "camera_body"
mass = "0.15"
frame = "camera"
center = ["0.01", "0", "0.02"]
inertia = [["0.0003", "0.00002", "0"], ["0.00002", "0.0002", "-0.00001"], ["0", "-0.00001", "0.0004"]]

[[particles]]
name = "glass"
mass = "0.02"
frame = "lens"
position = ["0.005", "0", "0"]

[gravity]
acceleration = ["0", "0", "-g"]
)toml";

// the code of the header's mass_matrix_and_forcing, emitted in the process (the sanitizer build
// has no eomgen binary to run)
std::string mass_matrix_and_forcing_code(const std::string& model_text) {
  std::string header = emit_cpp_header(derive_text(model_text));
  std::size_t from = header.find("void mass_matrix_and_forcing(");
  return from == std::string::npos ? std::string() : header.substr(from, header.find("\n}\n", from) - from);
}

TEST(JointTree, FixedLeavesFoldIntoTheirJointsLink) {
  expect_expanded_equations(sensor_head, 2);
  std::string body = mass_matrix_and_forcing_code(sensor_head);
  ASSERT_FALSE(body.empty());
  EXPECT_EQ(body.find("k_camera_"), std::string::npos) << body;
  EXPECT_EQ(body.find("k_lens_"), std::string::npos) << body;
  EXPECT_EQ(body.find("k_head_tB1"), std::string::npos) << "the head's bodies as one: " << body;
  EXPECT_NE(body.find("k_head_tB0"), std::string::npos) << body;
}

// The camera carrying a joint of its own, a shutter that turns about the camera's x through an
// anchor off its origin: the camera folds all the same (fold_fixed_links), the shutter hanging from
// the head by the camera's turn and offset composed with its own. M, f and their derivatives are
// the expanded derivation's, and M and f's code forms nothing of the camera
std::string sensor_head_with_shutter() {
  std::string text = sensor_head;
  text.replace(text.find("tilt = -0.2\n"), 12, "tilt = -0.2\nshutter = 0.5\n");
  text.replace(text.find("[[rigid_bodies]]"), 0,
               "[[frames]]\nname = \"blade\"\nparent = \"camera\"\norigin = [\"0.01\", \"0.02\", \"0\"]\nrotation = \"rot_y(0.3)\"\n"
               "joint = { type = \"revolute\", axis = [\"1\", \"0\", \"0\"], anchor = [\"0\", \"0.01\", \"0\"], coordinate = \"shutter\" }\n\n"
               "[[rigid_bodies]]\nname = \"blade_body\"\nmass = \"0.05\"\nframe = \"blade\"\ncenter = [\"0\", \"0.02\", \"0.01\"]\n"
               "inertia = [[\"0.00002\", \"0.000001\", \"0\"], [\"0.000001\", \"0.00001\", \"0\"], [\"0\", \"0\", \"0.00003\"]]\n\n");
  return text;
}

TEST(JointTree, AFixedLinkCarryingAJointFoldsIntoItsJointsLink) {
  std::string text = sensor_head_with_shutter();
  expect_expanded_equations(text, 3);
  expect_expanded_derivatives(text, 3);
  std::string body = mass_matrix_and_forcing_code(text);
  ASSERT_FALSE(body.empty());
  EXPECT_EQ(body.find("k_camera_"), std::string::npos) << body;
  EXPECT_NE(body.find("k_blade_"), std::string::npos) << body;
}

// the oblique axis, the slide, the fixed frame and the turned inertias included
TEST(JointTree, ClosedFormDerivativesAreThoseOfTheExpandedEquations) {
  expect_expanded_derivatives(tree, 4);
}

// The tree with joints that follow another joint's coordinate (URDF's mimic): the arm turned by
// −0.7 c + 0.2, c the hand's angle in another branch, and a copy of the tree where the hand
// follows the base's angle a, its ancestor, by 2 a − 0.1 and the slide follows it too. The
// recursions add each joint's share to the rows and columns of the coordinate it follows.
std::string with_followers(bool ancestor) {
  std::string text = tree;
  auto replace = [&](const std::string& from, const std::string& to) {
    std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  };
  if (!ancestor) {
    replace("coordinate = \"b\"", "coordinate = \"c\", multiplier = \"-0.7\", offset = 0.2");
    replace("b = -0.4\n", "");
  } else {
    replace("coordinate = \"c\"", "coordinate = \"a\", multiplier = 2, offset = \"-l/4\"");
    replace("c = 0.7\n", "");
    replace("coordinate = \"s\"", "coordinate = \"a\", multiplier = \"0.05\"");
    replace("s = 0.1\n", "");
    replace("potential = \"20*s^2\"", "potential = \"20*b^2\"");
  }
  return text;
}

TEST(JointTree, JointsThatFollowACoordinateGiveTheExpandedEquations) {
  expect_expanded_equations(with_followers(false), 3);
  expect_expanded_equations(with_followers(true), 2);
}

TEST(JointTree, JointsThatFollowACoordinateHaveTheExpandedDerivatives) {
  expect_expanded_derivatives(with_followers(false), 3);
  expect_expanded_derivatives(with_followers(true), 2);
}

// the velocity above each in the factorization of M from the leaves (emit/cpp_ldlt.hpp): the tree's
// (b and s on the base's a, c on the slide's s); when the hand's c also turns the arm, c couples
// both branches and sits below s, itself below a; with the tree's a numbered last, eliminating a
// couples b, s and c, and the fill-in makes one chain
TEST(JointTree, TheFactorizationOfMFollowsTheTreeAndItsFillIn) {
  EXPECT_EQ(derive_text(tree).coordinate_parents, (std::vector<int>{-1, 0, 0, 2}));
  EXPECT_EQ(derive_text(with_followers(false)).coordinate_parents, (std::vector<int>{-1, 0, 1}));
  EXPECT_EQ(derive_text(with_followers(true)).coordinate_parents, (std::vector<int>{-1, 0}));
  std::string last = tree;
  last.erase(last.find("a = 0.3\n"), 8);
  last.insert(last.find("c = 0.7\n") + 8, "a = 0.3\n");
  EXPECT_EQ(derive_text(last).coordinate_parents, (std::vector<int>{-1, 0, 1, 2})) << last;
}

TEST(JointTree, FramesWithJointsAreATreeWithoutAnOption) {
  std::string text = tree;
  Model model = built(text);
  EXPECT_TRUE(model.recursive_kinematics);
  EXPECT_FALSE(why_not_a_joint_tree(model));
  text.insert(text.find("\n[parameters]"), "method = \"appell\"\n");
  EXPECT_FALSE(built(text).recursive_kinematics) << "Appell's equations take the expanded kinematics";
  Diagnostics retired;
  std::string keyed = tree;
  keyed.insert(keyed.find("\n[parameters]"), "\nkinematics = \"expanded\"");
  build_model(parse_model_text(keyed, "tree.toml", retired), retired);
  EXPECT_NE(retired.format().find("tree.toml:4:14: error: model.kinematics: the key is retired"), std::string::npos)
      << retired.format();
  EXPECT_NE(retired.format().find("hint: remove the line"), std::string::npos) << retired.format();
}

TEST(JointTree, AVariantThatHoldsACoordinateIsDerivedByTheFrameRecursion) {
  // b held at its initial value −0.4: the same as the expanded model with b held
  ModelChoice held;
  held.freeze = {"b"};
  std::string path = write_file("tree.toml", tree);
  ModelChoice held_written_out = held;
  held_written_out.written_out = true;
  Derivation recursive = derive_model_file_for(path, held);
  Derivation expanded = derive_model_file_for(path, held_written_out);
  ASSERT_TRUE(recursive.equations && expanded.equations) << recursive.diagnostics.format() << expanded.diagnostics.format();
  const Equations& r = *recursive.equations;
  const Equations& e = *expanded.equations;
  ASSERT_EQ(r.forcing.size(), 3u);
  std::map<std::string, double> values{{"m", 1.1}, {"l", 0.7}, {"g", 9.81}, {"a", 0.4}, {"s", -0.2}, {"c", 1.3},
                                       {"der(a)", 0.8}, {"der(s)", -1.1}, {"der(c)", 2.0}};
  for (int k = 0; k < 3; ++k) values[fmt::format("ddq{}", k)] = 0.3 * k;
  GiNaC::exmap at = point_by_name(r, values), full = point_by_name(e, values);
  for (unsigned j = 0; j < 3; ++j) {
    EXPECT_NEAR(value_at(r.forcing[j], at), value_at(e.forcing[j], full), 1e-11) << j;
    for (unsigned k = 0; k < 3; ++k) EXPECT_NEAR(value_at(r.mass_matrix(j, k), at), value_at(e.mass_matrix(j, k), full), 1e-11);
  }
}

TEST(JointTree, OtherTreesKeepTheFrameRecursionAndSayWhy) {
  std::string moving = tree;
  moving.replace(moving.find("rotation = \"rot_x(0.3)\""), 23, "rotation = \"rot_x(s)\"");
  Model model = built(moving);
  auto why = why_not_a_joint_tree(model);
  ASSERT_TRUE(why);
  EXPECT_NE(why->find("frame 'base' is not placed by constants and moved by one joint"), std::string::npos) << *why;
  std::string idle = tree;
  idle.replace(idle.find("c = 0.7\n"), 8, "c = 0.7\nmotor = 0\n");
  idle.replace(idle.find("potential = "), 12, "kinetic = \"0.01*der(motor)^2\"\npotential = ");
  why = why_not_a_joint_tree(built(idle));
  ASSERT_TRUE(why);
  EXPECT_NE(why->find("coordinate 'motor' moves no joint"), std::string::npos) << *why;
}

}  // namespace
}  // namespace eomgen::test
