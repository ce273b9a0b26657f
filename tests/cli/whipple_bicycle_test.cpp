// The nonlinear Whipple bicycle of models/whipple_bicycle.toml (frames, two rolling
// wheels, Lagrange I on its constraint manifold) against the benchmark of Meijaard et
// al. (2007): its linearization gives the published M, C1, K0 and K2 to 1e-12 relative
// (M from the response to the roll and steer torques, C1 from one speed, K0 and K2 from
// two), its eigenvalues at v = 0 … 10 are those of the published matrices to 1e-10, the
// weave and capsize speeds of `eomgen sweep` their roots to 1e-9; a simulation from a
// small roll rate decays at 4.6 m/s and grows (the weave) at 3 m/s, and keeps its energy.
// One test: the model compiles once (a minute or two) into the shared cache.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "support/benchmark_bicycle.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

Eigen::MatrixXd matrix(const JsonValue& v) {
  Eigen::MatrixXd m(static_cast<long>(v.items.size()), static_cast<long>(v.items.at(0).items.size()));
  for (long i = 0; i < m.rows(); ++i)
    for (long j = 0; j < m.cols(); ++j) m(i, j) = v.items[std::size_t(i)].items[std::size_t(j)].value;
  return m;
}

// M, K = g K0 + v² K2 and C = v C1 of the roll and steer equations at speed v, read off
// x' = A x + B u on the reduced state [phi, delta, der(phi), der(delta)] with u = [T_phi, T_delta]
struct RollSteer {
  Eigen::Matrix2d M, K, C;
};

RollSteer linearized_at(double v) {
  JsonValue r = run_json(fmt::format("stability '{}' --set v={}", model_path("whipple_bicycle"), v));
  std::vector<std::string> state;
  for (const JsonValue& name : r.find("state")->items) state.push_back(name.text);
  EXPECT_EQ(state, (std::vector<std::string>{"phi", "delta", "der(phi)", "der(delta)"}));
  Eigen::MatrixXd A = matrix(*r.find("A")), B = matrix(*r.find("B"));
  RollSteer s;
  s.M = B.bottomRows(2).inverse();
  s.K = -s.M * A.bottomLeftCorner(2, 2);
  s.C = -s.M * A.bottomRightCorner(2, 2);
  return s;
}

void expect_published(const Eigen::Matrix2d& derived, const Eigen::Matrix2d& published, const char* name) {
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      EXPECT_NEAR(derived(i, j), published(i, j), 1e-12 * std::max(std::abs(published(i, j)), 1e-3 * published.cwiseAbs().maxCoeff()))
          << name << "[" << i << "][" << j << "]";
}

// the largest |phi| over the rows with t in [from, to]
double largest_roll(const std::vector<std::vector<double>>& rows, std::size_t phi, double from, double to) {
  double largest = 0;
  for (const auto& row : rows)
    if (row[0] >= from && row[0] <= to) largest = std::max(largest, std::abs(row[phi]));
  return largest;
}

TEST(WhippleBicycle, TheNonlinearModelReproducesTheBenchmark) {
  Benchmark published;
  {
    SCOPED_TRACE("M, C1, K0, K2 from the linearization at v = 2 and 5 m/s");
    RollSteer slow = linearized_at(2), fast = linearized_at(5);
    Eigen::Matrix2d K2 = (fast.K - slow.K) / (25.0 - 4.0), K0 = (slow.K - 4.0 * K2) / published.g;
    expect_published(slow.M, published.M, "M");
    expect_published(fast.M, published.M, "M");
    expect_published(fast.C / 5.0, published.C1, "C1");
    expect_published(slow.C / 2.0, published.C1, "C1");
    expect_published(K0, published.K0, "K0");
    expect_published(K2, published.K2, "K2");
  }
  {
    SCOPED_TRACE("eomgen sweep --param v=0:10:1001");
    std::string dir = temporary_directory();
    JsonValue r = run_json("sweep '" + model_path("whipple_bicycle") + "' --param v=0:10:1001 -o '" + dir + "/v.csv'");
    expect_benchmark_sweep(r, dir + "/v.csv");
  }
  for (double v : {4.6, 3.0}) {
    SCOPED_TRACE(fmt::format("a simulation at v = {} from der(phi) = 0.01", v));
    std::string dir = temporary_directory();
    JsonValue r = run_json(fmt::format("simulate '{}' --set v={} --initial 'der(phi)=0.01' --t-end {} --dt-out 0.01 "
                                       "-o '{}/run.csv'", model_path("whipple_bicycle"), v, v > 4 ? 10 : 3, dir));
    std::string header;
    auto rows = read_numeric_csv(dir + "/run.csv", &header);
    ASSERT_GT(rows.size(), 100u);
    std::size_t phi = 1;
    ASSERT_EQ(header.rfind("t,phi,delta,thetaR,x,y,psi,thetaF,theta,", 0), 0u) << header;
    double early = largest_roll(rows, phi, 0, 1), late = largest_roll(rows, phi, rows.back()[0] - 1, rows.back()[0]);
    if (v > 4) {
      EXPECT_LT(late, early / 10) << "self-stable: every eigenvalue has a negative real part at 4.6 m/s";
      EXPECT_LT(at(r, "relative_energy_drift"), 1e-6) << "no inputs, no dissipation: T + V is kept";
    } else {
      // the weave's real part is 1.71 /s at 3 m/s: over the two seconds between the windows, e^3.4 ≈ 30
      EXPECT_GT(late, 10 * early) << "the weave grows at 3 m/s";
    }
  }
  {
    SCOPED_TRACE("a steer angle given: the pitch is solved for, roll and steer are kept");
    std::string dir = temporary_directory();
    CommandOutput r = run_eomgen("simulate '" + model_path("whipple_bicycle") + "' --initial delta=0.1 --t-end 0.01 -o '" +
                                 dir + "/run.csv'");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err.find("do not allow"), std::string::npos) << r.err;
    std::string header;
    auto rows = read_numeric_csv(dir + "/run.csv", &header);
    ASSERT_FALSE(rows.empty());
    EXPECT_EQ(rows[0][1], 0.0) << "phi as in the model file";
    EXPECT_EQ(rows[0][2], 0.1) << "delta as given";
    EXPECT_GT(std::abs(rows[0][8]), 1e-5) << "the pitch that keeps the front wheel on the ground";
    std::size_t residual = std::size_t(std::count(header.begin(), header.begin() + long(header.find("position_residual")), ','));
    EXPECT_LT(std::abs(rows[0][residual]), 1e-12) << header;
  }
}

}  // namespace
}  // namespace eomgen::test
