// Joints on frames (FrameEntry::joint): a revolute joint about a coordinate axis is rot_x,
// rot_y or rot_z of its coordinate; one about an oblique axis through an anchor gives the
// classical one-axis rotor, M = eᵀ·I_c·e + m·|e × (c − a)|², with the potential of its
// centre turned by Rodrigues' formula; a prismatic joint slides along its unit axis;
// rot_axis(x, y, z, φ) is Rodrigues' rotation; each misuse of a joint is located.
// (tests/crosscheck/mujoco_oracle_test.cpp holds a branched tree of them against MuJoCo.)
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>

#include <fmt/format.h>

#include "model/model.hpp"
#include "pipeline.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

using GiNaC::ex;

const char* one_joint_model = R"toml([model]
name = "joint"

[parameters]
m = 1.3
A = 0.2
B = 0.3
C = 0.45
g = 9.81

[coordinates]
q = 0.4

[gravity]
acceleration = ["0", "0", "-g"]
)toml";

std::string rotor(const std::string& frame) {
  return one_joint_model + std::string("\n[[frames]]\nname = \"arm\"\n") + frame +
         "\n\n[[rigid_bodies]]\nname = \"rotor\"\nmass = \"m\"\nframe = \"arm\"\ncenter = [\"0.3\", \"-0.1\", \"0.2\"]\n"
         "inertia = [\"A\", \"B\", \"C\"]\n";
}

// the two derivations of a model: "written out" in q, or as eomgen chooses ("tree": the frames
// read as joints)
const char* const derivations[] = {"written out", "tree"};
Equations derive_as(const std::string& derivation, const std::string& text) {
  return derive_text(text, "model.toml", model_written_out(derivation == "written out"));
}

// random values by name: parameters, coordinates and their rates
std::vector<std::map<std::string, double>> random_values(const Symbols& s, int count) {
  std::mt19937 random(17);
  std::uniform_real_distribution<double> angle(-2, 2), rate(-1.5, 1.5), scale(0.5, 2);
  std::vector<std::map<std::string, double>> points;
  for (int k = 0; k < count; ++k) {
    std::map<std::string, double> v{{"t", 0.0}};
    for (const std::string& p : s.parameter_names) v[p] = scale(random);
    for (const std::string& q : s.coordinate_names) v[q] = angle(random), v["der(" + q + ")"] = rate(random);
    points.push_back(v);
  }
  return points;
}

void expect_near(double x, double y, const std::string& what) {
  EXPECT_NEAR(x, y, 1e-12 * std::max({1.0, std::abs(x), std::abs(y)})) << what;
}

void same_equations(const Equations& a, const Equations& b, const std::string& what) {
  ASSERT_EQ(a.forcing.size(), b.forcing.size());
  for (const auto& values : random_values(a.symbols, 8)) {
    GiNaC::exmap at_a = point_by_name(a, values), at_b = point_by_name(b, values);
    expect_near(value_at(a.mass_matrix(0, 0), at_a), value_at(b.mass_matrix(0, 0), at_b), what + ": M");
    for (std::size_t j = 0; j < a.forcing.size(); ++j)
      expect_near(value_at(a.forcing[j], at_a), value_at(b.forcing[j], at_b), what + ": f");
  }
}

// M and f (with the rate zero: the potential's force alone) against closed forms in the model's symbols
void expect_closed_forms(const Equations& e, const std::string& mass, const std::string& static_force, const std::string& what) {
  for (auto values : random_values(e.symbols, 8)) {
    values["der(q)"] = 0;
    GiNaC::exmap at = point_by_name(e, values);
    expect_near(value_at(e.mass_matrix(0, 0), at), value_at(closed_form(e, mass), at), what + ": M");
    expect_near(value_at(e.forcing[0], at), value_at(closed_form(e, static_force), at), what + ": f");
  }
}

TEST(Joints, RevoluteAboutACoordinateAxisIsTheElementaryRotation) {
  for (const char* derivation : derivations) {
    Equations joint = derive_as(derivation, rotor("rotation = \"rot_x(0.5)\"\njoint = { type = \"revolute\", axis = [\"0\", \"-2\", \"0\"], coordinate = \"q\" }"));
    Equations product = derive_as(derivation, rotor("rotation = \"rot_x(0.5)*rot_y(-q)\""));
    same_equations(joint, product, derivation);
  }
}

