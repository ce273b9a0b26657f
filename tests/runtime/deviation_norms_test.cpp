// How the critical case's runs measure a deviation (runtime/analyse/deviation_norms.hpp), on the
// pendulum's two states with linearizations set here: an undamped oscillation of frequency w keeps
// its modal amplitude exactly along e^{At} (w from 1e-12 to 1e12, pushed in either state), a damped
// one shrinks, and a Jordan block, exact or split by rounding, is refused the modal measure, whose
// large cancelling amplitudes would hide its secular growth.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "analyse/deviation_norms.hpp"
#include "generated/header_registry.hpp"

namespace eomgen::test {
namespace {

using runtime::DeviationNorm;

const eomgen_model_abi& pendulum() { return *generated_model("pendulum").abi; }

runtime::StabilityReport linearization(const Eigen::Matrix2d& A) {
  runtime::StabilityReport r;
  r.A = A;  // no M and K: the linearization's energy is not offered
  return r;
}

// x'' = −w² x − 2 ζ w x' from the push (x0, v0), in closed form
Eigen::Vector2d oscillation(double w, double zeta, double x0, double v0, double t) {
  double wd = w * std::sqrt(1 - zeta * zeta), decay = std::exp(-zeta * w * t);
  double b = (v0 + zeta * w * x0) / wd;
  double x = decay * (x0 * std::cos(wd * t) + b * std::sin(wd * t));
  double v = decay * (-zeta * w * (x0 * std::cos(wd * t) + b * std::sin(wd * t)) + wd * (-x0 * std::sin(wd * t) + b * std::cos(wd * t)));
  return {x, v};
}

TEST(DeviationNorms, AnUndampedOscillationKeepsItsModalAmplitudeAtEveryScale) {
  for (double w : {1e-12, 1.0, 1e12}) {
    Eigen::Matrix2d A{{0, 1}, {-w * w, 0}};
    std::vector<double> x{0, 0}, size{1e-2, 1e-2 * w};
    DeviationNorm norm(pendulum(), linearization(A), x, size);
    ASSERT_EQ(norm.kind(), DeviationNorm::Kind::modal_amplitudes) << "w = " << w;
    for (Eigen::Vector2d push : {Eigen::Vector2d(1e-2, 0), Eigen::Vector2d(0, 1e-2 * w)}) {
      double start = norm({push[0], push[1]});
      for (double phase : {0.3, 1.1, 2.0, 4.4, 100.0}) {
        Eigen::Vector2d y = oscillation(w, 0, push[0], push[1], phase / w);
        EXPECT_NEAR(norm({y[0], y[1]}) / start, 1, 1e-12) << "w = " << w << ", phase " << phase;
      }
    }
  }
}

TEST(DeviationNorms, ADampedOscillationShrinksInIt) {
  double w = 3e5, zeta = 0.01;
  Eigen::Matrix2d A{{0, 1}, {-w * w, -2 * zeta * w}};
  DeviationNorm norm(pendulum(), linearization(A), {0, 0}, {1e-2, 1e-2 * w});
  ASSERT_EQ(norm.kind(), DeviationNorm::Kind::modal_amplitudes);
  double start = norm({0, 1e-2 * w}), last = start;
  for (double phase : {0.5, 1.0, 2.0, 4.0, 8.0}) {
    Eigen::Vector2d y = oscillation(w, zeta, 0, 1e-2 * w, phase / w);
    double now = norm({y[0], y[1]});
    EXPECT_LE(now, last * (1 + 1e-12)) << "phase " << phase;
    EXPECT_NEAR(now / start, std::exp(-zeta * phase), 1e-12) << "phase " << phase;
    last = now;
  }
}

// x'' = 0 (a free mass's Jordan block) and x'' = −(1e-9)² x at unit sizes (the block split by
// rounding: its eigenvectors agree to 1e-9): each state in its own size instead
TEST(DeviationNorms, AJordanBlockIsMeasuredPerStateExactOrSplitByRounding) {
  for (double w : {0.0, 1e-9}) {
    Eigen::Matrix2d A{{0, 1}, {-w * w, 0}};
    DeviationNorm norm(pendulum(), linearization(A), {0, 0}, {1, 1});
    EXPECT_EQ(norm.kind(), DeviationNorm::Kind::per_state) << "w = " << w;
    EXPECT_DOUBLE_EQ(norm({0.5, -2.0}), 2.0);
    EXPECT_EQ(norm.measure(), "");
  }
}

TEST(DeviationNorms, ALagrangeModelWithAStiffnessTakesItsEnergy) {
  runtime::StabilityReport r = linearization(Eigen::Matrix2d{{0, 1}, {-4, 0}});
  r.M = Eigen::MatrixXd::Constant(1, 1, 2.0);
  r.K = Eigen::MatrixXd::Constant(1, 1, 8.0);
  DeviationNorm norm(pendulum(), r, {0.1, 0}, {1e-3, 2e-3});
  ASSERT_EQ(norm.kind(), DeviationNorm::Kind::linear_energy);
  // ½ 2 v² + ½ 8 δx², at δx = 0.5, v = 1: 1 + 1
  EXPECT_NEAR(norm({0.6, 1.0}), std::sqrt(2.0), 1e-15);
}

// Hamilton's pendulum at rest, q' = p/(m l²), p' = −m g l q, at masses 1e-12 … 1e12 kg and rates
// 1e6 … 1e-6 1/s: its kinetic energy's Hessian in p is 1/(m l²) and the stiffness that keeps the sum
// constant m g l, so the measure is √(½ δp²/(m l²) + ½ m g l δq²), K read off A and T alone. Moving
// (p ≠ 0), or without the parameters for T, it is not measured in energy.
TEST(DeviationNorms, AFirstOrderFormAtRestTakesTheEnergyOfItsLinearization) {
  const eomgen_model_abi& hamilton = *generated_model("pendulum_hamilton").abi;
  for (auto [m, w] : {std::pair{1e-12, 1e6}, std::pair{1.0, 1.0}, std::pair{1e12, 1e-6}}) {
    double l = 2, g = w * w * l, inertia = m * l * l;
    std::vector<double> parameters{m, l, g, 0};  // m, l, g, d
    runtime::StabilityReport r = linearization(Eigen::Matrix2d{{0, 1 / inertia}, {-m * g * l, 0}});
    std::vector<double> size{1e-2, 1e-2 * inertia * w};
    DeviationNorm norm(hamilton, r, {0, 0}, size, parameters.data());
    ASSERT_EQ(norm.kind(), DeviationNorm::Kind::linear_energy) << "m = " << m;
    EXPECT_NE(norm.measure().find("M_s"), std::string::npos) << norm.measure();
    double dq = 3e-3, dp = -2e-3 * inertia * w;
    EXPECT_NEAR(norm({dq, dp}) / std::sqrt(0.5 * dp * dp / inertia + 0.5 * m * g * l * dq * dq), 1, 1e-12) << "m = " << m;
    EXPECT_NE(DeviationNorm(hamilton, r, {0, 0.1 * inertia * w}, size, parameters.data()).kind(),
              DeviationNorm::Kind::linear_energy) << "m = " << m;
    EXPECT_NE(DeviationNorm(hamilton, r, {0, 0}, size).kind(), DeviationNorm::Kind::linear_energy) << "m = " << m;
  }
}

}  // namespace
}  // namespace eomgen::test
