// `eomgen simulate` end to end: energy conservation, an analytic solution for
// every integrator, the CSV layout, the compile cache, failures that end with
// exit status 3 and the trajectory up to the failure, and absolute tolerances in
// each state's own size.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <fmt/format.h>

#include "support/small_models.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

namespace fs = std::filesystem;

struct CommandRun {
  int status;
  std::string out, err;
};

CommandRun eomgen(const std::string& arguments, const std::string& cache) {
  std::string scratch = temporary_directory();
  int status = run_command("EOMGEN_CACHE_DIR='" + cache + "' '" + std::string(EOMGEN_EXECUTABLE) + "' " + arguments +
                           " > '" + scratch + "/out' 2> '" + scratch + "/err'");
  return {status, read_file(scratch + "/out"), read_file(scratch + "/err")};
}

// the cache shared by these tests, so each model is compiled once per test run
std::string shared_cache() { return std::string(EOMGEN_BINARY_DIR) + "/test-cache"; }

double json_number(const std::string& json, const std::string& key) {
  std::smatch m;
  if (!std::regex_search(json, m, std::regex("\"" + key + "\": ([-+0-9.eE]+)"))) return NAN;
  return std::stod(m[1]);
}

std::vector<std::vector<double>> read_csv(const std::string& path, std::string& header) {
  return read_numeric_csv(path, &header);
}

TEST(Simulate, DoublePendulumConservesEnergyWithTightTolerances) {
  for (const char* integrator : {"cvode-bdf", "arkode-dp5", "arkode-verner"}) {
    CommandRun r = eomgen("simulate '" + model_path("double_pendulum") + "' --t-end 10 --rtol 1e-10 --atol 1e-12 --format json --integrator " +
                       integrator,
                   shared_cache());
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_LT(json_number(r.out, "relative_energy_drift"), 1e-8) << integrator << "\n" << r.out;
    EXPECT_GT(json_number(r.out, "steps"), 100) << r.out;
    EXPECT_GT(json_number(r.out, "rhs_evaluations"), 100) << r.out;
  }
}

// m x'' = −k x: x(t) = x0 cos(ω t) + v0/ω sin(ω t), ω² = k/m
TEST(Simulate, EveryIntegratorFollowsTheHarmonicOscillator) {
  std::string model = write_model("oscillator", spring_mass_model("oscillator", 2.0, 8.0, 0.5, 1.0));
  const double omega = 2.0, t_end = 3.0;
  double exact = 0.5 * std::cos(omega * t_end) + 1.0 / omega * std::sin(omega * t_end);
  struct Case {
    const char* integrator;
    double tolerance;
  } cases[] = {{"cvode-bdf", 1e-7},   {"cvode-adams", 1e-7}, {"arkode-dp5", 1e-8}, {"arkode-verner", 1e-8},
               {"arkode-dirk", 1e-7}, {"rk4", 1e-9},         {"verlet", 1e-5}};
  for (const Case& c : cases) {
    std::string csv = temporary_directory() + "/x.csv";
    CommandRun r = eomgen("simulate '" + model + "' --t-end 3 --dt-out 0.5 --rtol 1e-11 --atol 1e-12 --step 1e-3 --integrator " +
                       c.integrator + " -o '" + csv + "'",
                   shared_cache());
    ASSERT_EQ(r.status, 0) << r.err;
    std::string header;
    auto rows = read_csv(csv, header);
    ASSERT_EQ(rows.size(), 7u);
    EXPECT_NEAR(rows.back()[1], exact, c.tolerance) << c.integrator;
  }
}

