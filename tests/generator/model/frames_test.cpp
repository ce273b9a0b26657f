// [[frames]] and [[points]]: a 3-D chain of rods with relative joint angles placed through
// frames derives to the same mass matrix and forcing as the same chain written out in
// full (each rod's rotation as a 3×3 matrix multiplied out here, its centre summed link by
// link), at random points, and so does it with recursive kinematics, whose expressions grow
// polynomially with the chain's length; a point's components and a point force follow the frame; a
// 3×3 matrix definition serves as a rotation, an inertia and by entry; and each misuse is located.
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <sstream>

#include <fmt/format.h>

#include "model/model_builder.hpp"
#include "pipeline.hpp"
#include "spatial/joint_tree_dynamics.hpp"
#include "support/expanded_oracle.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

using GiNaC::ex;

const char* header = R"toml([model]
name = "chain3d"

[parameters]
m = 1.2
l = 0.8
g = 9.81
F = 0.7

[gravity]
acceleration = ["0", "0", "-g"]
)toml";

std::string coordinates(int n) {
  std::string text = "\n[coordinates]\n";
  for (int i = 1; i <= n; ++i) text += fmt::format("a{0} = {1}\nb{0} = {2}\n", i, 0.1 * i, 0.3 - 0.05 * i);
  return text;
}

std::string rod(int i, const std::string& placement) {
  return fmt::format("\n[[rigid_bodies]]\nname = \"rod{}\"\nmass = \"m\"\n{}\ninertia = [\"m*l^2/12\", \"m*l^2/12\", \"m*l^2/200\"]\n",
                     i, placement);
}

std::string through_frames(int n) {
  std::string text = std::string(header) + coordinates(n);
  for (int i = 1; i <= n; ++i) {
    text += fmt::format("\n[[frames]]\nname = \"link{}\"\nrotation = \"rot_z(a{})*rot_x(b{})\"\n", i, i, i);
    if (i > 1) text += fmt::format("parent = \"link{}\"\norigin = [\"0\", \"0\", \"-l\"]\n", i - 1);
  }
  for (int i = 1; i <= n; ++i) text += rod(i, fmt::format("frame = \"link{}\"\ncenter = [\"0\", \"0\", \"-l/2\"]", i));
  text += fmt::format("\n[[points]]\nname = \"tip\"\nframe = \"link{}\"\nposition = [\"0\", \"0\", \"-l\"]\n", n);
  text += "\n[[forces]]\nat = \"tip\"\nforce = [\"F\", \"0\", \"0\"]\n\n[outputs]\ntip_height = \"tip.z\"\n";
  return text;
}

std::string printed(const ex& e) {
  std::ostringstream out;
  out << e;
  return out.str();
}

// the same chain with every rotation and position multiplied out by hand
std::string written_out(int n) {
  std::string text = std::string(header) + coordinates(n);
  GiNaC::symtab names;
  auto symbol = [&](const std::string& name) -> ex {
    if (!names.count(name)) names[name] = GiNaC::symbol(name);
    return names[name];
  };
  auto rot_x = [](const ex& a) { return GiNaC::matrix(3, 3, GiNaC::lst{1, 0, 0, 0, cos(a), -sin(a), 0, sin(a), cos(a)}); };
  auto rot_z = [](const ex& a) { return GiNaC::matrix(3, 3, GiNaC::lst{cos(a), -sin(a), 0, sin(a), cos(a), 0, 0, 0, 1}); };
  ex l = symbol("l");
  GiNaC::matrix R = GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(3)), joint(3, 1), tip(3, 1);
  for (int i = 1; i <= n; ++i) {
    R = R.mul(rot_z(symbol(fmt::format("a{}", i)))).mul(rot_x(symbol(fmt::format("b{}", i))));
    GiNaC::matrix half = R.mul(GiNaC::matrix(3, 1, GiNaC::lst{0, 0, -l / 2}));
    GiNaC::matrix full = R.mul(GiNaC::matrix(3, 1, GiNaC::lst{0, 0, -l}));
    std::string rows, center;
    for (unsigned r = 0; r < 3; ++r) {
      rows += "[";
      for (unsigned c = 0; c < 3; ++c) rows += fmt::format("\"{}\"{}", printed(R(r, c).expand()), c < 2 ? ", " : "");
      rows += r < 2 ? "], " : "]";
      center += fmt::format("\"{}\"{}", printed((joint(r, 0) + half(r, 0)).expand()), r < 2 ? ", " : "");
    }
    text += rod(i, fmt::format("center = [{}]\nrotation = [{}]", center, rows));
    tip = joint.add(full);
    joint = tip;
  }
  text += fmt::format("\n[[forces]]\nat = [\"{}\", \"{}\", \"{}\"]\nforce = [\"F\", \"0\", \"0\"]\n\n[outputs]\ntip_height = \"{}\"\n",
                      printed(tip(0, 0).expand()), printed(tip(1, 0).expand()), printed(tip(2, 0).expand()),
                      printed(tip(2, 0).expand()));
  return text;
}


