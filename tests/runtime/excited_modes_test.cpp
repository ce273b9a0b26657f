// Which modes a motion excites: the two-mass chain (m = 1, k = 100: ω = 10 with (1, 1)/√2 and
// ω = √300 with (1, −1)/√2) swinging in its first mode alone, then in both.
#include <gtest/gtest.h>

#include <cmath>

#include "analyse/excited_modes.hpp"

namespace eomgen::runtime {
namespace {

struct Chain {
  Eigen::MatrixXd M = Eigen::MatrixXd::Identity(2, 2), D = Eigen::MatrixXd::Zero(2, 2), K{{200, -100}, {-100, 200}};
};

// x(t) = a1 φ1 cos(ω1 t) + a2 φ2 cos(ω2 t), sampled on [0, 2]
std::vector<std::vector<double>> swing(double a1, double a2) {
  std::vector<std::vector<double>> states;
  double w1 = 10, w2 = std::sqrt(300.0), s = 1 / std::sqrt(2.0);
  for (int k = 0; k <= 400; ++k) {
    double t = 0.005 * k;
    double e1 = a1 * std::cos(w1 * t), e2 = a2 * std::cos(w2 * t);
    double r1 = -a1 * w1 * std::sin(w1 * t), r2 = -a2 * w2 * std::sin(w2 * t);
    states.push_back({s * (e1 + e2), s * (e1 - e2), s * (r1 + r2), s * (r1 - r2)});
  }
  return states;
}

TEST(ExcitedModes, AMotionInTheFirstModeNeedsItAlone) {
  Chain c;
  ModalAnalysis modes = modal_analysis(c.M, c.D, c.K);
  Eigen::MatrixXd C{{1, 0, 0, 0}};  // x1
  double range = 2 * 0.01 / std::sqrt(2.0);
  ExcitedModes e = excited_modes(modes, c.M, {0, 0}, swing(0.01, 0), C, {range}, 1e-4);
  ASSERT_EQ(e.share.size(), 2u);
  EXPECT_NEAR(e.share[0], 0.5, 1e-12) << "the amplitude 0.01/√2 of x1 over its range";
  EXPECT_LT(e.share[1], 1e-15);
  EXPECT_EQ(e.kept, (std::vector<std::size_t>{0}));
}

TEST(ExcitedModes, ASecondModeAboveTheBoundIsKeptAndOneBelowGoes) {
  Chain c;
  ModalAnalysis modes = modal_analysis(c.M, c.D, c.K);
  Eigen::MatrixXd C{{1, 0, 0, 0}};
  double range = 2 * 0.01 / std::sqrt(2.0);
  ExcitedModes both = excited_modes(modes, c.M, {0, 0}, swing(0.01, 1e-3), C, {range}, 1e-3);
  EXPECT_NEAR(both.share[1], 0.05, 1e-6);
  EXPECT_EQ(both.kept, (std::vector<std::size_t>{0, 1}));
  ExcitedModes faint = excited_modes(modes, c.M, {0, 0}, swing(0.01, 1e-7), C, {range}, 1e-3);
  EXPECT_NEAR(faint.share[1], 5e-6, 1e-10);
  EXPECT_EQ(faint.kept, (std::vector<std::size_t>{0}));
}

}  // namespace
}  // namespace eomgen::runtime
