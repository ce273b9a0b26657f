// `eomgen ensemble`: the pendulum with a normally distributed length has the mean period
// of the closed form T(l) = 4 √(l/g) K(sin(φ0/2)) averaged over the normal density, within
// the Monte-Carlo standard error the command reports; a failed run is named and left out;
// mistakes in the flags are said with what to write instead.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "parse/json_reader.hpp"
#include "support/small_models.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

// the complete elliptic integral of the first kind by the arithmetic-geometric mean
double elliptic_k(double k) {
  double a = 1, b = std::sqrt(1 - k * k);
  for (int i = 0; i < 40; ++i) std::tie(a, b) = std::make_pair(0.5 * (a + b), std::sqrt(a * b));
  return M_PI / (2 * a);
}

// E[√l] for l ~ normal(mean, sd), by Simpson's rule over ±10 sd
double expected_root(double mean, double sd) {
  const int n = 4000;
  double lo = mean - 10 * sd, h = 20 * sd / n, sum = 0;
  for (int i = 0; i <= n; ++i) {
    double l = lo + i * h, w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
    sum += w * std::sqrt(l) * std::exp(-0.5 * std::pow((l - mean) / sd, 2)) / (sd * std::sqrt(2 * M_PI));
  }
  return sum * h / 3;
}

const JsonValue& first_of(const JsonValue& v, const std::string& key) {
  const JsonValue* list = v.find(key);
  if (!list || list->items.empty()) throw std::runtime_error("no " + key);
  return list->items.front();
}

TEST(EnsembleCommand, PendulumWithANormalLengthHasTheMeanPeriodOfTheClosedForm) {
  const double g = 9.81, phi0 = 0.5, mean = 1.0, sd = 0.05;
  double closed_form = 4 * elliptic_k(std::sin(phi0 / 2)) / std::sqrt(g) * expected_root(mean, sd);
  JsonValue r = run_json("ensemble '" + model_path("pendulum") +
                         "' --samples 400 --vary 'l=normal(1,0.05)' --measure 'period(phi)' --outputs phi --t-end 10 "
                         "--rtol 1e-10 --atol 1e-12 --seed 1");
  EXPECT_EQ(at(r, "failed"), 0);
  const JsonValue& period = first_of(r, "measures");
  double estimate = at(period, "mean"), standard_error = at(period, "standard_error");
  EXPECT_EQ(at(period, "count"), 400);
  // the spread of the periods is that of √l: sd ≈ T̄ · sd/(2 mean)
  EXPECT_NEAR(at(period, "standard_deviation"), closed_form * sd / (2 * mean), 0.1 * closed_form * sd / (2 * mean));
  EXPECT_NEAR(standard_error, at(period, "standard_deviation") / 20, 1e-15);
  // within the Monte-Carlo standard error of the mean (the draws are fixed by the seed)
  EXPECT_LT(std::abs(estimate - closed_form), standard_error)
      << "estimate " << estimate << ", closed form " << closed_form << ", standard error " << standard_error;
}

// an initial value written in the parameters follows each sample's drawn parameter
TEST(EnsembleCommand, InitialValuesFollowTheVariedParameters) {
  std::string path = temporary_directory() + "/hanging_spring.toml";
  std::ofstream(path) << "[model]\nname = \"hanging_spring\"\ntitle = \"Mass on a spring, released 5 cm below rest\"\n"
                         "[parameters]\nm = 1.0\ng = 9.81\nk = 10.0\nl0 = 0.5\n"
                         "[coordinates]\nr = { initial = \"l0 + m*g/k + 0.05\", rate = 0.0 }\n"
                         "[[particles]]\nname = \"mass\"\nmass = \"m\"\nposition = [\"0\", \"-r\", \"0\"]\n"
                         "[gravity]\nacceleration = [\"0\", \"-g\", \"0\"]\n"
                         "[energy]\npotential = \"k*(r - l0)^2/2\"\n";
  JsonValue r = run_json("ensemble '" + path + "' --samples 4 --vary 'k=normal(100,0)' --measure 'final(r)' "
                         "--t-end 1e-6 --dt-out 1e-6");
  EXPECT_NEAR(at(first_of(r, "measures"), "mean"), 0.5 + 9.81 / 100 + 0.05, 1e-9) << "r(0) at k = 100, not at k = 10";
}

// Without --atol each sample's states' sizes set their absolute tolerances, as simulate's do: an
// oscillator of 1 nm and 1e5 rad/s ends where cos says to 1e-7 of its amplitude; with 1e-10 in
// every unit, to 2.6e-5
TEST(EnsembleCommand, ASmallOscillatorIsIntegratedToItsOwnScale) {
  std::string path = write_model("small_oscillator", spring_mass_model("small_oscillator", 1e-9, 10.0, 1e-9));
  const double exact = 1e-9 * std::cos(1e5 * 1e-3);
  auto final_x = [&](const std::string& extra) {
    JsonValue r = run_json("ensemble '" + path + "' --samples 2 --vary 'k=normal(10,0)' --measure 'final(x)' "
                           "--t-end 1e-3 --dt-out 1e-5 --integrator arkode-dp5 " + extra);
    return at(first_of(r, "measures"), "mean");
  };
  EXPECT_NEAR(final_x(""), exact, 1e-7 * 1e-9);
  EXPECT_GT(std::abs(final_x("--atol 1e-10") - exact), 1e-6 * 1e-9);
}

