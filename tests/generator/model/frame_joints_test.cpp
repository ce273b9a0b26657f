// Frames written as products of turns and sums of offsets read as joints
// (generator/model/frame_joints.hpp): with kinematics left out, a tree of such frames is built
// as the tree of joints it is, which the spatial algorithms derive, and its M, f, T, τ and
// closed-form derivatives are those of the same model written out in q. A universal joint
// (rot_z(a)*rot_x(b)) is two links, a turn by 2c + 0.3 about an oblique axis a joint with a
// multiplier and an offset, a constant turn after the last coordinate's a fixed link, an origin
// x e_x + h a slide. What does not read as joints (an angle in two coordinates or in t, an origin
// not linear in q, a particle placed outside the frames) stays written out, and so does every
// model for Routh's reduction, diff and another method.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <regex>
#include <string>

#include "emit/cpp_header.hpp"
#include "model/model.hpp"
#include "pipeline.hpp"
#include "spatial/joint_tree_dynamics.hpp"
#include "support/expanded_oracle.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

using GiNaC::ex;

const char* turns = R"toml([model]
name = "turns"

[parameters]
m = 1.2
l = 0.5
g = 9.81

[coordinates]
a = 0.3
b = -0.4
c = 0.6
d = 0.2

[[frames]]
name = "yoke"
origin = ["0", "0", "l"]
rotation = "rot_x(0.3)*rot_z(a)*rot_x(b)"

[[frames]]
name = "arm"
parent = "yoke"
origin = ["l", "0.1", "0"]
rotation = "rot_axis(1, 2, 2, 2*c + 0.3)*rot_y(Pi/2)"

[[frames]]
name = "hand"
parent = "arm"
origin = ["0", "0", "0.2"]
rotation = "rot_y(-d)"

[[rigid_bodies]]
name = "yoke_link"
mass = "m"
frame = "yoke"
center = ["0.05", "0.02", "-l/2"]
inertia = [["0.03", "0.002", "-0.001"], ["0.002", "0.028", "0.003"], ["-0.001", "0.003", "0.012"]]

[[rigid_bodies]]
name = "arm_link"
mass = "0.7"
frame = "arm"
center = ["l/2", "0", "0.01"]
rotation = "rot_y(0.4)"
inertia = ["0.002", "0.011", "0.012"]

[[points]]
name = "tip"
frame = "hand"
position = ["0.1", "0.05", "-0.3"]

[outputs]
tip_x = "tip.x"
tip_y = "tip.y"
tip_z = "tip.z"

[[particles]]
name = "weight"
mass = "0.4"
frame = "hand"
position = ["0", "0.03", "0.1"]

[gravity]
acceleration = ["0", "0", "-g"]

[energy]
potential = "20*d^2"
dissipation = "0.3*der(a)^2/2"
)toml";

// a gantry: a carriage slid along x at height h, a trolley slid across it along the numbers'
// direction (0.6, 0.8, 0) and turned by psi, a boom that hangs by −l z from it and swings by b,
// a rotor that turns by r in the boom and a bead that slides by 0.3 w in the trolley
const char* gantry = R"toml([model]
name = "gantry"

[parameters]
m = 1.2
l = 0.5
h = 2
g = 9.81

[coordinates]
x = 0.3
s = -0.4
psi = 0.6
z = 0.2
b = 0.1
r = 0.5
w = 0.3

[[frames]]
name = "carriage"
origin = ["x", "0.2", "h"]

[[frames]]
name = "trolley"
parent = "carriage"
origin = ["0.6*s", "0.8*s + 0.1", "0"]
rotation = "rot_z(psi)"

[[frames]]
name = "boom"
parent = "trolley"
origin = ["0", "0", "-l*z"]
rotation = "rot_y(b)*rot_x(0.2)"

[[rigid_bodies]]
name = "carriage_body"
mass = "3"
frame = "carriage"
center = ["0", "0.1", "0"]
inertia = ["0.1", "0.2", "0.25"]

