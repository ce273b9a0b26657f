// The bodies' ∂τ/∂q and ∂τ/∂s in closed form (generator/spatial/joint_tree_derivatives.hpp) on a
// floating base: a free torso (position, quaternion, angular velocity), a ball joint through an
// offset anchor below it, a hinge about an oblique axis and a slide on that, a turned fixed frame
// carrying a body and the slide (folded into the hinge's link: fold_fixed_links in spatial/joint_tree_dynamics.cpp), and
// springs and a damper (the applied part, which the closed form leaves out). At random states,
// with the quaternion off its unit length, each entry against central differences of the bodies'
// τ = inverse_dynamics − bodies_gradient->applied_inverse_dynamics, evaluated from the recursion's own definitions;
// and a free body carried by a hinge and a slide. A root joint whose coordinate is cyclic for the
// bodies. Which trees take the gradient's loops.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>

#include <fmt/format.h>

#include "pipeline.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

const char* floating = R"toml([model]
name = "floating"

[parameters]
m = 2.1
g = 9.81

[gravity]
acceleration = ["0", "0", "-g"]

[coordinates]
x = 0.1
y = -0.2
z = 0.5
qw = 1
qx = 0
qy = 0
qz = 0
pw = 1
px = 0
py = 0
pz = 0
h = 0.3
s = 0.05

[[frames]]
name = "torso"
joint = { type = "free", position = ["x", "y", "z"], quaternion = ["qw", "qx", "qy", "qz"], angular_velocity = ["wx", "wy", "wz"] }

[[frames]]
name = "shoulder"
parent = "torso"
origin = ["0.2", "0.1", "0"]
joint = { type = "ball", anchor = ["0.02", "0", "-0.03"], quaternion = ["pw", "px", "py", "pz"], angular_velocity = ["ox", "oy", "oz"] }

[[frames]]
name = "elbow"
parent = "shoulder"
origin = ["0", "0", "-0.3"]
rotation = "rot_x(0.4)"
joint = { type = "revolute", axis = ["1", "2", "2"], anchor = ["0.01", "0.02", "0"], coordinate = "h" }

[[frames]]
name = "mount"
parent = "elbow"
origin = ["0.05", "0", "-0.1"]
rotation = "rot_z(0.7)*rot_x(-0.2)"
joint = { type = "fixed" }

[[frames]]
name = "slider"
parent = "mount"
joint = { type = "prismatic", axis = ["0", "3", "4"], coordinate = "s" }

[[rigid_bodies]]
name = "body"
mass = "m"
frame = "torso"
center = ["0.01", "-0.02", "0.03"]
inertia = [["0.08", "0.004", "-0.002"], ["0.004", "0.11", "0.003"], ["-0.002", "0.003", "0.07"]]

[[rigid_bodies]]
name = "upper"
mass = "0.6"
frame = "shoulder"
center = ["0", "0.01", "-0.15"]
inertia = ["0.006", "0.005", "0.002"]
rotation = "rot_y(0.3)"

[[rigid_bodies]]
name = "lower"
mass = "0.4"
frame = "elbow"
center = ["0.02", "0", "-0.08"]
inertia = [["0.003", "0.0002", "-0.0001"], ["0.0002", "0.0025", "0.0003"], ["-0.0001", "0.0003", "0.002"]]

[[particles]]
name = "bolt"
mass = "0.1"
frame = "mount"
position = ["0", "0.01", "0"]

[[rigid_bodies]]
name = "bracket"
mass = "0.25"
frame = "mount"
center = ["0.03", "-0.01", "0.02"]
inertia = [["0.0007", "0.0001", "0.00005"], ["0.0001", "0.0009", "-0.0002"], ["0.00005", "-0.0002", "0.0011"]]

[[rigid_bodies]]
name = "carriage"
mass = "0.3"
frame = "slider"
center = ["0.01", "0", "0"]
inertia = ["0.0004", "0.0005", "0.0006"]

[energy]
potential = "5*h^2 + 40*s^2"
dissipation = "0.2*der(h)^2/2"
)toml";

// A free body carried by a hinge and a slide: its joint's position columns keep the axes of a
// parent that moves, turns and accelerates (v_λ, a_λ ≠ 0), which a free joint at the top never sees.
const char* carried = R"toml([model]
name = "carried"