TEST(Joints, RevoluteAboutAnObliqueAxisThroughAnAnchorIsTheOneAxisRotor) {
  // e = (1, 2, 2)/3, anchor a = (0.1, 0.2, −0.1), centre c = (0.3, −0.1, 0.2): d = c − a = (0.2, −0.3, 0.3),
  // e × d = (2·0.3 − 2·(−0.3), 2·0.2 − 1·0.3, 1·(−0.3) − 2·0.2)/3 = (1.2, 0.1, −0.7)/3,
  // |e × d|² = 1.94/9; eᵀ I e = (A + 4B + 4C)/9.
  // The centre's height: z = a_z + (R_e(q)·d)_z with R_e by Rodrigues' formula:
  // R·d = cos q·d + sin q·e × d + (1 − cos q)(e·d)e, e·d = 0.2/3,
  // so z = −0.1 + 0.3 cos q − 0.7/3 sin q + (1 − cos q)·0.4/9, and f = −m g dz/dq.
  for (const char* derivation : derivations) {
    Equations e = derive_as(derivation, rotor(
        "joint = { type = \"revolute\", axis = [\"1\", \"2\", \"2\"], anchor = [\"0.1\", \"0.2\", \"-0.1\"], coordinate = \"q\" }"));
    expect_closed_forms(e, "(A + 4*B + 4*C)/9 + m*1.94/9", "m*g*(0.3*sin(q) + 0.7/3*cos(q) - 0.4/9*sin(q))", derivation);
  }
}

TEST(Joints, PrismaticSlidesAlongItsUnitAxis) {
  for (const char* derivation : derivations) {
    // along (0, 3, 4)/5 in a frame turned by rot_x(0.5): height = 0.2 + q·(sin 0.5·3 + cos 0.5·4)/5
    Equations e = derive_as(derivation, rotor(
        "rotation = \"rot_x(0.5)\"\njoint = { type = \"prismatic\", axis = [\"0\", \"3\", \"4\"], coordinate = \"q\" }"));
    expect_closed_forms(e, "m", "-m*g*(3*sin(0.5) + 4*cos(0.5))/5", derivation);
  }
}

// a joint that follows q by m·q + c (URDF's mimic) is the rotor turned by that angle: with the
// oblique rotor above, angle θ = −2.5 q + 0.3 gives M = 6.25·M_θ and f = −2.5·f_θ(θ)
TEST(Joints, AJointThatFollowsACoordinateTurnsByItsMultipleAndOffset) {
  for (const char* derivation : derivations) {
    Equations e = derive_as(derivation, rotor(
        "joint = { type = \"revolute\", axis = [\"1\", \"2\", \"2\"], anchor = [\"0.1\", \"0.2\", \"-0.1\"], "
        "coordinate = \"q\", multiplier = -2.5, offset = \"0.3\" }"));
    expect_closed_forms(e, "6.25*((A + 4*B + 4*C)/9 + m*1.94/9)",
                        "-2.5*m*g*(0.3*sin(0.3 - 2.5*q) + 0.7/3*cos(0.3 - 2.5*q) - 0.4/9*sin(0.3 - 2.5*q))", derivation);
    Equations slide = derive_as(derivation, rotor(
        "rotation = \"rot_x(0.5)\"\njoint = { type = \"prismatic\", axis = [\"0\", \"3\", \"4\"], coordinate = \"q\", "
        "multiplier = \"B\", offset = -1 }"));
    expect_closed_forms(slide, "m*B^2", "-B*m*g*(3*sin(0.5) + 4*cos(0.5))/5", derivation);
  }
}

TEST(Joints, FixedJointKeepsThePlacement) {
  Equations fixed = derive_text(rotor("rotation = \"rot_z(q)\"\njoint = { type = \"fixed\" }"));
  Equations plain = derive_text(rotor("rotation = \"rot_z(q)\""));
  same_equations(fixed, plain, "fixed");
}