// `e` of one model at a point of another, matched by the symbols' names, its intermediates (a
// tree's, when its frames read as joints) evaluated in order
double at_point_by_name(const ex& e, const Equations& of, const std::map<std::string, double>& values) {
  return value_at(e, test::point_by_name(of, values));
}

TEST(Frames, ChainThroughFramesEqualsTheChainWrittenOut) {
  for (int n : {1, 2, 3}) {
    Equations framed = test::derive_text(through_frames(n)), full = test::derive_text(written_out(n));
    ASSERT_EQ(framed.forcing.size(), std::size_t(2 * n));
    ASSERT_EQ(full.forcing.size(), std::size_t(2 * n));
    std::mt19937 random(7u + unsigned(n));
    std::uniform_real_distribution<double> angle(-2, 2), rate(-1.5, 1.5), scale(0.5, 2);
    for (int point = 0; point < 8; ++point) {
      std::map<std::string, double> values{{"t", 0.0}};
      for (const std::string& p : framed.symbols.parameter_names) values[p] = scale(random);
      for (const std::string& q : framed.symbols.coordinate_names) {
        values[q] = angle(random);
        values["der(" + q + ")"] = rate(random);
      }
      auto same = [&](const ex& a, const ex& b, const std::string& what) {
        double x = at_point_by_name(a, framed, values), y = at_point_by_name(b, full, values);
        EXPECT_NEAR(x, y, 1e-11 * std::max({1.0, std::abs(x), std::abs(y)})) << what << " of the " << n << "-link chain";
      };
      for (unsigned j = 0; j < 2u * unsigned(n); ++j) {
        same(framed.forcing[j], full.forcing[j], fmt::format("f[{}]", j));
        for (unsigned k = 0; k < 2u * unsigned(n); ++k)
          same(framed.mass_matrix(j, k), full.mass_matrix(j, k), fmt::format("M[{}][{}]", j, k));
      }
      same(framed.outputs.at(0).expression, full.outputs.at(0).expression, "the tip's height");
    }
  }
}

std::string misuse(const std::string& frames, const std::string& body) {
  return std::string(header) + "\n[coordinates]\nq = 0.1\n" + frames + body;
}

std::string diagnostics_of(const std::string& text) { return derive_model_text(text, "bad.toml").diagnostics.format(); }