[parameters]
g = 9.81

[gravity]
acceleration = ["0", "-g", "0"]

[coordinates]
h = 0.3
s = 0.1
x = 0.1
y = -0.2
z = 0.5
qw = 1
qx = 0
qy = 0
qz = 0

[[frames]]
name = "arm"
origin = ["0.1", "0", "0.2"]
joint = { type = "revolute", axis = ["0", "1", "1"], anchor = ["0.02", "0", "0.01"], coordinate = "h" }

[[frames]]
name = "carrier"
parent = "arm"
origin = ["0.3", "0", "0"]
joint = { type = "prismatic", axis = ["2", "1", "0"], coordinate = "s" }

[[frames]]
name = "drone"
parent = "carrier"
origin = ["0", "0.05", "0"]
rotation = "rot_z(0.5)"
joint = { type = "free", position = ["x", "y", "z"], quaternion = ["qw", "qx", "qy", "qz"], angular_velocity = ["wx", "wy", "wz"] }

[[rigid_bodies]]
name = "link"
mass = "1.2"
frame = "arm"
center = ["0.15", "0.01", "0"]
inertia = [["0.01", "0.001", "0"], ["0.001", "0.02", "0.002"], ["0", "0.002", "0.015"]]

[[rigid_bodies]]
name = "sled"
mass = "0.5"
frame = "carrier"
center = ["0", "0.02", "0.01"]
inertia = ["0.001", "0.002", "0.0015"]

[[rigid_bodies]]
name = "hull"
mass = "0.8"
frame = "drone"
center = ["0.01", "-0.02", "0.03"]
inertia = [["0.008", "0.0004", "-0.0002"], ["0.0004", "0.011", "0.0003"], ["-0.0002", "0.0003", "0.007"]]
)toml";

// Each entry of ∂τ/∂q and ∂τ/∂s against central differences of the bodies' τ, at two random states
// with the quaternions off unit length.
void expect_closed_form_agrees(const char* text, std::size_t coordinates, std::size_t velocities) {
  Equations e = derive_text(text);
  ASSERT_TRUE(e.newton_euler() && e.newton_euler()->bodies_gradient);
  const Symbols& sym = e.symbols;
  std::size_t nq = sym.num_coordinates(), n = e.num_velocities();
  ASSERT_EQ(nq, coordinates);
  ASSERT_EQ(n, velocities);
  const InverseDynamicsGradient* closed_form = e.newton_euler()->bodies_gradient->expressions();
  ASSERT_TRUE(closed_form);
  ASSERT_EQ(closed_form->coordinates.cols(), nq);
  std::mt19937 random(17);
  std::uniform_real_distribution<double> value(-1, 1), scale(0.6, 1.8);
  for (int point = 0; point < 2; ++point) {
    std::map<std::string, double> values;
    for (const std::string& p : sym.parameter_names) values[p] = scale(random) * (p == "g" ? 9.81 : 1.0);
    for (const std::string& q : sym.coordinate_names) values[q] = value(random);
    values["qw"] += 1.5;  // |q| ≠ 1
    if (values.count("pw")) values["pw"] -= 1.5;
    for (const GiNaC::realsymbol& v : sym.velocities) values[v.get_name()] = 2 * value(random);
    for (std::size_t k = 0; k < n; ++k) values[fmt::format("ddq{}", k)] = 3 * value(random);
    // the bodies' τ at a point: each point evaluates every intermediate once
    auto bodies_tau = [&](const std::map<std::string, double>& values_at) {
      GiNaC::exmap p = point_by_name(e, values_at);
      std::vector<double> tau(n);
      for (std::size_t i = 0; i < n; ++i) tau[i] = value_at(e.newton_euler()->inverse_dynamics[i], p) - value_at(e.newton_euler()->bodies_gradient->applied_inverse_dynamics[i], p);
      return tau;
    };
    GiNaC::exmap at = point_by_name(e, values);
    auto check = [&](const std::string& name, auto closed) {
      std::map<std::string, double> plus = values, minus = values;
      double h = 1e-6 * std::max(1.0, std::abs(values.at(name)));
      plus[name] += h, minus[name] -= h;
      std::vector<double> up = bodies_tau(plus), down = bodies_tau(minus);
      for (std::size_t i = 0; i < n; ++i) {
        double difference = (up[i] - down[i]) / (2 * h), exact = value_at(closed(unsigned(i)), at);
        EXPECT_NEAR(exact, difference, 1e-7 * std::max(1.0, std::abs(difference)))
            << "d tau_" << i << " / d " << name << " at point " << point;
      }
    };
    for (unsigned c = 0; c < nq; ++c)
      check(sym.coordinate_names[c], [&](unsigned i) { return closed_form->coordinates(i, c); });
    for (unsigned c = 0; c < n; ++c)
      check(sym.velocities[c].get_name(), [&](unsigned i) { return closed_form->velocities(i, c); });
  }
}