[[rigid_bodies]]
name = "trolley_body"
mass = "m"
frame = "trolley"
center = ["0.05", "0", "0.02"]
inertia = [["0.03", "0.002", "-0.001"], ["0.002", "0.028", "0.003"], ["-0.001", "0.003", "0.012"]]

[[points]]
name = "tip"
frame = "boom"
position = ["0.1", "0.05", "-0.3"]

[outputs]
tip_x = "tip.x"
tip_y = "tip.y"
tip_z = "tip.z"

[[particles]]
name = "hook"
mass = "0.8"
frame = "boom"
position = ["0.1", "0", "-0.3"]

[[rigid_bodies]]
name = "rotor"
mass = "0.6"
frame = "boom"
center = ["0.1", "0", "-0.2"]
rotation = "rot_z(0.3)*rot_x(r)"
inertia = [["0.004", "0.0002", "-0.0001"], ["0.0002", "0.003", "0.0003"], ["-0.0001", "0.0003", "0.002"]]

[[particles]]
name = "bead"
mass = "0.3"
frame = "trolley"
position = ["0.3*w", "0", "-0.1"]

[gravity]
acceleration = ["0", "0", "-g"]

[energy]
potential = "30*z^2"
dissipation = "0.2*der(x)^2/2"
)toml";

// a screw: a nut that rises by p q as it turns by q about z, with an arm hinged on it by a; the
// nut's coordinate moves two joints, a slide and a turn
const char* screw = R"toml([model]
name = "screw"

[parameters]
p = 0.05
g = 9.81

[coordinates]
q = 0.4
a = 0.2

[[frames]]
name = "nut"
origin = ["0", "0", "p*q"]
rotation = "rot_z(q)"

[[frames]]
name = "arm"
parent = "nut"
origin = ["0.1", "0", "0"]
rotation = "rot_y(a)"

[[rigid_bodies]]
name = "nut_body"
mass = "2"
frame = "nut"
center = ["0.01", "0", "0"]
inertia = ["0.02", "0.02", "0.03"]

[[particles]]
name = "tip"
mass = "0.5"
frame = "arm"
position = ["0.3", "0", "0"]

[gravity]
acceleration = ["0", "0", "-g"]
)toml";

const char* spherical_pendulum = R"toml([model]
name = "pendulum"

[parameters]
m = 1.2
l = 0.5
g = 9.81

[coordinates]
a = 0.3
b = 0.4

[[frames]]
name = "rod"
rotation = "rot_z(a)*rot_x(b)"

[[particles]]
name = "bob"
mass = "m"
frame = "rod"
position = ["0", "0", "-l"]

[gravity]
acceleration = ["0", "0", "-g"]
)toml";


const FrameLink& link_named(const Model& m, const std::string& name) {
  for (const FrameLink& l : m.frame_links)
    if (l.name == name) return l;
  throw std::invalid_argument("no link " + name);
}

bool same_matrix(const GiNaC::matrix& a, const GiNaC::matrix& b) {
  for (unsigned r = 0; r < 3; ++r)
    for (unsigned c = 0; c < 3; ++c) {
      ex d = (a(r, c) - b(r, c)).evalf();
      if (!GiNaC::is_a<GiNaC::numeric>(d) || std::abs(GiNaC::ex_to<GiNaC::numeric>(d).to_double()) > 1e-15) return false;
    }
  return true;
}