// The fixed-step integrators on an oscillator of period 2π s (k = 1/s², m = 1), for time scales s
// from 1e-12 to 1e12, at a step of s/100 and rows s/10 apart: a thousand steps and the same
// error at every scale. The merge of a step "within roundoff" of the output time had been
// measured against one second: at s = 1e-12 every row's first step jumped to it, 100 steps in all,
// and rk4 was 1e4 times less accurate.
TEST(Simulate, AFixedStepIntegratorTakesItsStepsAtEveryTimeScale) {
  for (const char* integrator : {"rk4", "verlet", "gauss-legendre"}) {
    double at_one_second = NAN;
    for (double s : {1.0, 1e-12, 1e-6, 1e6, 1e12}) {
      std::string model = write_model("oscillator", spring_mass_model("oscillator", 1.0, 1 / (s * s), 1.0));
      std::string csv = temporary_directory() + "/x.csv";
      CommandRun r = eomgen(fmt::format("simulate '{}' --integrator {} --step {:.17g} --t-end {:.17g} --dt-out {:.17g} "
                                        "--format json -o '{}'", model, integrator, s / 100, 10 * s, s / 10, csv),
                            shared_cache());
      ASSERT_EQ(r.status, 0) << r.err;
      EXPECT_EQ(json_number(r.out, "steps"), 1000) << integrator << ", s = " << s;
      std::string header;
      double worst = 0;
      for (const auto& row : read_csv(csv, header)) worst = std::max(worst, std::abs(row[1] - std::cos(row[0] / s)));
      if (s == 1.0) at_one_second = worst;
      // the same to 1 %: rounding moves Gauss–Legendre's error of 1.1e-10 by 0.2 % between scales; a
      // merged step made rk4's 1e4 times larger
      EXPECT_NEAR(worst / at_one_second, 1, 1e-2) << integrator << ", s = " << s;
    }
  }
}

// Gauss–Legendre on a quartic oscillator (V = k x⁴/4, k = 1/A²: the same motion at every amplitude
// A, scaled) keeps its energy to the same relative drift for A from 1e-12 to 1e6. Its stage
// equations had been solved to 1e-15 of one unit: at A = 1e-9 to 1e-6 of the state, and the energy
// drifted three times as fast as at A = 1.
TEST(Simulate, GaussLegendreSolvesItsStagesToTheStatesOwnSize) {
  double at_one = NAN;
  for (double A : {1.0, 1e-12, 1e-9, 1e-6, 1e6}) {
    std::string model = write_model("quartic", particle_on_a_line_model("quartic", fmt::format("m = 1.0\nk = {:.17g}\n", 1 / (A * A)),
                                                                          "potential = \"k*x^4/4\"\n", A));
    CommandRun r = eomgen("simulate '" + model + "' --integrator gauss-legendre --step 0.01 --t-end 100 --dt-out 1 --format json",
                          shared_cache());
    ASSERT_EQ(r.status, 0) << r.err;
    double drift = json_number(r.out, "relative_energy_drift");
    if (A == 1.0) at_one = drift;
    EXPECT_NEAR(drift / at_one, 1, 0.1) << "A = " << A << ": " << drift << " against " << at_one;
  }
}

TEST(Simulate, CsvHasAHeaderAndARowPerOutputTime) {
  std::string csv = temporary_directory() + "/dp.csv";
  CommandRun r = eomgen("simulate '" + model_path("double_pendulum") + "' --t-end 1.005 --dt-out 0.1 -o '" + csv + "'", shared_cache());
  ASSERT_EQ(r.status, 0) << r.err;
  std::string header;
  auto rows = read_csv(csv, header);
  // the double pendulum's only first integral is T + V: its column repeats the energy's
  EXPECT_EQ(header, "t,phi1,phi2,der(phi1),der(phi2),energy,tip_x,tip_y,I[energy]");
  ASSERT_EQ(rows.size(), 12u);  // 0, 0.1, …, 1.0 and the final time
  for (std::size_t k = 0; k + 1 < rows.size(); ++k) EXPECT_EQ(rows[k][0], k * 0.1);
  EXPECT_EQ(rows.back()[0], 1.005);
  EXPECT_EQ(rows[0][1], 0.5);  // the model's initial phi1
  for (const auto& row : rows) {
    ASSERT_EQ(row.size(), 9u);
    EXPECT_NEAR(row[8], row[5], 1e-12 * std::abs(row[5]));
  }
}