TEST(JointTreeDerivatives, FloatingBaseAgreesWithCentralDifferences) { expect_closed_form_agrees(floating, 13, 11); }

TEST(JointTreeDerivatives, FreeBodyOnAMovingParentAgreesWithCentralDifferences) {
  expect_closed_form_agrees(carried, 9, 8);
}

// a chain of hinges about oblique axes through offset anchors, a body on each link; with `ball`,
// a ball joint at its root
std::string hinge_chain(int hinges, bool ball) {
  std::string coordinates, frames, bodies;
  if (ball) {
    coordinates += "bw = 1\nbx = 0\nby = 0\nbz = 0\n";
    frames += "[[frames]]\nname = \"root\"\njoint = { type = \"ball\", quaternion = [\"bw\", \"bx\", \"by\", \"bz\"], "
              "angular_velocity = [\"ox\", \"oy\", \"oz\"] }\n\n";
  }
  for (int k = 0; k < hinges; ++k) {
    coordinates += fmt::format("a{} = 0.{}\n", k, k + 1);
    std::string parent = k ? fmt::format("parent = \"link{}\"\n", k - 1) : ball ? "parent = \"root\"\n" : "";
    frames += fmt::format("[[frames]]\nname = \"link{0}\"\n{1}origin = [\"0\", \"0.0{2}\", \"-0.2\"]\n"
                          "joint = {{ type = \"revolute\", axis = [\"1\", \"{2}\", \"2\"], anchor = [\"0.01\", \"0\", \"0\"], "
                          "coordinate = \"a{0}\" }}\n\n",
                          k, parent, k % 3 + 1);
    bodies += fmt::format("[[rigid_bodies]]\nname = \"body{0}\"\nmass = \"1.{0}\"\nframe = \"link{0}\"\n"
                          "center = [\"0.01\", \"0\", \"-0.1\"]\ninertia = [\"0.01\", \"0.02\", \"0.015\"]\n\n",
                          k);
  }
  return "[model]\nname = \"chain\"\n\n[coordinates]\n" + coordinates + "\n" + frames + bodies +
         "[gravity]\nacceleration = [\"0\", \"0\", \"-9.81\"]\n";
}

// a chain of `balls` ball joints through offset anchors, a hinge at its end, a body on each link
std::string ball_chain(int balls) {
  std::string coordinates = "h = 0.3\n", frames, bodies;
  for (int k = 0; k <= balls; ++k) {
    std::string parent = k ? fmt::format("parent = \"link{}\"\norigin = [\"0.0{}\", \"0\", \"-0.3\"]\n", k - 1, k % 9) : "";
    std::string joint = k < balls ? fmt::format("{{ type = \"ball\", anchor = [\"0\", \"0.01\", \"0.05\"], quaternion = [\"w{0}\", "
                                                "\"x{0}\", \"y{0}\", \"z{0}\"], angular_velocity = [\"o{0}\", \"p{0}\", \"r{0}\"] }}",
                                                k)
                                  : "{ type = \"revolute\", axis = [\"1\", \"2\", \"2\"], coordinate = \"h\" }";
    if (k < balls) coordinates += fmt::format("w{0} = 1\nx{0} = 0\ny{0} = 0\nz{0} = 0\n", k);
    frames += fmt::format("[[frames]]\nname = \"link{}\"\n{}joint = {}\n\n", k, parent, joint);
    bodies += fmt::format("[[rigid_bodies]]\nname = \"body{0}\"\nmass = \"1.{0}\"\nframe = \"link{0}\"\n"
                          "center = [\"0.01\", \"0.02\", \"-0.15\"]\ninertia = [\"0.03\", \"0.025\", \"0.02\"]\n\n",
                          k);
  }
  return "[model]\nname = \"balls\"\n\n[coordinates]\n" + coordinates + "\n" + frames + bodies +
         "[gravity]\nacceleration = [\"0\", \"0\", \"-9.81\"]\n";
}

