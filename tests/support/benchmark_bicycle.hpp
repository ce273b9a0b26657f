/// @file The benchmark bicycle's published linearized equations (Meijaard et al. 2007),
/// M q'' + v C1 q' + (g K0 + v² K2) q = f, with their eigenvalues and the roots of their
/// largest real part: the reference the bicycle models are tested against.
#pragma once

#include <algorithm>
#include <complex>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "support/test_support.hpp"

namespace eomgen::test {

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

/// A sweep over v = 0 … 10 in 1001 points (its JSON summary and CSV) against the published
/// matrices: the weave and capsize speeds (recomputed here) to 1e-9, the stable interval
/// between them, and the eigenvalues at every point to 1e-10.
inline void expect_benchmark_sweep(const JsonValue& r, const std::string& csv) {
  Benchmark b;
  double weave = b.root(4, 4.5), capsize = b.root(5.5, 6.5);
  EXPECT_NEAR(weave, 4.29238253634, 1e-10) << "the published weave speed";
  EXPECT_NEAR(capsize, 6.02426201539, 1e-10) << "the published capsize speed";
  auto member = [](const JsonValue& v, const std::string& key) -> const JsonValue& {
    const JsonValue* m = v.find(key);
    if (!m) throw std::runtime_error("no member " + key);
    return *m;
  };
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
  auto rows = read_numeric_csv(csv);
  ASSERT_EQ(rows.size(), 1001u);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const auto& row = rows[k];
    ASSERT_EQ(row.size(), 9u);
    double v = row[0];
    EXPECT_NEAR(v, 0.01 * double(k), 1e-12);
    auto expected = b.eigenvalues(v);
    for (std::size_t i = 0; i < 4; ++i) {
      EXPECT_NEAR(row[1 + 2 * i], expected[i].real(), 1e-10 * std::max(1.0, std::abs(expected[i]))) << "v = " << v;
      EXPECT_NEAR(row[2 + 2 * i], expected[i].imag(), 1e-10 * std::max(1.0, std::abs(expected[i]))) << "v = " << v;
    }
  }
}

}  // namespace eomgen::test
