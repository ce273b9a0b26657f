// `eomgen sweep` along one parameter: the benchmark bicycle's weave and capsize speeds
// (Meijaard et al. 2007) from models/whipple_linear.toml against the roots of the
// published matrices recomputed here, its eigenvalues at v = 0 … 10 against those of the
// matrices, and the rolling disk's critical spin Ω² = g/(3R) (Routh) where a real pair
// meets at zero and leaves the axis as an undamped oscillation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "parse/json_reader.hpp"
#include "support/benchmark_bicycle.hpp"
#include "support/small_models.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

const JsonValue& member(const JsonValue& v, const std::string& key) {
  const JsonValue* m = v.find(key);
  if (!m) throw std::runtime_error("no member " + key);
  return *m;
}

TEST(EigenvalueSweep, TheBenchmarkBicycleIsSelfStableBetweenItsWeaveAndCapsizeSpeeds) {
  std::string dir = temporary_directory();
  JsonValue r = run_json("sweep '" + model_path("whipple_linear") + "' --param v=0:10:1001 -o '" + dir + "/v.csv' --plot '" +
                         dir + "/v.png'");
  expect_benchmark_sweep(r, dir + "/v.csv");
  EXPECT_TRUE(std::ifstream(dir + "/v.png").good()) << "the eigenvalue chart";
}

TEST(EigenvalueSweep, TheRollingDiskStaysUprightAboveRouthsCriticalSpin) {
  // the rolling disk with its spin rate as a parameter and the upright start
  std::string model = read_file(model_path("rolling_disk"));
  for (auto [from, to] : {std::pair<std::string, std::string>{"g = 9.81", "g = 9.81\nOmega = 8.0"},
                          {"theta = { initial = 1.4, rate = 0.0 }", "theta = { initial = \"Pi/2\", rate = 0.0 }"},
                          {"phi   = { initial = 0.0, rate = 15.0 }", "phi   = { initial = 0.0, rate = \"Omega\" }"}}) {
    std::size_t where = model.find(from);
    ASSERT_NE(where, std::string::npos) << from;
    model.replace(where, from.size(), to);
  }
  std::string path = temporary_directory() + "/spinning_disk.toml";
  std::ofstream(path) << model;
  JsonValue r = run_json("sweep '" + path + "' --param Omega=2:10:81");
  const auto& crossings = member(r, "crossings").items;
  ASSERT_EQ(crossings.size(), 1u);
  EXPECT_NEAR(at(crossings[0], "Omega"), std::sqrt(9.81 / (3 * 0.1)), 1e-9) << "Omega^2 = g/(3R)";
  EXPECT_EQ(member(crossings[0], "kind").text, "real");
  EXPECT_EQ(member(crossings[0], "direction").text, "stabilizing");
  EXPECT_TRUE(member(r, "stable_intervals").items.empty()) << "marginally, never asymptotically stable: no damping";
  CommandOutput text = run_eomgen("sweep '" + path + "' --param Omega=2:10:81");
  EXPECT_NE(text.out.find("a real eigenvalue through 0 crosses into the left half-plane (stability gained)"), std::string::npos)
      << text.out;
  CommandOutput wrong = run_eomgen("sweep '" + path + "' --param Omega=2:10:81 --symbolic");
  EXPECT_EQ(wrong.status, 2);
}