TEST(Frames, MisusesAreLocated) {
  const std::string body = "\n[[rigid_bodies]]\nname = \"b\"\nmass = \"m\"\nframe = \"arm\"\ninertia = [\"1\", \"1\", \"1\"]\n";
  EXPECT_NE(diagnostics_of(misuse("", body)).find("'arm' is not a frame"), std::string::npos);
  std::string later = misuse("\n[[frames]]\nname = \"hand\"\nparent = \"arm\"\n\n[[frames]]\nname = \"arm\"\nrotation = \"rot_z(q)\"\n", body);
  EXPECT_NE(diagnostics_of(later).find("bad.toml:18:11: error: frames[0].parent: 'arm' is not a frame yet"), std::string::npos)
      << diagnostics_of(later);
  std::string scalar = misuse("\n[[frames]]\nname = \"arm\"\nrotation = \"rot_z(q)\"\n\n[[points]]\nname = \"P\"\nframe = \"arm\"\n"
                              "position = [\"l\", \"0\", \"0\"]\n\n[outputs]\nh = \"P + 1\"\n", body);
  EXPECT_NE(diagnostics_of(scalar).find("'P' is a vector, not a scalar"), std::string::npos) << diagnostics_of(scalar);
  EXPECT_NE(diagnostics_of(scalar).find("P.x, P.y, P.z"), std::string::npos);
  std::string twice = misuse("\n[[frames]]\nname = \"arm\"\n\n[[frames]]\nname = \"arm\"\n", body);
  EXPECT_NE(diagnostics_of(twice).find("two frames are named 'arm'"), std::string::npos);
}

TEST(Frames, VectorDefinitionsAreUsedByNameAndByComponent) {
  std::string text = std::string(header) + R"toml(
[coordinates]
q = 0.3

[definitions]
arm = ["l*sin(q)", "0", "-l*cos(q)"]
height = "arm.z"

[[particles]]
name = "bob"
mass = "m"
position = "arm"

[outputs]
h = "height"
)toml";
  Equations e = test::derive_text(text);
  auto points = random_points(e.symbols, 10);
  EXPECT_TRUE(agree_at_points(e.mass_matrix(0, 0), closed_form(e, "m*l^2"), points));
  EXPECT_TRUE(agree_at_points(e.forcing[0], closed_form(e, "-m*g*l*sin(q)"), points));
  EXPECT_TRUE(agree_at_points(e.outputs.at(0).expression, closed_form(e, "-l*cos(q)"), points));

  std::string misspelt = text;
  misspelt.replace(misspelt.find("position = \"arm\""), 16, "position = \"amr\"");
  std::string said = diagnostics_of(misspelt);
  EXPECT_NE(said.find("particles[0].position: 'amr' is not a vector or a point"), std::string::npos) << said;
  EXPECT_NE(said.find("arm"), std::string::npos) << "the hint names the vector there is";
  EXPECT_EQ(said.find("amr.x"), std::string::npos) << "one error, not one per component:\n" << said;
}

// a top on a frame rotated by rot_z(a)*rot_x(b), with a tensor of inertia that has a product term
std::string top(const std::string& definitions, const std::string& rotation, const std::string& inertia) {
  return std::string(header) + "\n[coordinates]\na = 0.3\nb = 0.4\n" + definitions +
         "\n[[frames]]\nname = \"arm\"\nrotation = " + rotation +
         "\n\n[[rigid_bodies]]\nname = \"top\"\nmass = \"m\"\nframe = \"arm\"\ncenter = [\"0\", \"0\", \"-l\"]\ninertia = " +
         inertia + "\n\n[outputs]\nh = \"cos(b)\"\n";
}

