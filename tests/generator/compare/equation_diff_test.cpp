// Comparing derivations without the command line: the levels that decide each entry,
// renamed symbols, changed defaults, and the same motion from two derivation methods.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>

#include "compare/diff_report.hpp"
#include "compare/equation_diff.hpp"
#include "support/test_support.hpp"

namespace eomgen {
namespace {

const char* const pendulum_by_energy = R"toml(
[model]
name = "pendulum"
title = "the pendulum by its energies"
[parameters]
m = 1.0
l = 1.0
g = 9.81
d = 0.0
[coordinates]
phi = { initial = 0.5, rate = 0.0 }
[energy]
kinetic = "m*l^2*der(phi)^2/2"
potential = "POTENTIAL"
dissipation = "d*der(phi)^2/2"
)toml";

std::string write(const std::string& name, std::string text, const std::string& from = "", const std::string& to = "") {
  if (!from.empty()) text.replace(text.find(from), from.size(), to);
  std::string path = test::temporary_directory() + "/" + name + ".toml";
  std::ofstream(path) << text;
  return path;
}

std::string pendulum_file() { return test::read_file(test::model_path("pendulum")); }

EquationDiff compare(const std::string& old_path, const std::string& new_path, DiffOptions options = {}) {
  Diagnostics d;
  auto a = read_derivation(old_path, d), b = read_derivation(new_path, d);
  EXPECT_TRUE(d.empty()) << d.format();
  if (!a || !b) return {};
  EquationDiff out = compare_derivations(*a, *b, options, d);
  EXPECT_TRUE(d.empty()) << d.format();
  return out;
}

const EntryComparison* entry(const EquationDiff& d, const std::string& name) {
  for (const EntryComparison& c : d.entries)
    if (c.entry == name) return &c;
  return nullptr;
}

TEST(EquationDiff, TheSameSystemWrittenThreeOtherWays) {
  std::string original = test::model_path("pendulum");
  // the energies instead of a particle in gravity
  EquationDiff energy = compare(original, write("energy", pendulum_by_energy, "POTENTIAL", "-m*g*l*cos(phi)"));
  EXPECT_EQ(energy.verdict, "identical");
  // terms reordered
  EquationDiff reordered = compare(original, write("reordered", pendulum_by_energy, "POTENTIAL", "-cos(phi)*l*g*m + 0"));
  EXPECT_EQ(reordered.verdict, "identical");
  // sin(phi) through the double-angle identity: equal only by trigonometry, decided numerically
  EquationDiff identity = compare(original, write("identity", pendulum_file(), "\"l*sin(phi)\"", "\"2*l*sin(phi/2)*cos(phi/2)\""));
  EXPECT_EQ(identity.verdict, "equivalent");
  const EntryComparison* m = entry(identity, "M[0][0]");
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->status, "equivalent");
  EXPECT_EQ(m->decided_by, "numeric");
  EXPECT_EQ(entry(identity, "V")->decided_by, "text");
}

TEST(EquationDiff, OneChangedCoefficientNamesExactlyTheEntriesItChanges) {
  EquationDiff d = compare(write("before", pendulum_by_energy, "POTENTIAL", "-m*g*l*cos(phi)"),
                           write("after", pendulum_by_energy, "POTENTIAL", "-1.5*m*g*l*cos(phi)"));
  EXPECT_EQ(d.verdict, "different");
  std::vector<std::string> changed;
  for (const EntryComparison& c : d.entries)
    if (c.status == "different") changed.push_back(c.entry);
  EXPECT_EQ(changed, (std::vector<std::string>{"f[0]", "V"}));
  const EntryComparison* v = entry(d, "V");
  EXPECT_GT(v->max_abs_difference, 0);
  EXPECT_EQ(v->old_text, "-g*l*m*cos(phi)");
  EXPECT_EQ(v->new_text, "-3*g*l*m*cos(phi)/2");
}

TEST(EquationDiff, RenamedParameterAddedOutputChangedDefault) {
  std::string original = test::model_path("pendulum");
  std::string renamed = write("renamed", pendulum_file(), "mass     = \"m\"", "mass     = \"bob_mass\"");
  std::string text = test::read_file(renamed);
  text.replace(text.find("\nm = 1.0"), 8, "\nbob_mass = 1.0");
  std::ofstream(renamed) << text;
  EXPECT_EQ(compare(original, renamed).verdict, "different") << "without --rename, m was removed and bob_mass added";
  DiffOptions options;
  options.renames = {{"m", "bob_mass"}};
  EquationDiff with_rename = compare(original, renamed, options);
  EXPECT_EQ(with_rename.verdict, "identical");
  ASSERT_EQ(with_rename.renamed.size(), 1u);
  EquationDiff output = compare(original, write("output", pendulum_file() + "\n[outputs]\nbob_x = \"l*sin(phi)\"\n"));
  EXPECT_EQ(output.verdict, "different");
  EXPECT_EQ(output.added, (std::vector<std::string>{"output bob_x"}));
  EquationDiff g = compare(original, write("gravity", pendulum_file(), "g = 9.81", "g = 9.80665"));
  EXPECT_EQ(g.verdict, "different");
  ASSERT_EQ(g.defaults_changed.size(), 1u);
  EXPECT_EQ(g.defaults_changed[0].name, "g");
  EXPECT_EQ(g.defaults_changed[0].new_value, 9.80665);
}