// x'' = −x + (a − 2) x': stable below a = 2, marginal at the grid point a = 2, unstable above;
// the stable interval ends at the crossing, not at the grid point before it
TEST(EigenvalueSweep, StableIntervalEndsAtTheCrossingAndMarginalPointsAreSaid) {
  std::string path = temporary_directory() + "/negative_damping.toml";
  std::ofstream(path) << "[model]\nname = \"negative_damping\"\ntitle = \"damping falls with a\"\n[parameters]\na = 0.0\n"
                         "[coordinates]\nx = { initial = 0.0, rate = 0.0 }\n[[particles]]\nname = \"mass\"\nmass = \"1\"\n"
                         "position = [\"x\", \"0\", \"0\"]\n[energy]\npotential = \"x^2/2\"\n"
                         "[[forces]]\ngeneralized = { x = \"(a - 2)*der(x)\" }\n";
  JsonValue r = run_json("sweep '" + path + "' --param a=0:4:3");
  const JsonValue& stable = r.find("stable_intervals")->items.at(0);
  EXPECT_NEAR(stable.find("high")->value, 2, 1e-6);
  const JsonValue& marginal = r.find("marginal_intervals")->items.at(0);
  EXPECT_EQ(marginal.find("low")->value, 2);
  CommandOutput too_many = run_eomgen("sweep '" + path + "' --param a=0:4:2e9");
  EXPECT_EQ(too_many.status, 2);
  EXPECT_NE(too_many.err.find("a whole COUNT with 2 <= COUNT <= 100000"), std::string::npos) << too_many.err;
}

// x'' = −x + (c − d) x': stable above the crossing d = c, swept on d = c/1000 … 1e3 on a
// logarithmic axis of 49 points for c = 1e-7 … 1e-3. In even steps the grid's second point is
// already 21, and the crossing is bisected to 1e-10 of the width, 1e-7: all of c = 1e-7. A
// constant ratio apart it is found to 1e-4 of c (the real part's rounding, 1e-13 of the rate
// 1/s, is what is left at c = 1e-7), and the stable interval runs from there to the end.
TEST(EigenvalueSweep, ALogarithmicAxisFindsACrossingDecadesBelowItsEnd) {
  // the force (c − d) x' as a dissipation (d − c) x'²/2
  std::string path = write_model("small_damping", particle_on_a_line_model("small_damping", "m = 1.0\nc = 1e-6\nd = 1.0\n",
                                                                            "potential = \"x^2/2\"\n"
                                                                            "dissipation = \"(d - c)*der(x)^2/2\"\n"));
  for (double c : {1e-7, 1e-5, 1e-3}) {
    JsonValue r = run_json(fmt::format("sweep '{}' --set c={:g} --param d={:g}:1e3:49:log", path, c, c / 1000));
    EXPECT_TRUE(r.find("logarithmic")->truth);
    const auto& crossings = r.find("crossings")->items;
    ASSERT_EQ(crossings.size(), 1u) << "c = " << c;
    EXPECT_NEAR(crossings[0].find("d")->value / c, 1, 1e-4) << "c = " << c;
    const auto& stable = r.find("stable_intervals")->items;
    ASSERT_EQ(stable.size(), 1u) << "c = " << c;
    EXPECT_NEAR(stable[0].find("low")->value / c, 1, 1e-4) << "c = " << c;
    EXPECT_EQ(stable[0].find("high")->value, 1e3);
  }
  // a map over two logarithmic axes: its points a constant ratio apart, its chart drawn
  std::string dir = temporary_directory();
  CommandOutput map = run_eomgen("sweep '" + path + "' --param d=1e-9:1e3:13:log --param c=1e-9:1e3:5:log -o '" + dir +
                                 "/map.csv' --plot '" + dir + "/map.png'");
  ASSERT_EQ(map.status, 0) << map.err;
  std::vector<std::vector<double>> rows = read_numeric_csv(dir + "/map.csv");
  ASSERT_EQ(rows.size(), 13u * 5u);
  for (std::size_t i = 0; i < 13; ++i) EXPECT_NEAR(rows[i][0], std::pow(10.0, -9.0 + double(i)), 1e-12 * rows[i][0]) << i;
  EXPECT_TRUE(std::filesystem::exists(dir + "/map.png"));
  CommandOutput from_zero = run_eomgen("sweep '" + path + "' --param d=0:1e3:49:log");
  EXPECT_EQ(from_zero.status, 2);
  EXPECT_NE(from_zero.err.find("0 < LOW for :log"), std::string::npos) << from_zero.err;
}

}  // namespace
}  // namespace eomgen::test