TEST(Frames, MatrixDefinitionsServeAsRotationInertiaAndByEntry) {
  const std::string definitions = R"toml(
[definitions]
R = [["cos(a)", "-sin(a)*cos(b)", "sin(a)*sin(b)"], ["sin(a)", "cos(a)*cos(b)", "-cos(a)*sin(b)"], ["0", "sin(b)", "cos(b)"]]
I = [["m*l^2/3", "0", "-m*l^2/20"], ["0", "m*l^2/4", "0"], ["-m*l^2/20", "0", "m*l^2/6"]]
tilt = "R.zz"
)toml";
  std::string named = top(definitions, "\"R\"", "\"I\"");
  named.replace(named.find("h = \"cos(b)\""), 12, "h = \"tilt\"");
  Equations by_name = test::derive_text(named);
  Equations written = test::derive_text(top("", "\"rot_z(a)*rot_x(b)\"",
                                      R"([["m*l^2/3", "0", "-m*l^2/20"], ["0", "m*l^2/4", "0"], ["-m*l^2/20", "0", "m*l^2/6"]])"));
  ASSERT_EQ(by_name.forcing.size(), 2u);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> angle(-2, 2), rate(-1.5, 1.5), scale(0.5, 2);
  for (int point = 0; point < 8; ++point) {
    std::map<std::string, double> values{{"t", 0.0}};
    for (const std::string& p : by_name.symbols.parameter_names) values[p] = scale(random);
    for (const std::string& q : by_name.symbols.coordinate_names) {
      values[q] = angle(random);
      values["der(" + q + ")"] = rate(random);
    }
    auto same = [&](const ex& x, const ex& y, const std::string& what) {
      double u = at_point_by_name(x, by_name, values), v = at_point_by_name(y, written, values);
      EXPECT_NEAR(u, v, 1e-12 * std::max({1.0, std::abs(u), std::abs(v)})) << what;
    };
    for (unsigned j = 0; j < 2; ++j) {
      same(by_name.forcing[j], written.forcing[j], fmt::format("f[{}]", j));
      for (unsigned k = 0; k < 2; ++k) same(by_name.mass_matrix(j, k), written.mass_matrix(j, k), fmt::format("M[{}][{}]", j, k));
    }
    same(by_name.outputs.at(0).expression, written.outputs.at(0).expression, "R.zz");
  }
  // the product of inertia reaches the equations: without it M[0][1] (I_xz a' b' cos b) differs
  Equations diagonal = test::derive_text(top("", "\"rot_z(a)*rot_x(b)\"", R"(["m*l^2/3", "m*l^2/4", "m*l^2/6"])"));
  double largest_change = 0;
  for (int point = 0; point < 4; ++point) {
    std::map<std::string, double> values{{"t", 0.0}, {"m", 1.3}, {"l", 0.7}, {"g", 9.81}, {"F", 0.7}};
    for (const std::string& q : diagonal.symbols.coordinate_names) values[q] = angle(random), values["der(" + q + ")"] = rate(random);
    largest_change = std::max(largest_change, std::abs(at_point_by_name(diagonal.mass_matrix(0, 1), diagonal, values) -
                                                       at_point_by_name(written.mass_matrix(0, 1), written, values)));
  }
  EXPECT_GT(largest_change, 1e-3);

  std::string as_scalar = named;
  as_scalar.replace(as_scalar.find("h = \"tilt\""), 10, "h = \"R + 1\"");
  EXPECT_NE(diagnostics_of(as_scalar).find("'R' is a 3x3 matrix, not a scalar"), std::string::npos) << diagnostics_of(as_scalar);
  EXPECT_NE(diagnostics_of(as_scalar).find("R.xx, R.xy"), std::string::npos);
  std::string unknown = top(definitions, "\"R\"", "\"J\"");
  EXPECT_NE(diagnostics_of(unknown).find("inertia: 'J' is not a 3x3 matrix under [definitions]"), std::string::npos)
      << diagnostics_of(unknown);
  EXPECT_EQ(diagnostics_of(unknown).find("J.xx"), std::string::npos) << "one error, not one per entry";
  std::string not_orthogonal = named;
  const std::string last_row = R"x(["0", "sin(b)", "cos(b)"])x";
  not_orthogonal.replace(not_orthogonal.find(last_row), last_row.size(), R"x(["0", "sin(b)", "2*cos(b)"])x");
  EXPECT_NE(diagnostics_of(not_orthogonal).find("not orthogonal"), std::string::npos) << diagnostics_of(not_orthogonal);
}

// The chain's frames composed link by link (kinematics/recursive_kinematics.hpp), as build_model()
// derives a deep chain of frames that is no tree of joints: these frames read as joints, which
// build_model() would take as a tree, so the builder is told. The diagnostics of building and
// deriving it, and the equations when there are none.
std::string composed_diagnostics(const std::string& text, std::optional<Equations>* equations = nullptr) {
  Diagnostics d;
  ModelFile file = parse_model_text(text, "bad.toml", d);
  Model model = ModelBuilder(file, d, ModelBuilder::FrameReading::composed).build();
  if (!d.empty()) return d.format();
  std::optional<Equations> e = derive_built_model(model, {"bad.toml", 1, 1}, d);
  if (equations) *equations = std::move(e);
  return d.format();
}
Equations derive_composed(const std::string& text) {
  std::optional<Equations> e;
  std::string diagnostics = composed_diagnostics(text, &e);
  if (!e) throw std::runtime_error(diagnostics);
  return *e;
}