// `legs` chains of `hinges` hinges each, hung from the ground side by side (a fixed-base walker),
// with a body on each link
std::string hinge_legs(int legs, int hinges) {
  std::string coordinates, frames, bodies;
  for (int l = 0; l < legs; ++l)
    for (int k = 0; k < hinges; ++k) {
      std::string name = fmt::format("leg{}_{}", l, k);
      coordinates += fmt::format("a{}_{} = 0.{}\n", l, k, (l + k) % 9 + 1);
      std::string placed = k ? fmt::format("parent = \"leg{}_{}\"\norigin = [\"0\", \"0\", \"-0.2\"]\n", l, k - 1)
                             : fmt::format("origin = [\"0.{}\", \"0\", \"0\"]\n", l + 1);
      std::string axis = k % 2 ? "[\"0\", \"1\", \"0\"]" : "[\"1\", \"0\", \"0\"]";
      frames += fmt::format("[[frames]]\nname = \"{0}\"\n{1}joint = {{ type = \"revolute\", axis = {2}, coordinate = \"a{3}_{4}\" }}\n\n",
                            name, placed, axis, l, k);
      bodies += fmt::format("[[rigid_bodies]]\nname = \"body_{0}\"\nmass = \"1.{1}\"\nframe = \"{0}\"\n"
                            "center = [\"0.01\", \"0\", \"-0.1\"]\ninertia = [\"0.01\", \"0.02\", \"0.015\"]\n\n",
                            name, k + l);
    }
  return "[model]\nname = \"legs\"\n\n[coordinates]\n" + coordinates + "\n" + frames + bodies +
         "[gravity]\nacceleration = [\"0\", \"0\", \"-9.81\"]\n";
}

// a shallow tree of many velocities keeps straight-line code, whose size grows with the pairs of a
// joint and one at or above it: four legs of three hinges (12 velocities, 24 pairs) and three of
// four (30 pairs) do; three legs of five (45 pairs) take the loops
TEST(JointTreeDerivatives, ShallowTreesOfManyHingesKeepStraightLineCode) {
  std::string four_by_three = hinge_legs(4, 3);
  Equations walker = derive_text(four_by_three);
  ASSERT_EQ(walker.num_velocities(), 12u);
  EXPECT_FALSE(walker.gradient_loops());
  EXPECT_FALSE(derive_text(hinge_legs(3, 4)).gradient_loops());
  EXPECT_TRUE(derive_text(hinge_legs(3, 5)).gradient_loops());
  expect_closed_form_agrees(four_by_three.c_str(), 12, 12);
}

// the legs of hinge_legs all about the world's y axis: a tree that moves in one plane
// (spatial/planar_tree.hpp), whose straight-line code folds half of every six-vector
std::string planar_legs(int legs, int hinges) {
  std::string text = hinge_legs(legs, hinges);
  for (std::size_t at = text.find("axis = [\"1\", \"0\", \"0\"]"); at != std::string::npos;
       at = text.find("axis = [\"1\", \"0\", \"0\"]", at))
    text.replace(at, 22, "axis = [\"0\", \"1\", \"0\"]");
  return text;
}

// a tree in one plane keeps straight-line code up to 200 pairs (three legs of five: 45 pairs,
// which the same legs about two axes give to the loops) and takes the loops beyond (four of ten:
// 220); its closed form agrees with central differences
TEST(JointTreeDerivatives, TreesInOnePlaneKeepStraightLineCodeLonger) {
  std::string three_by_five = planar_legs(3, 5);
  ASSERT_EQ(three_by_five.find("\"1\", \"0\", \"0\""), std::string::npos);
  EXPECT_FALSE(derive_text(three_by_five).gradient_loops());
  EXPECT_TRUE(derive_text(hinge_legs(3, 5)).gradient_loops());
  EXPECT_TRUE(derive_text(planar_legs(4, 10)).gradient_loops());
  expect_closed_form_agrees(three_by_five.c_str(), 15, 15);
}