TEST(FrameJoints, ProductsOfTurnsAreLinksWithJoints) {
  Model m = built(turns);
  ASSERT_TRUE(m.recursive_kinematics);
  ASSERT_FALSE(why_not_a_joint_tree(m)) << *why_not_a_joint_tree(m);
  std::vector<std::string> names;
  for (const FrameLink& l : m.frame_links) names.push_back(l.name);
  EXPECT_EQ(names, (std::vector<std::string>{"yoke_turn1", "yoke", "arm_turn1", "arm", "hand"}));
  using Type = FrameLink::Joint::Type;
  const FrameLink::Joint& first = *link_named(m, "yoke_turn1").joint;
  EXPECT_EQ(first.type, Type::revolute);
  EXPECT_EQ(first.coordinate, 0);
  EXPECT_TRUE(same_matrix(first.placement, elementary_rotation(0, ex(0.3))));
  EXPECT_TRUE((first.placement_origin[2] - parameter_named(m.symbols, "l")).is_zero());
  const FrameLink::Joint& second = *link_named(m, "yoke").joint;
  EXPECT_EQ(second.coordinate, 1);
  EXPECT_EQ(link_named(m, "yoke").parent, 0);
  EXPECT_TRUE(second.placement_origin[0].is_zero() && second.placement_origin[2].is_zero()) << "it sits at the first's origin";
  EXPECT_TRUE((second.axis[0] - 1).is_zero());
  const FrameLink::Joint& oblique = *link_named(m, "arm_turn1").joint;
  EXPECT_EQ(oblique.coordinate, 2);
  EXPECT_TRUE((oblique.multiplier - 2).is_zero()) << oblique.multiplier;
  EXPECT_TRUE((oblique.offset - ex(3) / 10).is_zero()) << oblique.offset;
  EXPECT_TRUE((oblique.axis[1] - ex(2) / 3).is_zero()) << oblique.axis[1];
  const FrameLink::Joint& fixed = *link_named(m, "arm").joint;
  EXPECT_EQ(fixed.type, Type::fixed);
  EXPECT_TRUE(same_matrix(fixed.placement, elementary_rotation(1, GiNaC::Pi / 2)));
  const FrameLink::Joint& hand = *link_named(m, "hand").joint;
  EXPECT_EQ(hand.coordinate, 3);
  EXPECT_TRUE((hand.multiplier + 1).is_zero());
}

// an origin linear in the coordinates: a slide per coordinate, massless but the last, then the
// turns; and bodies moved in their frames
TEST(FrameJoints, MovingOriginsAreSlides) {
  Model m = built(gantry);
  ASSERT_FALSE(why_not_a_joint_tree(m)) << *why_not_a_joint_tree(m);
  std::vector<std::string> names;
  for (const FrameLink& l : m.frame_links) names.push_back(l.name);
  EXPECT_EQ(names, (std::vector<std::string>{"carriage", "trolley_turn1", "trolley", "boom_turn1", "boom_turn2", "boom",
                                              "bead", "rotor"}));
  using Type = FrameLink::Joint::Type;
  const FrameLink::Joint& carriage = *link_named(m, "carriage").joint;
  EXPECT_EQ(carriage.type, Type::prismatic);
  EXPECT_TRUE((carriage.axis[0] - 1).is_zero() && (carriage.multiplier - 1).is_zero());
  EXPECT_TRUE((carriage.placement_origin[2] - parameter_named(m.symbols, "h")).is_zero()) << carriage.placement_origin[2];
  const FrameLink::Joint& across = *link_named(m, "trolley_turn1").joint;
  EXPECT_EQ(across.type, Type::prismatic);
  EXPECT_TRUE((across.axis[1] - ex(4) / 5).is_zero() && (across.multiplier - 1).is_zero()) << across.axis[1];
  EXPECT_TRUE((across.placement_origin[1] - ex(1) / 10).is_zero());
  EXPECT_EQ(link_named(m, "trolley").joint->type, Type::revolute);
  const FrameLink::Joint& drop = *link_named(m, "boom_turn1").joint;
  EXPECT_EQ(drop.type, Type::prismatic);
  EXPECT_TRUE((drop.multiplier + parameter_named(m.symbols, "l")).is_zero()) << drop.multiplier;
  EXPECT_EQ(link_named(m, "boom_turn2").joint->type, Type::revolute);
  EXPECT_EQ(link_named(m, "boom").joint->type, Type::fixed);
  // a body that the coordinates move in its frame is a link of its own, in which it sits still
  const FrameLink& rotor = link_named(m, "rotor");
  EXPECT_EQ(rotor.joint->type, Type::revolute);
  EXPECT_EQ(m.frame_links[std::size_t(rotor.parent)].name, "boom");
  EXPECT_TRUE(same_matrix(rotor.joint->placement, elementary_rotation(2, ex(0.3))));
  const FrameLink& bead = link_named(m, "bead");
  EXPECT_EQ(bead.joint->type, Type::prismatic);
  EXPECT_TRUE((bead.joint->multiplier - ex(3) / 10).is_zero()) << bead.joint->multiplier;
  EXPECT_EQ(m.frame_links[std::size_t(bead.parent)].name, "trolley");
}