// the point with the intermediates of recursive kinematics added, each from its definition, in order
TEST(Frames, RecursiveKinematicsGivesTheEquationsOfTheChainWrittenOut) {
  for (int n : {1, 2, 3}) {
    Equations framed = derive_composed(through_frames(n)), full = test::derive_text(written_out(n));
    ASSERT_FALSE(framed.intermediates.empty());
    std::mt19937 random(11u + unsigned(n));
    std::uniform_real_distribution<double> angle(-2, 2), rate(-1.5, 1.5), scale(0.5, 2);
    for (int point = 0; point < 8; ++point) {
      std::map<std::string, double> values{{"t", 0.0}};
      for (const std::string& p : framed.symbols.parameter_names) values[p] = scale(random);
      for (const std::string& q : framed.symbols.coordinate_names) {
        values[q] = angle(random);
        values["der(" + q + ")"] = rate(random);
      }
      GiNaC::exmap at = point_by_name(framed, values);
      auto same = [&](const ex& a, const ex& b, const std::string& what) {
        double x = value_at(a, at), y = at_point_by_name(b, full, values);
        EXPECT_NEAR(x, y, 1e-11 * std::max({1.0, std::abs(x), std::abs(y)})) << what << " of the " << n << "-link chain";
      };
      for (unsigned j = 0; j < 2u * unsigned(n); ++j) {
        same(framed.forcing[j], full.forcing[j], fmt::format("f[{}]", j));
        for (unsigned k = 0; k < 2u * unsigned(n); ++k)
          same(framed.mass_matrix(j, k), full.mass_matrix(j, k), fmt::format("M[{}][{}]", j, k));
      }
      same(framed.outputs.at(0).expression, full.outputs.at(0).expression, "the tip's height");
      same(framed.kinetic_energy, full.kinetic_energy, "T");
      same(framed.potential_energy, full.potential_energy, "V");
    }
  }
}

// the printed size of what recursive kinematics derives: intermediates, M and f
std::size_t derived_size(const Equations& e) {
  std::size_t size = 0;
  for (const Intermediate& i : e.intermediates) size += printed(i.definition).size();
  for (unsigned j = 0; j < e.forcing.size(); ++j) {
    size += printed(e.forcing[j]).size();
    for (unsigned k = 0; k < e.forcing.size(); ++k) size += printed(e.mass_matrix(j, k)).size();
  }
  return size;
}

// Multiplied out, the entries of n rotations have up to 4^n terms (the written-out chain's
// derivation took 0.13 s at n = 2, 2.1 s at 3 and 89 s at 4); recursively, M has n² entries of
// O(n) products: doubling the chain multiplies the size by about 2³, far from 4⁴ = 256.
TEST(Frames, RecursiveKinematicsGrowsPolynomiallyWithTheChain) {
  std::size_t four = derived_size(derive_composed(through_frames(4)));
  std::size_t eight = derived_size(derive_composed(through_frames(8)));
  double growth = double(eight) / double(four);
  EXPECT_GT(growth, 2.0);
  EXPECT_LT(growth, 10.0) << four << " characters at n = 4, " << eight << " at n = 8";
}