// a measure that some samples cannot give says how many it left out, and that the loss follows
// the drawn damping (the heavily damped pendulums never swing back: no period)
TEST(EnsembleCommand, LeftOutSamplesAreCountedAndABiasedLossIsFlagged) {
  CommandOutput r = run_eomgen("ensemble '" + model_path("pendulum") + "' --samples 60 --vary 'd=uniform(0,30)' "
                               "--measure 'period(phi)' --t-end 5 --seed 3 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  Diagnostics diagnostics;
  auto json = parse_json(r.out, "stdout", diagnostics);
  ASSERT_TRUE(json) << diagnostics.format();
  const JsonValue& period = first_of(*json, "measures");
  EXPECT_GT(at(period, "left_out"), 0);
  EXPECT_EQ(at(period, "left_out") + at(period, "count"), 60);
  EXPECT_TRUE(period.find("biased")->truth);
  EXPECT_NE(r.err.find("finished samples left out"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("larger d"), std::string::npos) << r.err;
}

TEST(EnsembleCommand, WritesTheStatisticsOverTimeAndTheBandChart) {
  std::string dir = temporary_directory();
  CommandOutput r = run_eomgen("ensemble '" + model_path("pendulum") + "' --samples 50 --vary 'phi=uniform(0.4,0.6)' "
                               "--outputs phi,energy --quantiles 0.1,0.5,0.9 --t-end 2 --dt-out 0.1 -o '" + dir +
                               "/e.csv' --plot '" + dir + "/e.png'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("phi ~ uniform(0.4, 0.6)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("50 runs finished, 0 failed"), std::string::npos) << r.out;
  std::string header;
  auto rows = read_numeric_csv(dir + "/e.csv", &header);
  EXPECT_EQ(header, "t,phi.mean,phi.sd,phi.q0.1,phi.q0.5,phi.q0.9,energy.mean,energy.sd,energy.q0.1,energy.q0.5,energy.q0.9");
  ASSERT_EQ(rows.size(), 21u);
  // at t = 0 phi is the draw: uniform on [0.4, 0.6] has mean 0.5 and sd 0.2/√12
  EXPECT_NEAR(rows[0][1], 0.5, 3 * 0.2 / std::sqrt(12.0 * 50));
  EXPECT_NEAR(rows[0][2], 0.2 / std::sqrt(12.0), 0.015);
  EXPECT_LT(rows[0][3], rows[0][4]);
  EXPECT_LT(rows[0][4], rows[0][5]);
  // each run conserves its energy: the statistics of the energy stay those of t = 0
  for (const auto& row : rows) EXPECT_NEAR(row[6], rows[0][6], 1e-6);
  EXPECT_GT(read_file(dir + "/e.png").size(), 1000u);
}

TEST(EnsembleCommand, AFailedRunIsNamedAndLeftOut) {
  // m x'' = k x³ from x = 1, x' = 1 escapes to infinity at t = 1.311 for k = 1 (models/finite_escape.toml);
  // for k < 0 the force pulls back and the run is bounded
  CommandOutput r = run_eomgen("ensemble '" + model_path("finite_escape") + "' --samples 40 --vary 'k=uniform(-1,1)' "
                               "--t-end 1.5 --integrator cvode-bdf --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("runs failed and are left out of the statistics; the first, sample"), std::string::npos) << r.err;
  Diagnostics d;
  auto json = parse_json(r.out, "stdout", d);
  ASSERT_TRUE(json) << r.out;
  double failed = at(*json, "failed");
  EXPECT_GT(failed, 0);
  EXPECT_LT(failed, 40);
  EXPECT_EQ(at(first_of(*json, "at_end"), "count"), 40 - failed);
  // every run failing is no result at all
  CommandOutput all = run_eomgen("ensemble '" + model_path("finite_escape") + "' --samples 4 --vary 'k=uniform(0.9,1)' "
                                 "--t-end 1.5 --integrator cvode-bdf");
  EXPECT_EQ(all.status, 3) << all.err;
  EXPECT_NE(all.err.find("every run failed"), std::string::npos) << all.err;
}

TEST(EnsembleCommand, MistakesAreSaidWithTheFix) {
  std::string model = "'" + model_path("pendulum") + "'";
  struct Case {
    std::string arguments, expected;
  } cases[] = {
      {"--vary 'phii=normal(1,0.1)'", "did you mean 'phi'?"},
      {"--vary 'l=gauss(1,0.1)'", "expected NAME=normal(MEAN,SD)"},
      {"--vary 'l=uniform(2,1)'", "needs LOW < HIGH"},
      {"--vary 'l=normal(1,-1)'", "must be >= 0"},
      {"--vary 'l=normal(1,0.1)' --vary 'l=normal(1,0.2)'", "given twice"},
      {"--measure 'periode(phi)'", "expected final(SIGNAL)"},
      {"--measure 'period(ph)'", "did you mean 'phi'?"},
      {"--outputs tip", "not a state, output or energy"},
      {"--quantiles 0.5,2", "probabilities in [0, 1]"},
      {"--samples 0", "--samples must be between 1"},
      {"--samples 100000000 --dt-out 0.001", "hint: raise --dt-out"},
  };
  for (const Case& c : cases) {
    CommandOutput r = run_eomgen("ensemble " + model + " " + c.arguments);
    EXPECT_EQ(r.status, 2) << c.arguments << "\n" << r.err;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.arguments << "\n" << r.err;
  }
}

}  // namespace
}  // namespace eomgen::test