// where the links place a point (the frames' own placement, which outputs and constraints use)
void expect_expanded_outputs(const std::string& text) {
  Equations tree = derive_text(text), written = derive_text(text, "model.toml", model_written_out());
  ASSERT_EQ(tree.outputs.size(), 3u);
  std::mt19937 random(3);
  for (int point = 0; point < 5; ++point) {
    std::map<std::string, double> values = random_point(tree, random);
    GiNaC::exmap at = point_by_name(tree, values), full = point_by_name(written, values);
    for (std::size_t k = 0; k < 3; ++k) {
      double x = value_at(tree.outputs[k].expression, at), y = value_at(written.outputs[k].expression, full);
      EXPECT_NEAR(x, y, 1e-13 * std::max(1.0, std::abs(y))) << tree.outputs[k].name;
    }
  }
}

TEST(FrameJoints, TheTreeGivesTheExpandedEquations) {
  expect_expanded_outputs(turns);
  expect_expanded_outputs(gantry);
  expect_expanded_equations(turns, 4);
  expect_expanded_equations(gantry, 7);
  expect_expanded_equations(screw, 2);
}

TEST(FrameJoints, TheTreeGivesTheExpandedDerivatives) {
  expect_expanded_derivatives(turns, 4);
  expect_expanded_derivatives(gantry, 7);
  expect_expanded_derivatives(screw, 2);
}

