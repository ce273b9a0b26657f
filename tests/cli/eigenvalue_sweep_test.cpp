// `eomgen sweep` along one parameter: the benchmark bicycle's weave and capsize speeds
// (Meijaard et al. 2007) from models/whipple_linear.toml against the roots of the
// published matrices recomputed here, its eigenvalues at v = 0 … 10 against those of the
// matrices, and the rolling disk's critical spin Ω² = g/(3R) (Routh) where a real pair
// meets at zero and leaves the axis as an undamped oscillation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <fstream>

#include <Eigen/Dense>

#include "parse/json_reader.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

// the benchmark's published coefficient matrices, Meijaard et al. (2007) eqs. (A 20)-(A 22)
struct Benchmark {
  Eigen::Matrix2d M, C1, K0, K2;
  double g = 9.81;
  Benchmark() {
    M << 80.81722, 2.31941332208709, 2.31941332208709, 0.29784188199686;
    C1 << 0, 33.86641391492494, -0.85035641456978, 1.68540397397560;
    K0 << -80.95, -2.59951685249872, -2.59951685249872, -0.80329488458618;
    K2 << 0, 76.59734589573222, 0, 2.65431523794604;
  }
  std::vector<std::complex<double>> eigenvalues(double v) const {
    Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
    A.topRightCorner<2, 2>() = Eigen::Matrix2d::Identity();
    A.bottomLeftCorner<2, 2>() = -M.inverse() * (g * K0 + v * v * K2);
    A.bottomRightCorner<2, 2>() = -M.inverse() * (v * C1);
    Eigen::EigenSolver<Eigen::Matrix4d> solver(A, false);
    std::vector<std::complex<double>> out;
    for (int i = 0; i < 4; ++i) out.push_back(solver.eigenvalues()[i]);
    std::sort(out.begin(), out.end(), [](auto a, auto b) { return a.real() != b.real() ? a.real() > b.real() : a.imag() > b.imag(); });
    return out;
  }
  double largest_real_part(double v) const { return eigenvalues(v).front().real(); }
  // the root of the largest real part in [a, b], where it changes sign
  double root(double a, double b) const {
    bool positive_at_a = largest_real_part(a) > 0;
    while (b - a > 1e-13) {
      double mid = 0.5 * (a + b);
      ((largest_real_part(mid) > 0) == positive_at_a ? a : b) = mid;
    }
    return 0.5 * (a + b);
  }
};

const JsonValue& member(const JsonValue& v, const std::string& key) {
  const JsonValue* m = v.find(key);
  if (!m) throw std::runtime_error("no member " + key);
  return *m;
}

TEST(EigenvalueSweep, TheBenchmarkBicycleIsSelfStableBetweenItsWeaveAndCapsizeSpeeds) {
  Benchmark b;
  double weave = b.root(4, 4.5), capsize = b.root(5.5, 6.5);
  EXPECT_NEAR(weave, 4.29238253634, 1e-10) << "the published weave speed";
  EXPECT_NEAR(capsize, 6.02426201539, 1e-10) << "the published capsize speed";
  std::string dir = temporary_directory();
  JsonValue r = run_json("sweep '" + model_path("whipple_linear") + "' --param v=0:10:1001 -o '" + dir + "/v.csv' --plot '" +
                         dir + "/v.png'");
  const auto& crossings = member(r, "crossings").items;
  ASSERT_EQ(crossings.size(), 2u) << "the weave and the capsize speed";
  EXPECT_NEAR(at(crossings[0], "v"), weave, 1e-9);
  EXPECT_EQ(member(crossings[0], "kind").text, "oscillatory") << "the weave mode is a complex pair";
  EXPECT_EQ(member(crossings[0], "direction").text, "stabilizing");
  EXPECT_NEAR(at(crossings[1], "v"), capsize, 1e-9);
  EXPECT_EQ(member(crossings[1], "kind").text, "real") << "the capsize mode is a real eigenvalue";
  EXPECT_EQ(member(crossings[1], "direction").text, "destabilizing");
  const auto& stable = member(r, "stable_intervals").items;
  ASSERT_EQ(stable.size(), 1u);
  EXPECT_NEAR(at(stable[0], "low"), weave, 1e-9);
  EXPECT_NEAR(at(stable[0], "high"), capsize, 1e-9);
  // the eigenvalues at every whole speed against those of the published matrices
  auto rows = read_numeric_csv(dir + "/v.csv");
  ASSERT_EQ(rows.size(), 1001u);
  for (int v = 0; v <= 10; ++v) {
    const auto& row = rows[std::size_t(100 * v)];
    ASSERT_EQ(row.size(), 9u);
    EXPECT_EQ(row[0], v);
    auto expected = b.eigenvalues(v);
    for (std::size_t i = 0; i < 4; ++i) {
      EXPECT_NEAR(row[1 + 2 * i], expected[i].real(), 1e-10 * std::max(1.0, std::abs(expected[i]))) << "v = " << v;
      EXPECT_NEAR(row[2 + 2 * i], expected[i].imag(), 1e-10 * std::max(1.0, std::abs(expected[i]))) << "v = " << v;
    }
  }
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

}  // namespace
}  // namespace eomgen::test
