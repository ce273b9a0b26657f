// `eomgen bench` at a reduced size (the full run is in the README): it writes the
// report, the runs and the charts; the error of every adaptive method falls as its
// tolerance tightens; fixed-step RK4 shows order 4 and Störmer–Verlet order 2.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

namespace fs = std::filesystem;

struct Run {
  double rtol, step, error;
};

std::map<std::string, std::vector<Run>> read_runs(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::map<std::string, std::vector<Run>> runs;
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::string name, cell;
    std::getline(s, name, ',');
    std::vector<double> v;
    while (std::getline(s, cell, ',')) v.push_back(std::stod(cell));
    runs[name].push_back({v[0], v[1], v[2]});
  }
  return runs;
}

// least-squares slope of log error against log step, from the largest step while the error halves
double slope(const std::vector<Run>& runs, double low, double high) {
  std::vector<double> x, y;
  double previous = INFINITY;
  for (const Run& r : runs) {  // written from the largest step down
    if (r.error > high) continue;
    if (r.error < low || !(r.error < previous / 2)) break;
    previous = r.error;
    x.push_back(std::log(r.step));
    y.push_back(std::log(r.error));
  }
  if (x.size() < 3) return NAN;
  double mx = 0, my = 0, sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < x.size(); ++i) mx += x[i] / x.size(), my += y[i] / x.size();
  for (std::size_t i = 0; i < x.size(); ++i) sxy += (x[i] - mx) * (y[i] - my), sxx += (x[i] - mx) * (x[i] - mx);
  return sxy / sxx;
}

class Bench : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    directory_ = new std::string(temporary_directory() + "/bench");
    status_ = run_command("EOMGEN_CACHE_DIR='" + std::string(EOMGEN_BINARY_DIR) + "/test-cache' '" +
                          std::string(EOMGEN_EXECUTABLE) + "' bench '" + model_path("double_pendulum") +
                          "' --t-end 2 --dt-out 0.1 --tolerances 1e-3:1e-9:10 -o '" + *directory_ + "' > '" +
                          *directory_ + ".out' 2>&1");
  }
  static void TearDownTestSuite() { delete directory_; }
  static std::string* directory_;
  static int status_;
};
std::string* Bench::directory_ = nullptr;
int Bench::status_ = -1;

TEST_F(Bench, WritesTheReportRunsAndCharts) {
  ASSERT_EQ(status_, 0) << read_file(*directory_ + ".out");
  for (const char* file : {"report.md", "runs.csv", "work_precision.png", "work_precision.svg", "error_vs_evaluations.png",
                           "error_vs_evaluations.svg", "energy_error.png", "energy_error.svg"})
    EXPECT_TRUE(fs::exists(*directory_ + "/" + file)) << file;
  std::string report = read_file(*directory_ + "/report.md");
  EXPECT_NE(report.find("## Verdict"), std::string::npos);
  EXPECT_NE(report.find("cheapest"), std::string::npos);
  // an undamped oscillation has no meaningful stiffness ratio (it was printed as 1.27e-16)
  EXPECT_NE(report.find("Stiffness at the start: not stiff"), std::string::npos) << report;
  EXPECT_EQ(report.find("e-16"), std::string::npos) << report;
}

TEST_F(Bench, ErrorFallsWithTheToleranceForEveryAdaptiveMethod) {
  ASSERT_EQ(status_, 0);
  auto runs = read_runs(*directory_ + "/runs.csv");
  for (const char* name : {"cvode-bdf", "cvode-adams", "arkode-dp5", "arkode-verner", "arkode-dirk"}) {
    const auto& r = runs[name];
    ASSERT_EQ(r.size(), 7u) << name;
    for (std::size_t k = 1; k < r.size(); ++k)
      EXPECT_LT(r[k].error, r[k - 1].error) << name << " at rtol " << r[k].rtol;
    EXPECT_LT(r.back().error, 1e-4 * r.front().error) << name;
  }
}

TEST_F(Bench, FixedStepMethodsShowTheirOrder) {
  ASSERT_EQ(status_, 0);
  auto runs = read_runs(*directory_ + "/runs.csv");
  double rk4 = slope(runs["rk4"], 1e-11, 1e-3), verlet = slope(runs["verlet"], 1e-11, 1e-2);
  EXPECT_GE(rk4, 3.7);
  EXPECT_LE(rk4, 4.3);
  EXPECT_GE(verlet, 1.8);
  EXPECT_LE(verlet, 2.2);
}

}  // namespace
}  // namespace eomgen::test