// Gymnasium's pusher in shape: seven hinges about their links' own z, y, x, y, x, y, x axes, and
// two bodies on two slides each (11 velocities, 34 pairs), a body on every moving frame
std::string arm_beside_two_sliders() {
  std::string coordinates, frames, bodies;
  const char* axes[] = {R"(["0", "0", "1"])", R"(["0", "1", "0"])", R"(["1", "0", "0"])"};
  auto add = [&](const std::string& name, const std::string& parent, const std::string& origin, const std::string& type,
                 const char* axis, int k) {
    coordinates += fmt::format("{} = 0.{}\n", name, k % 9 + 1);
    frames += fmt::format("[[frames]]\nname = \"{0}\"\n{1}origin = {2}\njoint = {{ type = \"{3}\", axis = {4}, coordinate = \"{0}\" }}\n\n",
                          name, parent.empty() ? "" : "parent = \"" + parent + "\"\n", origin, type, axis);
    bodies += fmt::format("[[rigid_bodies]]\nname = \"{0}_body\"\nmass = \"1.{1}\"\nframe = \"{0}\"\n"
                          "center = [\"0.05\", \"0.01\", \"0\"]\ninertia = [\"0.01\", \"0.02\", \"0.015\"]\n\n",
                          name, k);
  };
  for (int k = 0; k < 7; ++k)
    add(fmt::format("arm{}", k), k ? fmt::format("arm{}", k - 1) : "", k ? R"(["0.3", "0", "0"])" : R"(["0", "-0.6", "0"])",
        "revolute", axes[k == 0 ? 0 : k % 2 ? 1 : 2], k);
  for (const char* thing : {"object", "goal"}) {
    add(fmt::format("{}_y", thing), "", R"(["0.45", "-0.05", "-0.3"])", "prismatic", axes[1], 7);
    add(fmt::format("{}_x", thing), fmt::format("{}_y", thing), R"(["0", "0", "0"])", "prismatic", axes[2], 8);
  }
  return "[model]\nname = \"pusher\"\n\n[coordinates]\n" + coordinates + "\n" + frames + bodies +
         "[gravity]\nacceleration = [\"0\", \"0\", \"-9.81\"]\n";
}

