// `eomgen diff` on the command line: exit statuses like diff and cmp, the JSON
// report's keys, located mistakes, and --self against an eomgen executable.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

std::string changed_pendulum(const std::string& from, const std::string& to) {
  std::string text = read_file(model_path("pendulum"));
  text.replace(text.find(from), from.size(), to);
  std::string path = temporary_directory() + "/pendulum.toml";
  std::ofstream(path) << text;
  return path;
}

// the rolling disk as it was written before frames and `rolls` (its centre and rotation in
// full, the two no-slip conditions by hand) against models/rolling_disk.toml
const char* rolling_disk_by_hand = R"toml(# Thin disk rolling without slipping on a horizontal plane. Coordinates: the
# contact point (x, y) and the Euler angles 3-1-3 of the disk, heading psi,
# tilt theta (theta = pi/2 is upright) and spin phi. Rolling means the disk's
# material point at the contact is at rest: der(x) + R*cos(psi)*der(phi) = 0 and
# der(y) + R*sin(psi)*der(phi) = 0 (two nonholonomic constraints; the vertical
# one is built into the centre's height R*sin(theta)). Appell's equations with
# the independent velocities der(psi), der(theta), der(phi) chosen by eomgen.
# First integral: the energy T + V. Upright straight rolling (theta = pi/2,
# der(psi) = 0, der(phi) = Omega) is stable when Omega^2 > m*g*R*A/(C*(C + m*R^2)),
# which is g/(3*R) for the thin disk (A = m*R^2/4, C = m*R^2/2).
# Source: Hiller §4.3; E. J. Routh, Advanced Rigid Dynamics (1884), §244.

[model]
name   = "rolling_disk"
title  = "Thin disk rolling without slipping"
method = "appell"

[parameters]
m = 1.0      # kg
R = 0.1      # radius, m
g = 9.81

[coordinates]
x     = 0.0
y     = 0.0
psi   = { initial = 0.0, rate = 0.0 }
theta = { initial = 1.4, rate = 0.0 }
phi   = { initial = 0.0, rate = 15.0 }

[[rigid_bodies]]
name     = "disk"
mass     = "m"
center   = ["x - R*sin(psi)*cos(theta)", "y + R*cos(psi)*cos(theta)", "R*sin(theta)"]
rotation = "euler313(psi, theta, phi)"
inertia  = ["m*R^2/4", "m*R^2/4", "m*R^2/2"]

[gravity]
acceleration = ["0", "0", "-g"]

[[constraints]]
name         = "roll_x"
nonholonomic = "der(x) + R*cos(psi)*der(phi)"

[[constraints]]
name         = "roll_y"
nonholonomic = "der(y) + R*sin(psi)*der(phi)"

[outputs]
center_height = "R*sin(theta)"
)toml";

TEST(DiffCommand, TheRollingDiskWithFramesAndRollsIsTheDiskWrittenByHand) {
  std::string path = temporary_directory() + "/rolling_disk.toml";
  std::ofstream(path) << rolling_disk_by_hand;
  CommandOutput r = run_eomgen("diff '" + path + "' '" + model_path("rolling_disk") +
                               "' --rename roll_x=roll_slip_x --rename roll_y=roll_slip_y");
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find(": identical\n"), std::string::npos) << r.out;
}

// |l| for l: equal where the parameters are sampled (positive), not shown equal for l < 0: exit 1,
// and 0 with --region, which says the sampled region is all that is asked about
// A bob of mass m on a rod of length l turned by a torsion spring k (no gravity): M = m l², f = −k φ.
std::string torsion_pendulum(double size, const std::string& mass, const std::string& position) {
  std::string path = temporary_directory() + "/torsion_pendulum.toml";
  std::ofstream(path) << fmt::format(R"toml([model]
name = "torsion_pendulum"
[parameters]
m = {0:.17g}
l = {0:.17g}
k = 1.0
[coordinates]
phi = {{ initial = 0.5, rate = 0.0 }}
[[particles]]
name = "bob"
mass = "{1}"
position = [{2}]
[energy]
potential = "k*phi^2/2"
)toml",
                                     size, mass, position);
  return path;
}

// A 1e-12 kg bob on a 1e-12 m rod has M = 1e-36: twice the mass had been "equivalent" (|ΔM| under
// 1e-30 of one unit) and the verdict "equivalent", though it swings √2 times slower. Now it is
// "different" for m and l from 1e-12 to 1e12, while the same bob written in half angles
// (2 sin(φ/2) cos(φ/2) for sin φ) stays "equivalent" at every size: its terms' rounding, not one
// unit, is the floor.
TEST(DiffCommand, ASmallBobOfTwiceTheMassIsDifferentAtEverySize) {
  const std::string by_sines = "\"l*sin(phi)\", \"-l*cos(phi)\", \"0\"", by_halves = "\"2*l*sin(phi/2)*cos(phi/2)\", \"l*(2*sin(phi/2)^2 - 1)\", \"0\"";
  for (double size : {1e-12, 1e-6, 1.0, 1e6, 1e12}) {
    std::string old_side = torsion_pendulum(size, "m", by_sines);
    std::string heavier = temporary_directory() + "/heavier.toml", halved = temporary_directory() + "/halved.toml";
    std::filesystem::copy_file(torsion_pendulum(size, "2*m", by_sines), heavier);
    std::filesystem::copy_file(torsion_pendulum(size, "m", by_halves), halved);
    CommandOutput twice = run_eomgen("diff '" + old_side + "' '" + heavier + "' --format json");
    EXPECT_EQ(twice.status, 1) << "m = l = " << size << ": " << twice.err;
    EXPECT_NE(twice.out.find("\"verdict\": \"different\""), std::string::npos) << "m = l = " << size << ": " << twice.out;
    CommandOutput same = run_eomgen("diff '" + old_side + "' '" + halved + "' --format json");
    EXPECT_EQ(same.status, 0) << "m = l = " << size << ": " << same.err;
    EXPECT_NE(same.out.find("\"verdict\": \"equivalent\""), std::string::npos) << "m = l = " << size << ": " << same.out;
  }
}