TEST(Simulate, SetAndInitialOverrideTheModel) {
  std::string csv = temporary_directory() + "/p.csv";
  CommandRun r = eomgen("simulate '" + model_path("pendulum") + "' --t-end 0.1 --set l=2 --initial phi=0.25 --initial 'der(phi)=1' -o '" + csv + "'",
                 shared_cache());
  ASSERT_EQ(r.status, 0) << r.err;
  std::string header;
  auto rows = read_csv(csv, header);
  EXPECT_EQ(rows[0][1], 0.25);
  EXPECT_EQ(rows[0][2], 1.0);
  CommandRun bad = eomgen("simulate '" + model_path("pendulum") + "' --set gg=2", shared_cache());
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("did you mean"), std::string::npos) << bad.err;
}

TEST(Simulate, SecondRunCompilesNothing) {
  std::string cache = temporary_directory();
  CommandRun first = eomgen("simulate '" + model_path("spherical_pendulum") + "' --t-end 0.1", cache);
  CommandRun second = eomgen("simulate '" + model_path("spherical_pendulum") + "' --t-end 0.1", cache);
  ASSERT_EQ(first.status, 0) << first.err;
  ASSERT_EQ(second.status, 0) << second.err;
  EXPECT_NE(first.err.find("compiling spherical_pendulum"), std::string::npos) << first.err;
  EXPECT_EQ(second.err.find("compiling"), std::string::npos) << second.err;
  // the same numbers either way, apart from the wall time
  auto without_time = [](std::string s) { return std::regex_replace(s, std::regex("wall time [0-9.]+ s"), ""); };
  EXPECT_EQ(without_time(first.out), without_time(second.out));
}

TEST(Simulate, CorruptCacheEntryIsRebuiltNotLoaded) {
  std::string cache = temporary_directory();
  ASSERT_EQ(eomgen("simulate '" + model_path("pendulum") + "' --t-end 0.1", cache).status, 0);
  int corrupted = 0;
  for (const auto& entry : fs::recursive_directory_iterator(cache))
    if (entry.path().filename() == "model.so") {
      std::ofstream(entry.path(), std::ios::trunc) << "not a shared object";
      ++corrupted;
    }
  ASSERT_EQ(corrupted, 1);
  CommandRun again = eomgen("simulate '" + model_path("pendulum") + "' --t-end 0.1", cache);
  EXPECT_EQ(again.status, 0) << again.err;
  EXPECT_NE(again.err.find("compiling pendulum"), std::string::npos) << again.err;
}

TEST(Simulate, ConcurrentRunsShareOneCacheEntry) {
  std::string cache = temporary_directory();
  std::string command = "EOMGEN_CACHE_DIR='" + cache + "' '" + std::string(EOMGEN_EXECUTABLE) + "' simulate '" +
                        model_path("cart_pendulum") + "' --t-end 0.1 > /dev/null 2>&1";
  EXPECT_EQ(run_command("(" + command + " & " + command + " & " + command + " & wait) && " + command), 0);
  int entries = 0;
  for (const auto& entry : fs::directory_iterator(cache)) entries += entry.path().filename().string()[0] != '.';
  EXPECT_EQ(entries, 1);
}

TEST(Simulate, DivisionByZeroEndsWithExitThreeAndKeepsTheTrajectory) {
  std::string model = write_model("runaway", R"toml([model]
name = "runaway"
[coordinates]
x = { initial = 0.0, rate = 1.0 }
[[particles]]
name = "p"
mass = "1"
position = ["x", "0", "0"]
[[forces]]
generalized = { x = "1/sqrt(1 - x)" }
)toml");
  std::string csv = temporary_directory() + "/runaway.csv";
  CommandRun r = eomgen("simulate '" + model + "' --t-end 2 --dt-out 0.01 -o '" + csv + "'", shared_cache());
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_NE(r.err.find("the right-hand side is not finite"), std::string::npos) << r.err;
  std::string header;
  auto rows = read_csv(csv, header);
  ASSERT_GT(rows.size(), 50u);
  EXPECT_LT(rows.back()[0], 2.0);
  for (std::size_t k = 0; k + 1 < rows.size(); ++k) EXPECT_DOUBLE_EQ(rows[k][0], k * 0.01);
}