// A joint about an oblique axis through an anchor turns its frame by E = a + b cos q + c sin q and
// moves its origin by r alike: both are named, so that each entry of the world pose is three products
// of named entries (R = R_p E, o = o_p + R_p r), not the expansion of all of them.
TEST(Frames, ObliqueJointsComposeNamedRelativePoses) {
  Equations e = test::derive_text(R"toml([model]
name = "oblique"

[coordinates]
a = 0.1
b = 0.2

[[frames]]
name = "base"
joint = { type = "revolute", axis = ["1", "2", "2"], anchor = ["0.1", "0", "0"], coordinate = "a" }

[[frames]]
name = "arm"
parent = "base"
origin = ["0", "0", "0.3"]
joint = { type = "revolute", axis = ["2", "-1", "2"], anchor = ["0", "0.05", "0"], coordinate = "b" }

[[rigid_bodies]]
name = "link"
mass = "1"
frame = "arm"
center = ["0.1", "0", "0"]
inertia = ["0.01", "0.02", "0.03"]
)toml");
  std::map<std::string, ex> definition;
  for (const Intermediate& i : e.intermediates) definition[i.symbol.get_name()] = i.definition;
  for (const char* axes : {"xx", "xy", "xz", "yx", "yy", "yz", "zx", "zy", "zz"}) {
    ASSERT_TRUE(definition.count(fmt::format("arm.E_{}", axes))) << axes;
    ex R = definition.at(fmt::format("arm.R_{}", axes));
    EXPECT_LE(R.nops(), 3u) << "arm.R_" << axes << " = " << R;
  }
  for (const char* axis : {"x", "y", "z"}) {
    ex o = definition.at(fmt::format("arm.o_{}", axis));
    EXPECT_LE(o.nops(), 4u) << "arm.o_" << axis << " = " << o;
  }
}

TEST(Frames, RecursiveKinematicsMisusesAreLocated) {
  std::string chain = through_frames(2);
  std::string appell = chain;
  appell.insert(appell.find("name = \"chain3d\""), "method = \"appell\"\n");
  EXPECT_NE(composed_diagnostics(appell).find("give Lagrange's equations of the second kind or of the first kind only"),
            std::string::npos)
      << composed_diagnostics(appell);
  std::string moving = chain;
  moving.replace(moving.find("rot_z(a1)"), 9, "rot_z(a1 + t)");
  EXPECT_NE(composed_diagnostics(moving).find("frame 'link1' moves with time t itself"), std::string::npos)
      << composed_diagnostics(moving);
  EXPECT_EQ(diagnostics_of(moving), "") << "build_model() writes it out in q";
  std::string through_point = chain + "\n[[particles]]\nname = \"bob\"\nmass = \"m\"\nposition = \"tip\"\n";
  EXPECT_NE(composed_diagnostics(through_point).find("a body is placed in a frame, not through a point of one"),
            std::string::npos)
      << composed_diagnostics(through_point);
  std::string sliding = chain;
  const std::string centre = "[\"0\", \"0\", \"-l/2\"]";
  sliding.replace(sliding.find(centre), centre.size(), "[\"t\", \"0\", \"-l/2\"]");
  EXPECT_NE(composed_diagnostics(sliding).find("a body in a frame moves with the coordinates alone, not with t"),
            std::string::npos)
      << composed_diagnostics(sliding);
}