TEST(Joints, RotAxisIsRodriguesRotation) {
  ex phi = GiNaC::symbol("phi");
  ElementaryRotation along_z = turn_about({0, 0, 5}, phi);
  EXPECT_EQ(along_z.axis, 2);
  EXPECT_TRUE(along_z.angle.is_equal(phi));
  ElementaryRotation against_x = turn_about({-1, 0, 0}, phi);
  EXPECT_EQ(against_x.axis, 0);
  EXPECT_TRUE(against_x.angle.is_equal(-phi));
  ElementaryRotation oblique = turn_about({1, 2, 2}, phi);
  ASSERT_EQ(oblique.axis, ElementaryRotation::about_direction);
  GiNaC::matrix R = rotation_matrix(oblique);
  GiNaC::matrix e(3, 1, GiNaC::lst{1, 2, 2});
  GiNaC::matrix turned = R.mul(e);
  for (unsigned a = 0; a < 3; ++a) EXPECT_TRUE((turned(a, 0) - e(a, 0)).expand().is_zero()) << "the axis stays";
  GiNaC::matrix RtR = R.transpose().mul(R);
  for (unsigned a = 0; a < 3; ++a)
    for (unsigned b = 0; b < 3; ++b)
      EXPECT_TRUE((RtR(a, b) - (a == b ? 1 : 0)).expand().subs(pow(GiNaC::sin(phi), 2) == 1 - pow(GiNaC::cos(phi), 2)).expand().is_zero())
          << "RᵀR = I at " << a << b;
  // a quarter turn about e takes (2, −1, 0) ⊥ e to e × (2, −1, 0)/|…|·|…| = (2, 4, −5)/3
  GiNaC::matrix quarter = GiNaC::ex_to<GiNaC::matrix>(ex(R).subs(phi == GiNaC::Pi / 2).evalm());
  GiNaC::matrix v = quarter.mul(GiNaC::matrix(3, 1, GiNaC::lst{2, -1, 0}));
  EXPECT_TRUE((v(0, 0) - ex(2) / 3).is_zero() && (v(1, 0) - ex(4) / 3).is_zero() && (v(2, 0) + ex(5) / 3).is_zero()) << v;
  Equations by_rot_axis = derive_as("written out", rotor("rotation = \"rot_axis(1, 2, 2, q)\""));
  Equations by_joint = derive_as("written out", rotor("joint = { type = \"revolute\", axis = [\"1\", \"2\", \"2\"], coordinate = \"q\" }"));
  same_equations(by_rot_axis, by_joint, "rot_axis");
}

std::string joint_diagnostics(const std::string& text) { return derive_model_text(text, "bad.toml").diagnostics.format(); }

TEST(Joints, MisusesAreLocated) {
  auto with_joint = [](const std::string& joint) { return joint_diagnostics(rotor("joint = " + joint)); };
  std::string unknown = with_joint("{ type = \"revolute\", axis = [\"0\", \"0\", \"1\"], coordinate = \"p\" }");
  EXPECT_NE(unknown.find("bad.toml:19:68: error: frames[0].joint.coordinate: 'p' is not a coordinate"), std::string::npos) << unknown;
  std::string zero = with_joint("{ type = \"revolute\", axis = [\"0\", \"0\", \"0\"], coordinate = \"q\" }");
  EXPECT_NE(zero.find("frames[0].joint.axis: the joint's axis is zero"), std::string::npos) << zero;
  std::string kind = with_joint("{ type = \"hinge\", axis = [\"0\", \"0\", \"1\"], coordinate = \"q\" }");
  EXPECT_NE(kind.find("'hinge' is not a joint type"), std::string::npos) << kind;
  EXPECT_NE(kind.find("\"revolute\", \"prismatic\", \"ball\", \"free\" or \"fixed\""), std::string::npos) << kind;
  std::string no_axis = with_joint("{ type = \"prismatic\", coordinate = \"q\" }");
  EXPECT_NE(no_axis.find("a prismatic joint needs an axis"), std::string::npos) << no_axis;
  std::string anchored = with_joint("{ type = \"prismatic\", axis = [\"0\", \"0\", \"1\"], anchor = [\"0\", \"0\", \"1\"], coordinate = \"q\" }");
  EXPECT_NE(anchored.find("a prismatic joint has no anchor"), std::string::npos) << anchored;
  std::string moved = with_joint("{ type = \"fixed\", coordinate = \"q\" }");
  EXPECT_NE(moved.find("a fixed joint has no coordinate"), std::string::npos) << moved;
  std::string misspelt = with_joint("{ type = \"revolute\", axis = [\"0\", \"0\", \"1\"], coordinate = \"q\", anchr = [\"0\", \"0\", \"0\"] }");
  EXPECT_NE(misspelt.find("anchor"), std::string::npos) << misspelt;
  std::string still = with_joint("{ type = \"revolute\", axis = [\"0\", \"0\", \"1\"], coordinate = \"q\", multiplier = 0 }");
  EXPECT_NE(still.find("frames[0].joint.multiplier: the multiplier is zero: the joint would not move"), std::string::npos) << still;
  std::string moving = with_joint("{ type = \"revolute\", axis = [\"0\", \"0\", \"1\"], coordinate = \"q\", offset = \"q\" }");
  EXPECT_NE(moving.find("frames[0].joint.offset: coordinate 'q' in a joint's multiplier or offset"), std::string::npos) << moving;
  std::string fixed = with_joint("{ type = \"fixed\", multiplier = 2 }");
  EXPECT_NE(fixed.find("frames[0].joint.multiplier: a fixed joint has no multiplier"), std::string::npos) << fixed;
  std::string coupled = with_joint("{ type = \"revolute\", axis = [\"0\", \"0\", \"q\"], coordinate = \"q\" }");
  EXPECT_NE(coupled.find("frames[0].joint.axis"), std::string::npos) << "an axis is constant:\n" << coupled;
}

}  // namespace
}  // namespace eomgen::test