TEST(Simulate, SingularMassMatrixEndsWithExitThreeNamingTheConfiguration) {
  // T = ½ x² ẋ²: M = x² vanishes at x = 0, reached at t = ½ from x = 1, ẋ = −1
  std::string model = write_model("vanishing_mass", R"toml([model]
name = "vanishing_mass"
[coordinates]
x = { initial = 1.0, rate = -1.0 }
[energy]
kinetic = "x^2*der(x)^2/2"
)toml");
  std::string csv = temporary_directory() + "/v.csv";
  CommandRun r = eomgen("simulate '" + model + "' --t-end 2 -o '" + csv + "'", shared_cache());
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_NE(r.err.find("the mass matrix is singular"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("at x = "), std::string::npos) << r.err;
  std::string header;
  auto rows = read_csv(csv, header);
  EXPECT_NEAR(rows.back()[0], 0.5, 1e-3);
}

TEST(Simulate, SliderCrankUnderIdaReportsResidualsAndConstraintForces) {
  std::string csv = temporary_directory() + "/slider.csv";
  CommandRun run = eomgen("simulate " + model_path("slider_crank") + " --integrator ida --t-end 2 --format json -o " + csv, shared_cache());
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_LT(json_number(run.out, "max_position_residual"), 1e-7) << run.out;
  EXPECT_LT(json_number(run.out, "max_velocity_residual"), 1e-6) << run.out;
  EXPECT_GT(json_number(run.out, "lambda_loop_x"), 1.0) << run.out;
  std::string header;
  auto rows = read_csv(csv, header);
  EXPECT_EQ(header, "t,phi,beta,x,der(phi),der(beta),der(x),energy,lambda_loop_x,lambda_loop_y,position_residual,velocity_residual,I[energy]");
  EXPECT_EQ(rows.size(), 201u);
}

TEST(Simulate, ReportsTheDriftOfEveryFirstIntegral) {
  // the heavy top keeps T + V, p_psi and p_phi; each is printed with its change over the run
  CommandRun text = eomgen("simulate " + model_path("heavy_symmetric_top") + " --t-end 5 --rtol 1e-10 --atol 1e-12",
                           shared_cache());
  ASSERT_EQ(text.status, 0) << text.err;
  for (const char* name : {"    energy: I(0) = ", "    p_psi: I(0) = ", "    p_phi: I(0) = "})
    EXPECT_NE(text.out.find(name), std::string::npos) << name << " missing from\n" << text.out;
  EXPECT_NE(text.out.find("their change is the integration error"), std::string::npos) << text.out;
  CommandRun json = eomgen("simulate " + model_path("heavy_symmetric_top") + " --t-end 5 --rtol 1e-10 --atol 1e-12 "
                           "--format json", shared_cache());
  ASSERT_EQ(json.status, 0) << json.err;
  std::size_t p_psi = json.out.find("\"name\": \"p_psi\"");
  ASSERT_NE(p_psi, std::string::npos) << json.out;
  double change = json_number(json.out.substr(p_psi), "relative_change");
  EXPECT_GT(change, 0) << json.out;
  EXPECT_LT(change, 1e-7) << json.out;
  // with an input acting the momentum of the cart is not conserved, and the report says so
  CommandRun driven = eomgen("simulate " + model_path("cart_pendulum") + " --t-end 1 --set F=1", shared_cache());
  ASSERT_EQ(driven.status, 0) << driven.err;
  EXPECT_NE(driven.out.find("the inputs act, so they need not stay constant"), std::string::npos) << driven.out;
}

TEST(Simulate, ReportsWhetherTheQuaternionsWereKeptUnit) {
  std::string model = model_path("tumbling_body");
  CommandRun kept = eomgen("simulate " + model + " --t-end 20", shared_cache());
  ASSERT_EQ(kept.status, 0) << kept.err;
  EXPECT_NE(kept.out.find("  quaternions: normalized after every step (largest correction of |q| "), std::string::npos)
      << kept.out;
  CommandRun json = eomgen("simulate " + model + " --t-end 20 --format json", shared_cache());
  ASSERT_EQ(json.status, 0) << json.err;
  EXPECT_NE(json.out.find("\"quaternions\": {\"count\": 1, \"normalized\": \"after every step\""), std::string::npos) << json.out;
  EXPECT_LE(json_number(json.out, "max_norm_error"), 4e-16) << json.out;
  EXPECT_GT(json_number(json.out, "max_correction"), 0) << json.out;
  CommandRun free = eomgen("simulate " + model + " --t-end 20 --stabilization none --format json", shared_cache());
  ASSERT_EQ(free.status, 0) << free.err;
  EXPECT_NE(free.out.find("\"normalized\": null"), std::string::npos) << free.out;
  EXPECT_GT(json_number(free.out, "max_norm_error"), 1e-12) << "arkode-dp5 at rtol 1e-8 drifts |q|\n" << free.out;
  // the reference integrator has no projection of its own: the rows it gives are normalized
  CommandRun wide = eomgen("simulate " + model + " --t-end 2 --integrator reference --format json", shared_cache());
  ASSERT_EQ(wide.status, 0) << wide.err;
  EXPECT_NE(wide.out.find("\"normalized\": \"at the output times\""), std::string::npos) << wide.out;
  EXPECT_LE(json_number(wide.out, "max_norm_error"), 4e-16) << wide.out;
  CommandRun zero = eomgen("simulate " + model + " --initial qw=0", shared_cache());
  EXPECT_EQ(zero.status, 3);
  EXPECT_NE(zero.err.find("the quaternion (qw, qx, qy, qz) is 0 at the start"), std::string::npos) << zero.err;
}

// A tree of 21 hinges, whose header forms M in the loops of its derivatives' pass: the compiled
// model holds the rhs in double and in the reference integrator's wide scalar, and a `+=` on M
// had kept it from compiling. The default integrator against the reference's rows.
TEST(Simulate, ALongTreeRunsWithTheDefaultAndTheReferenceIntegrator) {
  std::string model = std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/models/branched_tree.toml", scratch = temporary_directory();
  CommandRun fast = eomgen("simulate '" + model + "' --t-end 0.02 --rtol 1e-11 -o '" + scratch + "/fast.csv'", shared_cache());
  ASSERT_EQ(fast.status, 0) << fast.err;
  CommandRun wide = eomgen("simulate '" + model + "' --t-end 0.02 --integrator reference -o '" + scratch + "/wide.csv'",
                           shared_cache());
  ASSERT_EQ(wide.status, 0) << wide.err;
  std::string header;
  auto a = read_csv(scratch + "/fast.csv", header), b = read_csv(scratch + "/wide.csv", header);
  ASSERT_EQ(a.size(), b.size());
  double largest = 0, worst = 0;
  for (double v : b.back()) largest = std::max(largest, std::abs(v));
  for (std::size_t i = 0; i < b.back().size(); ++i) worst = std::max(worst, std::abs(a.back()[i] - b.back()[i]));
  EXPECT_LT(worst, 1e-8 * largest);
}

TEST(Simulate, RollingDiskRunsAHundredSecondsOnItsConstraints) {
  CommandRun run = eomgen("simulate " + model_path("rolling_disk") + " --t-end 100 --format json", shared_cache());
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_LT(json_number(run.out, "max_velocity_residual"), 1e-8) << run.out;
  EXPECT_NE(run.out.find("\"count\": 2"), std::string::npos) << run.out;
}

TEST(Simulate, PseudoVelocitiesAreSetByNameOrByTheirDefinition) {
  std::string csv = temporary_directory() + "/knife.csv";
  CommandRun run = eomgen("simulate " + model_path("knife_edge") + " --t-end 0.1 --initial v=3 --initial 'der(phi)=2' -o " + csv,
                          shared_cache());
  ASSERT_EQ(run.status, 0) << run.err;
  std::string header;
  auto rows = read_csv(csv, header);
  EXPECT_EQ(header.substr(0, 14), "t,x,y,phi,v,w,");
  EXPECT_EQ(rows[0][4], 3.0);
  EXPECT_EQ(rows[0][5], 2.0);
  CommandRun dependent = eomgen("simulate " + model_path("knife_edge") + " --initial 'der(x)=1'", shared_cache());
  EXPECT_EQ(dependent.status, 2);
  EXPECT_NE(dependent.err.find("follows from them and the constraints"), std::string::npos) << dependent.err;
}

TEST(Simulate, IdaOnAModelWithoutMultipliersIsAUsageError) {
  CommandRun run = eomgen("simulate " + model_path("knife_edge") + " --integrator ida", shared_cache());
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("lagrange1"), std::string::npos) << run.err;
}