// A chain of frames that is no tree of joints (each frame swings about y, and its origin slides
// out as it swings, which no joint does) is composed link by link from 4 moving frames on, the
// equations of the same model written out in q; a shorter one is written out
TEST(Frames, DeepChainsThatAreNoTreeOfJointsAreComposed) {
  auto telescoping = [](int n) {
    std::string text = std::string(header) + "\n[coordinates]\n";
    for (int i = 1; i <= n; ++i) text += fmt::format("a{} = 0.{}\n", i, i);
    for (int i = 1; i <= n; ++i) {
      text += fmt::format("\n[[frames]]\nname = \"link{}\"\nrotation = \"rot_y(a{})\"\n", i, i);
      if (i > 1) text += fmt::format("parent = \"link{}\"\norigin = [\"0\", \"0\", \"-l*(1 + sin(a{})/5)\"]\n", i - 1, i);
    }
    for (int i = 1; i <= n; ++i) text += rod(i, fmt::format("frame = \"link{}\"\ncenter = [\"0\", \"0\", \"-l/2\"]", i));
    return text;
  };
  EXPECT_FALSE(test::built(telescoping(3)).recursive_kinematics);
  EXPECT_TRUE(test::built(through_frames(3)).recursive_kinematics) << "its frames read as joints";
  Model four = test::built(telescoping(4));
  ASSERT_TRUE(four.recursive_kinematics);
  EXPECT_TRUE(why_not_a_joint_tree(four)) << "composed, not a tree of joints";
  Equations composed = test::derive_text(telescoping(4)), full = test::derive_text(telescoping(4), "model.toml", model_written_out());
  ASSERT_FALSE(composed.intermediates.empty());
  ASSERT_TRUE(full.intermediates.empty());
  std::mt19937 random(5);
  std::uniform_real_distribution<double> angle(-2, 2), rate(-1.5, 1.5);
  for (int point = 0; point < 4; ++point) {
    std::map<std::string, double> values{{"t", 0.0}, {"m", 1.2}, {"l", 0.8}, {"g", 9.81}, {"F", 0.7}};
    for (const std::string& q : composed.symbols.coordinate_names) values[q] = angle(random), values["der(" + q + ")"] = rate(random);
    GiNaC::exmap at = point_by_name(composed, values), written = point_by_name(full, values);
    for (unsigned j = 0; j < 4; ++j) {
      double f = value_at(full.forcing[j], written);
      EXPECT_NEAR(value_at(composed.forcing[j], at), f, 1e-11 * std::max(1.0, std::abs(f))) << "f[" << j << "]";
      for (unsigned k = 0; k < 4; ++k) {
        double M = value_at(full.mass_matrix(j, k), written);
        EXPECT_NEAR(value_at(composed.mass_matrix(j, k), at), M, 1e-11 * std::max(1.0, std::abs(M))) << "M[" << j << "][" << k << "]";
      }
    }
  }
}

// a shape's rotation (its axes in its body's, after a capsule's axis) and the ellipsoid reach the
// drawing as written: rot_x(a) with a a parameter, and quat(w, x, y, z) as the frames take it
TEST(Frames, ShapesAreTurnedByTheirRotation) {
  Equations e = derive_text(R"toml(
[model]
name = "turned_shapes"
[parameters]
a = 0.3
[coordinates]
q = 0.1
[[frames]]
name = "link"
joint = { type = "revolute", axis = ["0", "0", "1"], coordinate = "q" }
shape = [{ type = "box", size = ["0.1", "0.2", "0.3"], rotation = "rot_x(a)" },
         { type = "ellipsoid", size = ["0.1", "0.2", "0.3"], offset = ["0", "0", "0.5"], rotation = "quat(0.5, 0.5, 0.5, 0.5)" }]
[[rigid_bodies]]
name = "body"
frame = "link"
mass = "1"
inertia = ["0.1", "0.1", "0.1"]
)toml");
  const DrawnBody* link = nullptr;
  for (const DrawnBody& d : e.drawing)
    if (d.name == "link") link = &d;
  ASSERT_NE(link, nullptr);
  ASSERT_EQ(link->shapes.size(), 2u);
  GiNaC::exmap at = point_by_name(e, {{"a", 0.3}, {"q", 0.1}, {"der(q)", 0}});
  const double c = std::cos(0.3), s = std::sin(0.3);
  const double turned[9] = {1, 0, 0, 0, c, -s, 0, s, c};
  for (unsigned i = 0; i < 9; ++i) EXPECT_NEAR(value_at(link->shapes[0].rotation.op(i), at), turned[i], 1e-15) << i;
  EXPECT_EQ(link->shapes[1].type, Shape::Type::ellipsoid);
  // quat(½, ½, ½, ½) turns x to y, y to z, z to x: its columns are e_y, e_z, e_x
  const double cycled[9] = {0, 0, 1, 1, 0, 0, 0, 1, 0};
  for (unsigned i = 0; i < 9; ++i) EXPECT_NEAR(value_at(link->shapes[1].rotation.op(i), at), cycled[i], 1e-15) << i;
}

}  // namespace
}  // namespace eomgen::test