TEST(EquationDiff, LagrangeTwoAgainstAppellIsTheSameMotion) {
  // Appell's equations in the pseudo-velocity w = l der(phi): M and f are scaled, q'' is the same
  std::string appell = write("appell", pendulum_file() + "\n[pseudo_velocities]\nw = \"l*der(phi)\"\n", "title = ",
                             "method = \"appell\"\ntitle = ");
  EquationDiff d = compare(test::model_path("pendulum"), appell);
  EXPECT_EQ(d.verdict, "same_motion") << d.motion;
  EXPECT_EQ(entry(d, "M[0][0]")->status, "different");
  // and a different system in Appell's form is not
  std::string heavier = write("heavier", pendulum_file() + "\n[pseudo_velocities]\nw = \"l*der(phi)\"\n", "title = ",
                              "method = \"appell\"\ntitle = ");
  std::string text = test::read_file(heavier);
  text.replace(text.find("g = 9.81"), 8, "g = 9.81\nk = 2.0");
  text.replace(text.find("dissipation = "), 14, "potential = \"k*phi^2/2\"\ndissipation = ");
  std::ofstream(heavier) << text;
  EXPECT_EQ(compare(test::model_path("pendulum"), heavier).verdict, "different");
}

TEST(EquationDiff, ALagrangianTimesAConstantIsTheSameMotion) {
  // L and R doubled: M, f, T, V and R all double, the accelerations do not change
  std::string once = write("once", pendulum_by_energy, "POTENTIAL", "-m*g*l*cos(phi)");
  std::string doubled_text = pendulum_by_energy;
  doubled_text.replace(doubled_text.find("m*l^2*der(phi)^2/2"), 18, "m*l^2*der(phi)^2");
  doubled_text.replace(doubled_text.find("d*der(phi)^2/2"), 14, "d*der(phi)^2");
  std::string doubled = write("doubled", doubled_text, "POTENTIAL", "-2*m*g*l*cos(phi)");
  EquationDiff d = compare(once, doubled);
  EXPECT_EQ(d.verdict, "same_motion") << d.motion;
  EXPECT_EQ(entry(d, "V")->status, "different");
  // a potential changed by more than a factor is not
  EXPECT_EQ(compare(once, write("steeper", pendulum_by_energy, "POTENTIAL", "-2*m*g*l*cos(phi)")).verdict, "different");
}

// equations that agree where they were sampled are not the same where they are not
TEST(EquationDiff, BranchesAreNotTrustedToASampleBox) {
  std::string original = test::model_path("pendulum");
  // −l·√(1 − sin²φ) is −l·|cos φ|: different once cos φ < 0 is sampled
  std::string rooted = write("rooted", pendulum_file(), "\"-l*cos(phi)\"", "\"-l*sqrt(1 - sin(phi)^2)\"");
  EXPECT_EQ(compare(original, rooted).verdict, "different");
  // x³ against |x|³ in a potential: different for x < 0
  std::string cubic = write("cubic", pendulum_by_energy, "POTENTIAL", "m*g*l*phi^3");
  std::string absolute = write("absolute", pendulum_by_energy, "POTENTIAL", "m*g*l*abs(phi)^3");
  EXPECT_EQ(compare(cubic, absolute).verdict, "different");
  // √(x²)·x² against |x|³ agree everywhere, but a branch only sampled is not shown to be equal
  std::string root_form = write("root_form", pendulum_by_energy, "POTENTIAL", "m*g*l*sqrt(phi^2)*phi^2");
  EquationDiff sampled = compare(absolute, root_form);
  EXPECT_EQ(sampled.verdict, "equal_on_samples");
  EXPECT_EQ(entry(sampled, "V")->decided_by, "numeric on the samples");
}