// An oscillator of 1e5 rad/s whose amplitude is a, for a from 1e-12 to 1: the default absolute
// tolerance, 1e-10 in every unit, had left a = 1e-9 m at 5e-5 of its amplitude where rtol asks
// 1e-8. Without --atol each state's tolerance follows its size, and the run is as accurate at
// every amplitude (1e-7 of it, against the cosine); with --atol it is the one given.
TEST(Simulate, ASmallOscillatorIsAsAccurateAsALargeOne) {
  std::string model = write_model("small_oscillator", spring_mass_model("small_oscillator", 1e-9, 10.0, 1.0));
  const double omega = 1e5;
  auto worst_error = [&](double a, const std::string& extra, std::string* err) {
    std::string csv = temporary_directory() + "/o.csv";
    CommandRun r = eomgen("simulate '" + model + "' --t-end 1e-3 --dt-out 1e-5 --integrator arkode-dp5 --initial x=" +
                              fmt::format("{:.17g}", a) + " " + extra + " -o '" + csv + "'",
                          shared_cache());
    EXPECT_EQ(r.status, 0) << r.err;
    if (err) *err = r.err;
    std::string header;
    double worst = 0;
    for (const auto& row : read_csv(csv, header)) worst = std::max(worst, std::abs(row[1] - a * std::cos(omega * row[0])) / a);
    return worst;
  };
  for (double a : {1.0, 1e-3, 1e-6, 1e-9, 1e-12}) {
    std::string err;
    double error = worst_error(a, "", &err);
    EXPECT_LT(error, 1e-7) << "a = " << a;
    if (a <= 1e-6) {
      EXPECT_NE(err.find("absolute tolerance from each state's size"), std::string::npos) << err;
    }
  }
  EXPECT_GT(worst_error(1e-9, "--atol 1e-10", nullptr), 1e-6);
}

