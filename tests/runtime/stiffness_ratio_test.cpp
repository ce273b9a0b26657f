// The stiffness ratio that chooses the default integrator (runtime/analyse/work_precision.hpp):
// fastest decay over slowest rate of known spectra, hidden by a random similarity so that rounding
// mixes them, at time scales from 1e-12 to 1e12 and in states of units from 1e-8 to 1e8; a free
// coordinate (a Jordan chain at zero, split by rounding) is no slow rate, and a slow decay far
// below the fastest one is.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "analyse/work_precision.hpp"

namespace eomgen::test {
namespace {

// blocks on the diagonal: a decay -1, a decay -fast, an undamped oscillation at 10 rad/s and, when
// asked, the Jordan chain [0 fast; 0 0] of a free coordinate and its rate (in units that make the
// chain's entry as large as the fast decay: rounding then splits it into ±1e-8 of the scale)
Eigen::MatrixXd spectrum(double fast, bool free_coordinate) {
  std::size_t n = free_coordinate ? 6 : 4;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(Eigen::Index(n), Eigen::Index(n));
  A(0, 0) = -1, A(1, 1) = -fast, A(2, 3) = 10, A(3, 2) = -10;
  if (free_coordinate) A(4, 5) = fast;
  return A;
}

// T A T^-1 with T random and well conditioned, times `time_scale`, in states scaled by powers of ten
Eigen::MatrixXd hidden(const Eigen::MatrixXd& A, double time_scale, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> entry(-1, 1);
  Eigen::MatrixXd T = Eigen::MatrixXd::Identity(A.rows(), A.cols()) * 3;
  for (Eigen::Index i = 0; i < T.rows(); ++i)
    for (Eigen::Index j = 0; j < T.cols(); ++j) T(i, j) += entry(random);
  Eigen::VectorXd units(A.rows());
  for (Eigen::Index i = 0; i < units.size(); ++i) units(i) = std::pow(10.0, double(8 - 16 * i / (units.size() - 1)));
  Eigen::MatrixXd B = T * A * T.inverse() * time_scale;
  return units.asDiagonal() * B * units.cwiseInverse().asDiagonal();
}

TEST(StiffnessRatio, AFreeCoordinateIsNoSlowRateAtAnyScale) {
  for (double time_scale : {1e-12, 1e-6, 1.0, 1e6, 1e12})
    for (unsigned seed : {1u, 2u, 3u}) {
      SCOPED_TRACE(testing::Message() << "time scale " << time_scale << ", seed " << seed);
      EXPECT_NEAR(runtime::stiffness_ratio_of(hidden(spectrum(1e4, false), time_scale, seed)), 1e4, 1e-6 * 1e4);
      // the chain's eigenvalues come out near ±1e-8 of the scale: before, the slowest rate
      EXPECT_NEAR(runtime::stiffness_ratio_of(hidden(spectrum(1e4, true), time_scale, seed)), 1e4, 1e-6 * 1e4);
      EXPECT_NEAR(runtime::stiffness_ratio_of(hidden(spectrum(50, true), time_scale, seed)), 50, 1e-6 * 50);
    }
}

// a decay of 1 beside one of 1e8: within the cluster tolerance of zero, it is still the slowest rate
TEST(StiffnessRatio, ASlowDecayFarBelowTheFastestIsARate) {
  for (double time_scale : {1e-12, 1.0, 1e12})
    for (bool free_coordinate : {false, true}) {
      SCOPED_TRACE(testing::Message() << "time scale " << time_scale << (free_coordinate ? ", a free coordinate" : ""));
      EXPECT_NEAR(runtime::stiffness_ratio_of(hidden(spectrum(1e8, free_coordinate), time_scale, 4)), 1e8, 1e-3 * 1e8);
    }
}

TEST(StiffnessRatio, NoDecayIsNoStiffnessAndNoNumberIsNone) {
  Eigen::MatrixXd oscillator = Eigen::MatrixXd::Zero(4, 4);
  oscillator(0, 1) = 1e3, oscillator(1, 0) = -1e3, oscillator(2, 3) = 1;
  EXPECT_LT(runtime::stiffness_ratio_of(hidden(oscillator, 1.0, 5)), 1e-6) << "about zero: rounding's real parts";
  EXPECT_EQ(runtime::stiffness_ratio_of(Eigen::MatrixXd::Zero(3, 3)), 0.0);
  Eigen::MatrixXd broken = Eigen::MatrixXd::Identity(2, 2);
  broken(0, 1) = NAN;
  EXPECT_TRUE(std::isnan(runtime::stiffness_ratio_of(broken)));
}

}  // namespace
}  // namespace eomgen::test
