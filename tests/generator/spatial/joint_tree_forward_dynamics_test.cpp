// The articulated-body algorithm over a joint tree (generator/spatial/joint_tree_forward_dynamics.hpp):
// its q'' against M⁻¹ f of the same derivation (M from the composite-rigid-body algorithm, f from
// Newton–Euler) at random states, on chains and trees of oblique hinges through offset anchors, a
// slide, a fixed frame, ball and free joints, with armature, damping, springs and inputs; where eomgen takes it by
// itself (a mean depth of 5 joints or more) and where not; and the located refusals when it is asked
// for a tree it does not solve. MuJoCo checks the generated code of a long chain
// (tests/crosscheck/mujoco_oracle_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "emit/cpp_header.hpp"
#include "pipeline.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

using GiNaC::ex;

std::string crosscheck_model(const std::string& name) {
  return read_file(std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/models/" + name + ".toml");
}

// a chain of rods on universal joints (rot_z then rot_x: two hinges a rod), `hinges` of them in all
// (a first rod of one hinge when odd), gravity along −z, a spring on the first hinge and a force
// input at the tip
std::string rod_chain(int hinges) {
  int rods = (hinges + 1) / 2;
  std::string out = "[model]\nname = \"rods\"\n[parameters]\nm = 1.2\nl = 0.8\ng = 9.81\nk = 2.5\n"
                    "[gravity]\nacceleration = [\"0\", \"0\", \"-g\"]\n[inputs]\nF = 0.0\n[coordinates]\n";
  bool odd = hinges % 2 == 1;
  for (int i = 1; i <= rods; ++i) {
    if (!(odd && i == 1)) out += fmt::format("a{} = 0.1\n", i);
    out += fmt::format("b{} = 0.2\n", i);
  }
  for (int i = 1; i <= rods; ++i) {
    std::string turn = odd && i == 1 ? "rot_x(b1)" : fmt::format("rot_z(a{0})*rot_x(b{0})", i);
    out += fmt::format("[[frames]]\nname = \"link{}\"\nrotation = \"{}\"\n", i, turn);
    if (i > 1) out += fmt::format("parent = \"link{}\"\norigin = [\"0\", \"0\", \"-l\"]\n", i - 1);
  }
  for (int i = 1; i <= rods; ++i)
    out += fmt::format("[[rigid_bodies]]\nname = \"rod{0}\"\nmass = \"m\"\nframe = \"link{0}\"\ncenter = [\"0\", \"0\", "
                       "\"-l/2\"]\ninertia = [\"m*l^2/12\", \"m*l^2/12\", \"m*l^2/200\"]\n",
                       i);
  out += fmt::format("[[points]]\nname = \"tip\"\nframe = \"link{}\"\nposition = [\"0\", \"0\", \"-l\"]\n", rods);
  out += "[[forces]]\nat = \"tip\"\nforce = [\"F\", \"0\", \"0\"]\n";
  return out + "[energy]\npotential = \"k*b1^2/2\"\n";
}

// the algorithm's q'' against M⁻¹ f at random states and inputs
void expect_accelerations_solve_the_equations(const Equations& e, int points, unsigned seed) {
  ASSERT_TRUE(e.joint_tree_accelerations()) << e.model_name;
  std::size_t n = e.num_velocities();
  for (GiNaC::exmap at : random_points(e.symbols, points, seed)) {
    for (const Intermediate& i : e.intermediates) at[i.symbol] = value_at(i.definition, at);
    for (const Intermediate& i : e.joint_tree_accelerations()->intermediates) at[i.symbol] = value_at(i.definition, at);
    std::vector<std::vector<double>> M(n, std::vector<double>(n));
    std::vector<double> f(n);
    for (unsigned j = 0; j < n; ++j) {
      f[j] = value_at(e.forcing[j], at);
      for (unsigned k = 0; k < n; ++k) M[j][k] = value_at(e.mass_matrix(j, k), at);
    }
    std::vector<double> expected = solved_linear_system(M, f);
    double scale = 0;
    for (double x : expected) scale = std::max(scale, std::abs(x));
    for (std::size_t j = 0; j < n; ++j)
      EXPECT_NEAR(value_at(e.joint_tree_accelerations()->accelerations[j], at), expected[j], 1e-11 * std::max(1.0, scale))
          << e.model_name << ": q''[" << j << "] of " << n;
  }
}

Equations articulated(const std::string& text) { return derive_text(text, "model.toml", solved_by(ForwardDynamics::articulated)); }

TEST(JointTreeAccelerations, LongChainOfHingesThroughOffsetAnchorsGivesMInverseF) {
  expect_accelerations_solve_the_equations(derive_text(crosscheck_model("hinge_chain")), 2, 3u);
}

TEST(JointTreeAccelerations, ArmWithArmatureGivesMInverseF) {
  // armature: [energy] kinetic ½ Σ a q'², whose a q'' the joint's D takes
  expect_accelerations_solve_the_equations(articulated(crosscheck_model("seven_joint_arm")), 4, 5u);
}

TEST(JointTreeAccelerations, BranchedTreeWithASlideAndAFixedFrameGivesMInverseF) {
  expect_accelerations_solve_the_equations(articulated(crosscheck_model("branched_tree")), 2, 7u);
  expect_accelerations_solve_the_equations(articulated(read_file(model_path("oblique_tree"))), 6, 9u);
}

// Appell's equations in the tree's velocities (a quaternion's angular velocity, a free joint's linear
// velocity in the world's axes): a joint of 3 or 6 columns, its D factored as L Δ Lᵀ
TEST(JointTreeAccelerations, BallAndFreeJointsGiveMInverseF) {
  expect_accelerations_solve_the_equations(articulated(crosscheck_model("ball_hung_chain")), 3, 19u);
  expect_accelerations_solve_the_equations(articulated(crosscheck_model("quadruped")), 2, 21u);
  expect_accelerations_solve_the_equations(articulated(read_file(model_path("tumbling_body"))), 4, 23u);
  expect_accelerations_solve_the_equations(articulated(read_file(model_path("ball_joint_top"))), 4, 25u);
}

TEST(JointTreeAccelerations, ChainOfUniversalJointsWithATipForceGivesMInverseF) {
  for (int hinges : {1, 2, 5, 9}) expect_accelerations_solve_the_equations(articulated(rod_chain(hinges)), 4, 11u + unsigned(hinges));
}

// n links hung one below the other on hinges about oblique axes through offset anchors, with
// armature: each turn of an articulated inertia a dense 3×3 product
std::string oblique_chain(int n) {
  std::string out = "[model]\nname = \"oblique\"\n[parameters]\ng = 9.81\n[coordinates]\n";
  for (int i = 1; i <= n; ++i) out += fmt::format("q{} = 0.1\n", i);
  const char* axes[] = {"[\"0.3\", \"0.5\", \"0.8\"]", "[\"-0.6\", \"0.7\", \"0.2\"]"};
  for (int i = 1; i <= n; ++i) {
    out += fmt::format("[[frames]]\nname = \"link{}\"\n", i);
    if (i > 1) out += fmt::format("parent = \"link{}\"\norigin = [\"0.02\", \"0.01\", \"-0.3\"]\n", i - 1);
    out += fmt::format("joint = {{ type = \"revolute\", axis = {}, anchor = [\"0.01\", \"0\", \"0.02\"], coordinate = \"q{}\" }}\n",
                       axes[i % 2], i);
    out += fmt::format("[[rigid_bodies]]\nname = \"rod{0}\"\nmass = \"1.5\"\nframe = \"link{0}\"\ncenter = [\"0.01\", \"0\", "
                       "\"-0.15\"]\ninertia = [[\"0.02\", \"0.001\", \"0\"], [\"0.001\", \"0.025\", \"0.002\"], [\"0\", \"0.002\", "
                       "\"0.015\"]]\n",
                       i);
  }
  std::string kinetic;
  for (int i = 1; i <= n; ++i) kinetic += fmt::format("{}0.01*der(q{})^2/2", i > 1 ? " + " : "", i);
  return out + "[gravity]\nacceleration = [\"0\", \"0\", \"-g\"]\n[energy]\nkinetic = \"" + kinetic + "\"\n";
}

bool header_takes_articulated_bodies(const Equations& e) {
  return emit_cpp_header(e).substr(0, 2000).find("articulated-body algorithm over the joints") != std::string::npos;
}

// the mean depth admits a tree (spatial/joint_tree_forward_dynamics.cpp), the operations decide
// (emit/cpp_joint_tree.hpp): 4 hinges in a row have 2.5, 9 have 5
TEST(JointTreeAccelerations, EomgenTakesTheAlgorithmWhereItsCodeIsShorter) {
  EXPECT_FALSE(derive_text(rod_chain(4)).joint_tree_accelerations());
  EXPECT_TRUE(header_takes_articulated_bodies(derive_text(rod_chain(9))));
  EXPECT_TRUE(header_takes_articulated_bodies(derive_text(crosscheck_model("hinge_chain"))));
  EXPECT_TRUE(header_takes_articulated_bodies(derive_text(crosscheck_model("floating_snake")))) << "a free joint above";
  EXPECT_FALSE(derive_text(crosscheck_model("seven_joint_arm")).joint_tree_accelerations()) << "mean depth 4";
  EXPECT_FALSE(derive_text(crosscheck_model("branched_tree")).joint_tree_accelerations()) << "mean depth 4.3";
  EXPECT_FALSE(derive_text(rod_chain(12), "model.toml", solved_by(ForwardDynamics::mass_matrix)).joint_tree_accelerations());
  // oblique axes: deep enough to weigh, but M = L D Lᵀ is the shorter code; asked for, the algorithm
  Equations oblique = derive_text(oblique_chain(12));
  ASSERT_TRUE(oblique.joint_tree_accelerations());
  EXPECT_FALSE(header_takes_articulated_bodies(oblique));
  Equations asked = articulated(oblique_chain(12));
  EXPECT_TRUE(header_takes_articulated_bodies(asked));
  expect_accelerations_solve_the_equations(asked, 2, 17u);
}

std::string refusal(const std::string& text) {
  ModelChoice choice = solved_by(ForwardDynamics::articulated);
  return derive_model_text(text, "tree.toml", choice).diagnostics.format();
}

TEST(JointTreeAccelerations, TreesItDoesNotSolveAreLocatedErrors) {
  // a coordinate that moves two joints (one follows the other's, as URDF's mimic)
  std::string hand = refusal(crosscheck_model("coupled_hand"));
  EXPECT_NE(hand.find("tree.toml:1:1: error: --forward-dynamics: the articulated-body recursion needs a tree of particles "
                      "or of joints"),
            std::string::npos)
      << hand;
  EXPECT_NE(hand.find("moves more than one joint"), std::string::npos) << hand;
  EXPECT_NE(hand.find("hint: leave --forward-dynamics out, or use mass_matrix"), std::string::npos) << hand;
  // below a ball joint (Appell's equations), the tree's own reason
  std::string ball = crosscheck_model("ball_hung_chain");
  ball.insert(ball.find("dissipation = "), "kinetic = \"der(a1)*der(a2)/10\"\n");
  std::string under_ball = refusal(ball);
  EXPECT_NE(under_ball.find("needs a tree of joints, and this model is not one: its [energy] kinetic couples the rates of "
                            "'a1' and 'a2'"),
            std::string::npos)
      << under_ball;
  std::string lagrange1 = rod_chain(3);
  lagrange1.insert(lagrange1.find("[parameters]"), "method = \"lagrange1\"\n");
  EXPECT_NE(refusal(lagrange1).find("not method 'lagrange1'"), std::string::npos) << refusal(lagrange1);
  std::string coupled = rod_chain(3) + "kinetic = \"der(a2)*der(b2)/10\"\n";
  std::string message = refusal(coupled);
  EXPECT_NE(message.find("its [energy] kinetic couples the rates of 'a2' and 'b2'"), std::string::npos) << message;
  EXPECT_EQ(derive_model_text(coupled, "tree.toml", {}).diagnostics.format(), "") << "eomgen's choice keeps M";
}

// a free base without mass whose hinge below turns about an axis through its origin: its turn about
// that axis meets no inertia (M singular), which the recursion finds as a pivot of exact zero: an
// error naming the frame and the axis, where GiNaC's division by zero said neither (the M form
// leaves it to the header's LDLᵀ, whose simulation reports the singular M at its first step)
TEST(JointTreeAccelerations, AJointDirectionThatMovesNoInertiaIsNamed) {
  std::string text = R"([model]
name = "massless_hip"
method = "appell"

[gravity]
acceleration = ["0", "0", "-9.81"]

[coordinates]
x = 0
y = 0
z = 0
qw = 1
qx = 0
qy = 0
qz = 0
hip = 0

[[frames]]
name = "hip"
joint = { type = "free", position = ["x", "y", "z"], quaternion = ["qw", "qx", "qy", "qz"], angular_velocity = ["wx", "wy", "wz"] }

[[frames]]
name = "thigh"
parent = "hip"
joint = { type = "revolute", axis = ["1", "0", "0"], coordinate = "hip" }

[[rigid_bodies]]
name = "leg"
frame = "thigh"
mass = "2"
center = ["0", "0", "-0.2"]
inertia = ["0.03", "0.03", "0.01"]
)";
  std::string message = refusal(text);
  EXPECT_NE(message.find("tree.toml:3:10: error: model.method: the joint of frame 'hip' moves no inertia turning about "
                         "(1, 0, 0)"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("hint: give the links this joint moves the mass and inertia they have"), std::string::npos)
      << message;
  std::string weighed = text + "\n[[rigid_bodies]]\nname = \"pelvis\"\nframe = \"hip\"\nmass = \"1\"\ninertia = [\"0.01\", "
                               "\"0.01\", \"0.01\"]\n";
  EXPECT_EQ(refusal(weighed), "");
}

}  // namespace
}  // namespace eomgen::test