// A quartic well c x⁴/4 written with a dissipation d der(x)²/2, so that only the values tell
// whether T + V is conserved, on scales L from 1e-12 to 1e12 (c = 1/L², x0 = L: the same motion
// in other units). Differentiated with steps of 1e-3 of a unit, the energy had been "not
// conserved" at every L but 1 with d = 0; with d = 1 it is not, at every L.
TEST(Simulate, WhetherEnergyIsConservedDoesNotDependOnTheUnits) {
  std::string model = write_model("quartic_well_with_dissipation",
                                  particle_on_a_line_model("quartic_well_with_dissipation", "m = 1.0\nc = 1.0\nd = 0.0\n",
                                                           "potential = \"c*x^4/4\"\ndissipation = \"d*der(x)^2/2\"\n"));
  for (double L : {1e-12, 1e-6, 1.0, 1e6, 1e12})
    for (double d : {0.0, 1.0}) {
      JsonValue r = run_json(fmt::format("simulate '{}' --set c={:.17g} --set d={:g} --initial x={:.17g} --t-end 1 --dt-out 0.5 "
                                         "-o '{}/q.csv'", model, 1 / (L * L), d, L, temporary_directory()));
      const JsonValue* conserves = r.find("conserves_energy");
      ASSERT_NE(conserves, nullptr);
      EXPECT_EQ(conserves->truth, d == 0) << "L = " << L << ", d = " << d;
    }
}