TEST(EquationDiff, EveryCommittedBaselineIsIdenticalToItsModel) {
  for (const char* name : {"pendulum", "double_pendulum", "rolling_disk", "slider_crank", "heavy_symmetric_top", "mathieu"}) {
    EquationDiff d = compare(std::string(EOMGEN_SOURCE_DIR) + "/generated/" + name + ".json", test::model_path(name));
    EXPECT_EQ(d.verdict, "identical") << name;
    EXPECT_FALSE(d.entries.empty()) << name;
  }
}

// A tree's baseline holds its quantities (generated/ is the default derivation). A model of more than
// 4 velocities, or of ball and free joints, is compared in them too, and is identical to its
// baseline (oblique_tree's 5 joints written out had run past the 300 s limit); a smaller one is
// written out, equal to its baseline at every random point.
TEST(EquationDiff, TreesAreComparedWithTheirBaselinesInTheirQuantities) {
  for (const char* name : {"oblique_tree", "ball_joint_top", "tumbling_body"}) {
    EquationDiff d = compare(std::string(EOMGEN_SOURCE_DIR) + "/generated/" + name + ".json", test::model_path(name));
    EXPECT_EQ(d.verdict, "identical") << name;
    EXPECT_FALSE(d.entries.empty()) << name;
  }
  for (const char* name : {"measured_arm", "spatial_double_pendulum", "four_bar_linkage"}) {
    EquationDiff d = compare(std::string(EOMGEN_SOURCE_DIR) + "/generated/" + name + ".json", test::model_path(name));
    EXPECT_EQ(d.verdict, "equivalent") << name;
    for (const EntryComparison& c : d.entries) EXPECT_NE(c.decided_by, "text") << name << " " << c.entry;
  }
}

// A robot on a free joint (pseudo-velocities, a quaternion): one thigh 10 g heavier changes the
// entries that its leg moves, and the first quantity that differs is that thigh's
TEST(EquationDiff, ARobotOnAFreeJointIsComparedInItsQuantities) {
  std::string quadruped = std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/mjcf/quadruped.xml";
  std::string text = test::read_file(quadruped), heavier = test::temporary_directory() + "/heavier_thigh.xml";
  ASSERT_NE(text.find("mass=\"0.386\""), std::string::npos);
  text.replace(text.find("mass=\"0.386\""), 13, "mass=\"0.396\"");
  std::ofstream(heavier) << text;
  EquationDiff d = compare(quadruped, heavier);
  EXPECT_EQ(d.verdict, "different");
  ASSERT_FALSE(d.intermediates_changed.empty());
  EXPECT_EQ(d.intermediates_changed.front().name.rfind("front_left_thigh.", 0), 0u) << d.intermediates_changed.front().name;
  int different = 0, equivalent = 0;
  for (const EntryComparison& c : d.entries) different += c.status == "different", equivalent += c.status == "equivalent";
  EXPECT_GT(different, 0);
  EXPECT_GT(equivalent, 0);  // the other legs' own rows
}

// robot files are compared as `eomgen import` reads them, as every command takes them: the same
// URDF in another file is identical, and the fore link 0.1 kg heavier changes M, f and V
TEST(EquationDiff, RobotFilesAreComparedAsTheImportReadsThem) {
  std::string original = std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/urdf/two_link_arm.urdf";
  std::string arm = test::read_file(original), dir = test::temporary_directory();
  std::ofstream(dir + "/same_arm.urdf") << arm;
  std::string heavier = arm;
  heavier.replace(heavier.find("<mass value=\"0.8\"/>"), 19, "<mass value=\"0.9\"/>");
  std::ofstream(dir + "/heavier_arm.urdf") << heavier;
  EXPECT_EQ(compare(original, dir + "/same_arm.urdf").verdict, "identical");
  EquationDiff changed = compare(original, dir + "/heavier_arm.urdf");
  EXPECT_EQ(changed.verdict, "different");
  ASSERT_NE(entry(changed, "V"), nullptr);
  EXPECT_EQ(entry(changed, "V")->status, "different");
  ASSERT_NE(entry(changed, "M[0][0]"), nullptr);
  EXPECT_EQ(entry(changed, "M[0][0]")->status, "different");
}