// The 7-joint arm of the tree benchmark written with rotations instead of joints, as a user writes
// it by hand (rotation = "rot_x(-Pi/2)*rot_z(q2)"): the same header, byte for byte. Until frames
// read as joints, it took the expanded derivation: a 44 MB header in 67 s.
TEST(FrameJoints, AnArmWrittenWithRotationsIsTheArmWrittenWithJoints) {
  std::string joints = read_file(std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/models/seven_joint_arm.toml");
  ASSERT_FALSE(joints.empty());
  const std::regex turned("rotation = \"([^\"]*)\"\njoint  = \\{ type = \"revolute\", axis = \\[\"0\", \"0\", \"1\"\\], coordinate = \"(q[0-9])\" \\}");
  const std::regex upright("joint  = \\{ type = \"revolute\", axis = \\[\"0\", \"0\", \"1\"\\], coordinate = \"(q[0-9])\" \\}");
  std::string rotations = std::regex_replace(std::regex_replace(joints, turned, "rotation = \"$1*rot_z($2)\""), upright,
                                             "rotation = \"rot_z($1)\"");
  ASSERT_EQ(rotations.find("joint  ="), std::string::npos) << rotations;
  EXPECT_EQ(emit_cpp_header(derive_text(rotations)), emit_cpp_header(derive_text(joints)));
}

// each change makes one frame unreadable as joints, and the model stays written out in q (a slide
// along a direction of parameters would need its length, √(2 l²) here, and its sign)
TEST(FrameJoints, WhatIsNotAJointStaysWrittenOut) {
  auto changed = [](const std::string& from, const std::string& to) {
    std::string text = turns;
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  for (const std::string& text : {changed("rot_y(-d)", "rot_y(c - d)"), changed("rot_y(-d)", "rot_y(sin(d))"),
                                  changed("rot_y(-d)", "rot_y(d + t)"), changed("[\"0\", \"0\", \"0.2\"]", "[\"0\", \"0\", \"0.2 + d^2\"]"),
                                  changed("[\"0\", \"0\", \"0.2\"]", "[\"0\", \"0.2*t\", \"0\"]"),
                                  changed("[\"0\", \"0\", \"0.2\"]", "[\"0\", \"l*d\", \"l*d\"]"),
                                  changed("frame = \"hand\"\nposition = [\"0\", \"0.03\", \"0.1\"]", "position = [\"0\", \"0.03\", \"l*sin(a)\"]")}) {
    Model m = built(text);
    EXPECT_FALSE(m.recursive_kinematics) << text;
    EXPECT_TRUE(m.frame_links.empty()) << text;
  }
}

// Routh's reduction, diff and another method work on equations written out in q: a tree, read
// from turns or written with joints, is derived for them written out
TEST(FrameJoints, RouthAndDiffTakeTheModelWrittenOut) {
  std::string path = write_model("turns", turns);
  Derivation tree = derive_model_file(path);
  ASSERT_TRUE(tree.diagnostics.empty()) << tree.diagnostics.format();
  EXPECT_FALSE(tree.equations->intermediates.empty()) << "derived as a tree";
  ModelChoice as_written;
  as_written.written_out = true;
  Derivation written = derive_model_file_for(path, as_written);
  ASSERT_TRUE(written.diagnostics.empty()) << written.diagnostics.format();
  EXPECT_TRUE(written.equations->intermediates.empty());
  // a spherical pendulum on a universal joint: its turn a about the vertical is cyclic
  std::string pendulum = write_model("pendulum", spherical_pendulum);
  Derivation reduced = derive_reduced_model_file(pendulum, {"a"});
  EXPECT_TRUE(reduced.diagnostics.empty()) << reduced.diagnostics.format();
  // and another method than the file's
  Derivation hamilton = derive_model_file_as(pendulum, "hamilton");
  EXPECT_TRUE(hamilton.diagnostics.empty()) << hamilton.diagnostics.format();
  // the same pendulum written with joints: the same written-out equations for all three
  std::string jointed = spherical_pendulum;
  auto replace = [&](const std::string& from, const std::string& to) { jointed.replace(jointed.find(from), from.size(), to); };
  replace("name = \"rod\"\nrotation = \"rot_z(a)*rot_x(b)\"",
          "name = \"rod_a\"\njoint = { type = \"revolute\", axis = [\"0\", \"0\", \"1\"], coordinate = \"a\" }\n\n[[frames]]\n"
          "name = \"swing\"\nparent = \"rod_a\"\njoint = { type = \"revolute\", axis = [\"1\", \"0\", \"0\"], coordinate = \"b\" }");
  replace("frame = \"rod\"", "frame = \"swing\"");
  std::string joints = write_model("pendulum", jointed);
  Derivation joint_tree = derive_model_file(joints);
  ASSERT_TRUE(joint_tree.diagnostics.empty()) << joint_tree.diagnostics.format();
  ASSERT_FALSE(joint_tree.equations->intermediates.empty()) << jointed;
  Derivation joints_written = derive_model_file_for(joints, as_written);
  ASSERT_TRUE(joints_written.diagnostics.empty()) << joints_written.diagnostics.format();
  EXPECT_TRUE(joints_written.equations->intermediates.empty());
  const Equations& by_joints = *joints_written.equations;
  Derivation rotations_written = derive_model_file_for(pendulum, as_written);
  ASSERT_TRUE(rotations_written.equations);
  const Equations& by_rotations = *rotations_written.equations;
  std::mt19937 random(9);
  for (int point = 0; point < 3; ++point) {
    std::map<std::string, double> values = random_point(by_joints, random);
    GiNaC::exmap at = point_by_name(by_joints, values), same = point_by_name(by_rotations, values);
    for (unsigned j = 0; j < 2; ++j) {
      EXPECT_NEAR(value_at(by_joints.forcing[j], at), value_at(by_rotations.forcing[j], same), 1e-12) << "f" << j;
      for (unsigned k = 0; k < 2; ++k)
        EXPECT_NEAR(value_at(by_joints.mass_matrix(j, k), at), value_at(by_rotations.mass_matrix(j, k), same), 1e-12);
    }
  }
  EXPECT_TRUE(derive_reduced_model_file(joints, {"a"}).diagnostics.empty());
  EXPECT_TRUE(derive_model_file_as(joints, "hamilton").diagnostics.empty());
}

}  // namespace
}  // namespace eomgen::test