// Beyond 8 velocities and 32 pairs, a tree whose straight-line gradient folds to no more operations
// than the seven-joint arm's keeps it (the pusher: twice as fast as the loops), and it agrees with
// central differences; the gantry hand's oblique fingers (39 pairs) keep the loops
TEST(JointTreeDerivatives, ATreeWhoseStraightLineCodeFoldsKeepsItBeyondThePairs) {
  std::string pusher = arm_beside_two_sliders();
  Equations e = derive_text(pusher);
  ASSERT_EQ(e.num_velocities(), 11u);
  EXPECT_FALSE(e.gradient_loops());
  expect_closed_form_agrees(pusher.c_str(), 11, 11);
  Derivation hand = derive_model_file(std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/models/gantry_hand.toml");
  ASSERT_TRUE(hand.equations) << hand.diagnostics.format();
  EXPECT_TRUE(hand.equations->gradient_loops());
}

// hinge_chain(3)'s root joint made `root_joint` and its gravity `gravity`; its ∂τ/∂q column is the
// cyclic root's structural zero when `cyclic`, and every entry agrees with central differences
void expect_root_column(const std::string& root_joint, const std::string& gravity, bool cyclic) {
  std::string text = hinge_chain(3, false);
  const std::string oblique = R"(type = "revolute", axis = ["1", "1", "2"], anchor = ["0.01", "0", "0"])";
  text.replace(text.find(oblique), oblique.size(), root_joint);
  const std::string down = R"(acceleration = ["0", "0", "-9.81"])";
  text.replace(text.find(down), down.size(), "acceleration = " + gravity);
  Equations e = derive_text(text);
  ASSERT_TRUE(e.newton_euler() && e.newton_euler()->bodies_gradient) << text;
  const InverseDynamicsGradient* closed_form = e.newton_euler()->bodies_gradient->expressions();
  ASSERT_TRUE(closed_form) << text;
  const GiNaC::matrix& dq = closed_form->coordinates;
  bool zero = true;
  for (unsigned i = 0; i < dq.rows(); ++i) zero = zero && dq(i, 0).is_zero();
  EXPECT_EQ(zero, cyclic) << text;
  expect_closed_form_agrees(text.c_str(), 3, 3);
}

// A root hinge about gravity's direction, through an anchor off the origin, moves its subtree as
// one body that gravity does not tell apart: its coordinate is cyclic for the bodies' τ and the
// rest is formed at its zero; so with any root hinge without gravity, or any root slide. Tilt
// gravity and the hinge's column is there again.
TEST(JointTreeDerivatives, ARootJointThatGravityDoesNotSeeIsCyclic) {
  const std::string vertical = R"(type = "revolute", axis = ["0", "0", "2"], anchor = ["0.05", "-0.02", "0.3"])";
  const std::string oblique = R"(type = "revolute", axis = ["1", "1", "2"], anchor = ["0.01", "0", "0"])";
  const std::string slide = R"(type = "prismatic", axis = ["1", "1", "2"])";
  expect_root_column(vertical, R"(["0", "0", "-9.81"])", true);
  expect_root_column(vertical, R"(["0", "0", "4"])", true);
  expect_root_column(vertical, R"(["0.5", "0", "-9.81"])", false);
  expect_root_column(oblique, R"(["0", "0", "-9.81"])", false);
  expect_root_column(oblique, R"(["0", "0", "0"])", true);
  expect_root_column(slide, R"(["0.5", "0", "-9.81"])", true);
}

// beyond 8 velocities a tree of hinges and slides takes the loops (the measured crossover), with
// joints that follow another's coordinate among them, and below a root joint of several velocities
// (its motion straight-line code); so does a long tree with ball joints below its root
TEST(JointTreeDerivatives, TreesOfMoreThanEightHingesTakeTheLoops) {
  EXPECT_FALSE(derive_text(hinge_chain(8, false)).gradient_loops());
  Equations nine = derive_text(hinge_chain(9, false));
  ASSERT_TRUE(nine.gradient_loops());
  EXPECT_EQ(nine.gradient_loops()->parent, (std::vector<int>{-1, 0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_TRUE(nine.gradient_loops()->roots.empty());
  Equations ball = derive_text(hinge_chain(9, true));
  ASSERT_TRUE(ball.gradient_loops()) << "a ball joint at the root";
  ASSERT_EQ(ball.gradient_loops()->roots.size(), 1u);
  const JointedRoot& root = ball.gradient_loops()->roots[0];
  EXPECT_EQ(root.link, 0u);
  EXPECT_EQ(root.velocity, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(root.turns, (std::vector<bool>{true, true, true}));
  EXPECT_EQ(root.coordinate, (std::vector<int>{0, 1, 2, 3})) << "the quaternion's four components";
  EXPECT_TRUE(ball.gradient_loops()->velocity[0].empty()) << "the root's table entries are a fixed link's";
  EXPECT_EQ(ball.gradient_loops()->velocity[1], (std::vector<int>{3}));
  EXPECT_EQ(ball.gradient_loops()->most_columns(), 1u);
  EXPECT_FALSE(derive_text(floating).gradient_loops()) << "11 velocities, a ball joint below the free torso";
  // a ball joint below the root: straight-line code up to 400 pairs of columns (the measured crossover),
  // then the loops, its link of three columns and four directions in their tables
  EXPECT_FALSE(derive_text(ball_chain(7)).gradient_loops()) << "7 balls and a hinge: 22 velocities, 274 pairs";
  Equations balls = derive_text(ball_chain(9));
  ASSERT_TRUE(balls.gradient_loops()) << "9 balls and a hinge: 28 velocities, 433 pairs";
  const TreeLinkTables& links = *balls.gradient_loops();
  ASSERT_EQ(links.velocity.size(), 10u);
  EXPECT_TRUE(links.velocity[0].empty()) << "the root's ball is the jointed root's";
  EXPECT_EQ(links.velocity[1], (std::vector<int>{4, 5, 6}));
  EXPECT_EQ(links.velocity[9], (std::vector<int>{0})) << "the hinge's rate, its angle declared first";
  EXPECT_EQ(links.coordinate[1], (std::vector<int>{5, 6, 7, 8})) << "the second ball's quaternion";
  EXPECT_EQ(links.coordinate[9], (std::vector<int>{0})) << "the hinge's angle, declared first";
  EXPECT_EQ(links.most_columns(), 3u);
  EXPECT_EQ(links.most_directions(), 4u);
  ASSERT_EQ(links.weight[1].size(), 4u);
  EXPECT_EQ(links.weight[1][0].size(), 3u) << "a quaternion component's weights over the ball's three columns";
  // tests/crosscheck/robot_jacobian_test.cpp checks this one's loops against the complex step
  Derivation hand = derive_model_file(std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/models/gantry_hand.toml");
  ASSERT_TRUE(hand.equations) << hand.diagnostics.format();
  EXPECT_TRUE(hand.equations->gradient_loops()) << "a slide and a fixed link among 11 joints";
  // nine hinges, the last following the eighth's coordinate: 8 velocities, straight-line sums
  std::string follower = hinge_chain(9, false);
  follower.replace(follower.find("a8 = 0.9\n"), 9, "");
  follower.replace(follower.find("coordinate = \"a8\""), 17, "coordinate = \"a7\", multiplier = -2");
  EXPECT_FALSE(derive_text(follower).gradient_loops()) << follower;
  // 11 joints, 9 velocities, two distal hinges following their middle ones: into their leaders'
  Derivation coupled = derive_model_file(std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/models/coupled_hand.toml");
  ASSERT_TRUE(coupled.equations) << coupled.diagnostics.format();
  ASSERT_TRUE(coupled.equations->gradient_loops());
  EXPECT_EQ(coupled.equations->gradient_loops()->velocity,
            (std::vector<std::vector<int>>{{0}, {1}, {2}, {3}, {3}, {4}, {5}, {5}, {6}, {7}, {8}}))
      << "the fixed link folded into its parent's";
}

// A chain of nine hinges beside a body on a free joint and a body hung from a ball joint: each root's
// joint of several velocities is a jointed root of the loops (its table entries a fixed link's),
// and neither counts as a ball joint below a root, whose cut is 400 pairs
TEST(JointTreeDerivatives, FreeObjectsBesideATreeAreJointedRootsOfTheLoops) {
  std::string text = hinge_chain(9, false);
  text.replace(text.find("[coordinates]\n"), 14,
               "[coordinates]\nx = 0\ny = 0\nz = 0\nqw = 1\nqx = 0\nqy = 0\nqz = 0\nbw = 1\nbx = 0\nby = 0\nbz = 0\n");
  text += R"toml(
[[frames]]
name = "box"
origin = ["0.5", "0", "0"]
joint = { type = "free", position = ["x", "y", "z"], quaternion = ["qw", "qx", "qy", "qz"], angular_velocity = ["wx", "wy", "wz"] }

[[frames]]
name = "lamp"
origin = ["-0.5", "0", "1"]
joint = { type = "ball", quaternion = ["bw", "bx", "by", "bz"], angular_velocity = ["ox", "oy", "oz"] }

[[rigid_bodies]]
name = "box_body"
mass = "0.7"
frame = "box"
center = ["0.01", "0", "0.02"]
inertia = ["0.01", "0.02", "0.015"]

[[rigid_bodies]]
name = "lamp_body"
mass = "0.4"
frame = "lamp"
center = ["0", "0.01", "-0.3"]
inertia = ["0.01", "0.012", "0.003"]
)toml";
  Equations e = derive_text(text);
  ASSERT_TRUE(e.gradient_loops()) << "9 hinges, a free body and a ball: 18 velocities, 90 pairs";
  const TreeLinkTables& links = *e.gradient_loops();
  ASSERT_EQ(links.roots.size(), 2u);
  std::vector<std::size_t> roots = {links.roots[0].link, links.roots[1].link};
  for (std::size_t r : roots) {
    EXPECT_EQ(links.parent[r], -1);
    EXPECT_TRUE(links.velocity[r].empty()) << "a jointed root's table entries are a fixed link's";
  }
  EXPECT_EQ(links.roots[0].velocity.size() + links.roots[1].velocity.size(), 9u) << "six columns and three";
  EXPECT_EQ(links.most_columns(), 1u) << "the hinges' one column: the one-column pass";
}

}  // namespace
}  // namespace eomgen::test