std::string robot_variant(const std::string& file, const std::string& from, const std::string& to, const std::string& name) {
  std::string text = test::read_file(std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/urdf/" + file);
  std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  std::string path = test::temporary_directory() + "/" + name + ".urdf";
  std::ofstream(path) << text;
  return path;
}

// A robot of more than 4 velocities is compared in its tree's quantities (written out, the
// seven-joint arm's took a minute a side and thousands of terms an entry): the entries at random
// points, each side's quantities evaluated in order, and the quantities whose definitions differ
// listed by name, the first of them at the link that changed. Its first link's inertia turned by
// 0.1 rad about x changes M and f.
TEST(EquationDiff, RobotsAreComparedInTheirTreesQuantities) {
  std::string arm = std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/urdf/seven_joint_arm.urdf";
  std::string turned = robot_variant("seven_joint_arm.urdf", "rpy=\"0 0 0\"", "rpy=\"0.1 0 0\"", "turned_arm");
  EquationDiff d = compare(arm, turned);
  EXPECT_EQ(d.verdict, "different");
  ASSERT_NE(entry(d, "M[0][0]"), nullptr);
  EXPECT_EQ(entry(d, "M[0][0]")->status, "different");
  EXPECT_EQ(entry(d, "M[0][0]")->decided_by, "numeric");
  EXPECT_GT(entry(d, "M[0][0]")->max_rel_difference, 1e-4);
  ASSERT_FALSE(d.intermediates_changed.empty());
  EXPECT_EQ(d.intermediates_changed.front().name.rfind("link1.", 0), 0u) << d.intermediates_changed.front().name;
  EXPECT_NE(d.motion.find("differ"), std::string::npos) << d.motion;
  // the report stays readable: no line of thousands of characters, no rationals of 60 digits
  std::string report = diff_text(d);
  EXPECT_NE(report.find("the tree's quantities that differ"), std::string::npos);
  std::size_t longest = 0;
  for (std::size_t start = 0, end; start < report.size(); start = end + 1) {
    end = report.find('\n', start);
    if (end == std::string::npos) end = report.size();
    longest = std::max(longest, end - start);
  }
  EXPECT_LT(longest, 1300u);
  EXPECT_FALSE(std::regex_search(report, std::regex("[0-9]{30}/|/[0-9]{30}")));
  EXPECT_EQ(compare(arm, arm).verdict, "identical");
}

// The first link's inertia turned by a whole turn (2π in 16 digits): the same robot to the file's
// rounding (1e-18 of M), which the default tolerance (1e-30) tells apart and 1e-12 does not; the
// quantities that differ are that link's alone
TEST(EquationDiff, ARobotRestatedToItsRoundingIsEquivalentWithinATolerance) {
  std::string arm = std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/urdf/seven_joint_arm.urdf";
  std::string turned = robot_variant("seven_joint_arm.urdf", "rpy=\"0 0 0\"", "rpy=\"0 0 6.283185307179586\"", "whole_turn");
  EquationDiff exact = compare(arm, turned);
  EXPECT_EQ(exact.verdict, "different");
  for (const EntryComparison& c : exact.entries) EXPECT_LT(c.max_rel_difference, 1e-15) << c.entry;
  // 17 digits hide some of the link's differences: those quantities say so, their texts stay expressions
  int hidden = 0;
  for (const IntermediateChange& c : exact.intermediates_changed)
    if (c.beyond_the_decimals) {
      ++hidden;
      EXPECT_EQ(c.old_text, c.new_text) << c.name;
    }
  EXPECT_GT(hidden, 0);
  EXPECT_NE(diff_text(exact).find("(its numbers differ beyond 17 digits)"), std::string::npos);
  DiffOptions loose;
  loose.tolerance = 1e-12;
  EquationDiff within = compare(arm, turned, loose);
  EXPECT_EQ(within.verdict, "equivalent");
  ASSERT_FALSE(within.intermediates_changed.empty());
  for (const IntermediateChange& c : within.intermediates_changed) EXPECT_EQ(c.name.rfind("link1.", 0), 0u) << c.name;
}

TEST(EquationDiff, InputsThatAreNotDerivationsAreLocatedMistakes) {
  std::string dir = test::temporary_directory();
  std::ofstream(dir + "/other.json") << "{\n  \"name\": \"not a derivation\"\n}\n";
  std::ofstream(dir + "/broken.json") << "{\n  \"model\": \"x\",\n  \"method\" \"lagrange2\"\n}\n";
  Diagnostics d;
  EXPECT_FALSE(read_derivation(dir + "/other.json", d));
  EXPECT_NE(d.format().find("other.json:1:1: error: not a derivation: the key \"model\" is missing"), std::string::npos) << d.format();
  Diagnostics syntax;
  EXPECT_FALSE(read_derivation(dir + "/broken.json", syntax));
  EXPECT_NE(syntax.format().find("broken.json:3:12: error: not valid JSON: ':' was expected"), std::string::npos) << syntax.format();
  Diagnostics missing;
  EXPECT_FALSE(read_derivation(dir + "/nothing.json", missing));
  EXPECT_NE(missing.format().find("cannot be read"), std::string::npos) << missing.format();
}

}  // namespace
}  // namespace eomgen