TEST(DiffCommand, EqualOnTheSampledRegionExitsOneUnlessTheRegionIsEnough) {
  std::string baseline = std::string(EOMGEN_SOURCE_DIR) + "/generated/pendulum.json";
  std::string branched = changed_pendulum("\"-l*cos(phi)\"", "\"-abs(l)*cos(phi)\"");
  CommandOutput strict = run_eomgen("diff '" + baseline + "' '" + branched + "'");
  EXPECT_EQ(strict.status, 1) << strict.out << strict.err;
  EXPECT_NE(strict.out.find("equal_on_samples"), std::string::npos) << strict.out;
  EXPECT_NE(strict.out.find("sampled region only"), std::string::npos) << strict.out;
  CommandOutput region = run_eomgen("diff '" + baseline + "' '" + branched + "' --region");
  EXPECT_EQ(region.status, 0) << region.out << region.err;
  EXPECT_NE(region.out.find("equal_on_samples"), std::string::npos) << region.out;
}

TEST(DiffCommand, RenamingASymbolTheOldSideLacksIsAMistake) {
  CommandOutput r = run_eomgen("diff '" + model_path("pendulum") + "' '" + model_path("pendulum") + "' --rename kk=k");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.err.find("--rename kk=k: kk is not a symbol of"), std::string::npos) << r.err;
}

TEST(DiffCommand, ExitStatusesLikeDiff) {
  std::string baseline = std::string(EOMGEN_SOURCE_DIR) + "/generated/pendulum.json";
  CommandOutput same = run_eomgen("diff '" + baseline + "' '" + model_path("pendulum") + "'");
  EXPECT_EQ(same.status, 0) << same.err;
  EXPECT_NE(same.out.find(": identical\n"), std::string::npos) << same.out;
  EXPECT_NE(same.out.find("5 entries compared: 5 identical"), std::string::npos) << same.out;
  // the pivot raised by l/10: V gains a constant, the motion stays the same
  CommandOutput raised = run_eomgen("diff '" + baseline + "' '" + changed_pendulum("\"-l*cos(phi)\"", "\"-l*cos(phi) + l/10\"") + "'");
  EXPECT_NE(raised.out.find("different: V"), std::string::npos) << raised.out;
  EXPECT_NE(raised.out.find("same_motion"), std::string::npos) << raised.out;
  CommandOutput changed = run_eomgen("diff '" + baseline + "' '" + changed_pendulum("\"-l*cos(phi)\"", "\"-11*l*cos(phi)/10\"") + "'");
  EXPECT_EQ(changed.status, 1) << changed.err;
  EXPECT_NE(changed.out.find("different: V"), std::string::npos) << changed.out;
  EXPECT_NE(changed.out.find("    old: -g*l*m*cos(phi)\n    new: "), std::string::npos) << changed.out;
  CommandOutput missing = run_eomgen("diff '" + baseline + "' /nonexistent/model.toml");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("/nonexistent/model.toml"), std::string::npos) << missing.err;
  std::string other = temporary_directory() + "/other.json";
  std::ofstream(other) << "{\n  \"name\": \"not a derivation\"\n}\n";
  CommandOutput malformed = run_eomgen("diff '" + other + "' '" + baseline + "'");
  EXPECT_EQ(malformed.status, 2);
  EXPECT_NE(malformed.err.find("other.json:1:1: error: not a derivation"), std::string::npos) << malformed.err;
  EXPECT_EQ(malformed.out, "");
  EXPECT_EQ(run_eomgen("diff '" + baseline + "'").status, 2) << "two inputs are needed";
  EXPECT_EQ(run_eomgen("diff '" + baseline + "' '" + baseline + "' --rename k").status, 2);
}

TEST(DiffCommand, JsonHasTheDocumentedKeys) {
  CommandOutput r = run_eomgen("diff '" + model_path("pendulum") + "' '" + changed_pendulum("g = 9.81", "g = 9.80665") +
                               "' --format json");
  EXPECT_EQ(r.status, 1);
  for (const char* key : {"\"verdict\": \"different\"", "\"old\":", "\"new\":", "\"symbols\": {\"added\": [], \"removed\": [], "
                          "\"renamed\": [], \"defaults_changed\": [{\"name\": \"g\", \"old\": 9.81, "
                          "\"new\": 9.80665}]}", "\"entries\": [{\"entry\": \"M[0][0]\", \"status\": \"identical\", "
                          "\"decided_by\": \"text\"", "\"max_abs_difference\"", "\"max_rel_difference\""})
    EXPECT_NE(r.out.find(key), std::string::npos) << key << "\n" << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << "one JSON object on one line";
}

TEST(DiffCommand, SelfComparesTwoExecutablesModelByModel) {
  // the same executable on both sides: every model derives identically, one line each
  std::string dir = temporary_directory();
  for (const char* name : {"pendulum", "knife_edge", "mathieu"})
    std::ofstream(dir + "/" + name + ".toml") << read_file(model_path(name));
  CommandOutput r = run_eomgen(std::string("diff --self '") + EOMGEN_EXECUTABLE + "' '" + dir + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  for (const char* name : {"knife_edge", "mathieu", "pendulum"})
    EXPECT_NE(r.out.find(dir + "/" + name + ".toml: identical\n"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("3 models compared"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace eomgen::test