// A free mass at rest (E(0) = 0) pushed by F = 1 N for 1 s gains ½ m v² = F² t² / (2 m) = 0.25 J
// (m = 2): the report gives that change, and no relative drift, where dividing by 1e-300 had printed
// 2.5e299; the JSON's relative_energy_drift is null.
TEST(Simulate, AnEnergyThatStartsAtZeroHasNoRelativeDrift) {
  std::string model = write_model("pushed_mass", pushed_mass_model);
  CommandRun text = eomgen(fmt::format("simulate '{}' --set F=1 --t-end 1 --rtol 1e-10 -o '{}/m.csv'", model, temporary_directory()),
                           shared_cache());
  ASSERT_EQ(text.status, 0) << text.err;
  std::smatch change;
  ASSERT_TRUE(std::regex_search(text.out, change, std::regex(R"(max \|E\(t\) - E\(0\)\| = ([0-9.e+-]+) \(E\(0\) = 0: no relative drift\))")))
      << text.out;
  EXPECT_NEAR(std::stod(change[1]), 0.25, 1e-6) << text.out;
  CommandRun json = eomgen(fmt::format("simulate '{}' --set F=1 --t-end 1 --format json -o '{}/m.csv'", model, temporary_directory()),
                           shared_cache());
  ASSERT_EQ(json.status, 0) << json.err;
  EXPECT_NE(json.out.find("\"relative_energy_drift\": null"), std::string::npos) << json.out;
}

// The Cartesian pendulum with its rod l from 1e-13 to 1e13 m, started at (0.6 l, −0.9 l), off its
// rod: the constraint moves the given y to −0.8 l, and says so at every l (against 1e-12 of
// max(1, |y|), the change at 1e-13 m went unsaid); started on the rod, nothing is said.
TEST(Simulate, AGivenValueTheConstraintsChangeIsSaidAtEveryScale) {
  for (double l : {1e-13, 1e-6, 1.0, 1e6, 1e13})
    for (double y : {-0.9, -0.8}) {
      CommandOutput r = run_eomgen(fmt::format("simulate '{}' --set l={:g} --initial x={:.17g} --initial y={:.17g} --t-end 1e-9 "
                                               "--dt-out 1e-9 -o '{}/p.csv'", model_path("pendulum_cartesian"), l, 0.6 * l,
                                               y * l, temporary_directory()));
      EXPECT_EQ(r.status, 0) << r.err;
      bool said = r.err.find("the constraints do not allow the initial values you gave: changed y") != std::string::npos;
      EXPECT_EQ(said, y == -0.9) << "l = " << l << ", y = " << y << ": " << r.err;
    }
}

TEST(RunCommand, MainJobDrawsTheCharts) {
  std::string dir = temporary_directory();
  CommandRun r = eomgen("run -o '" + dir + "'", shared_cache());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("M[0][1] = l1*l2*m2*cos(phi1 - phi2)"), std::string::npos);
  for (const char* file : {"double_pendulum.hpp", "double_pendulum.csv", "double_pendulum.png", "double_pendulum_energy.png"})
    EXPECT_TRUE(fs::exists(dir + "/" + file) && fs::file_size(dir + "/" + file) > 1000) << file;
}

}  // namespace
}  // namespace eomgen::test
