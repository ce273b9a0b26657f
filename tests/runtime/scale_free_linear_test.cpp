// The analyses of x' = A x + B u, y = C x in the system's own scales: a pendulum hanging from a
// free cart, pushed by a force, with its time scaled by s and its masses by μ (1e-12 to 1e12 and
// 1e-9 to 1e9), and its states' units changed by powers of ten at random. Its transfer function
// from the force to the cart's position keeps its double pole at 0 (a free cart: G(0) infinite),
// its pendulum's poles and its zeros; it is controllable from the force, observable from the
// cart's position and, from the pendulum's angle, blind to the cart (two of four states).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <fmt/format.h>

#include "analyse/controllability.hpp"
#include "analyse/transfer_function.hpp"

namespace eomgen::test {
namespace {

constexpr double cart = 1.0, bob = 0.2, rod = 0.5;

// states x, θ, x', θ', each in units scaled by `units` (x = D x̃): (D⁻¹ A D, D⁻¹ B, C D)
struct CartSystem {
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(4, 4), B = Eigen::MatrixXd::Zero(4, 1);
  double omega = 0, omega0 = 0;  // the pendulum's frequency on the cart, and with the cart held
  CartSystem(double s, double mu, const Eigen::Vector4d& units) {
    double g = 9.81 * s * s;
    Eigen::Matrix2d M, K;
    M << mu * (cart + bob), mu * bob * rod, mu * bob * rod, mu * bob * rod * rod;
    K << 0, 0, 0, mu * bob * g * rod;
    A.topRightCorner(2, 2).setIdentity();
    A.bottomLeftCorner(2, 2) = -M.inverse() * K;
    B.bottomRows(2) = M.inverse() * Eigen::Vector2d(1, 0);
    A = units.cwiseInverse().asDiagonal() * A * units.asDiagonal();
    B = units.cwiseInverse().asDiagonal() * B;
    omega = std::sqrt(g * (cart + bob) / (cart * rod)), omega0 = std::sqrt(g / rod);
    this->units = units;
  }
  Eigen::MatrixXd reading(int state) const {
    Eigen::MatrixXd C = Eigen::MatrixXd::Zero(1, 4);
    C(0, state) = units[state];
    return C;
  }
  Eigen::Vector4d units;
};

std::vector<double> time_scales() { return {1e-12, 1e-9, 1e-6, 1e-3, 1, 1e3, 1e6, 1e9, 1e12}; }

Eigen::Vector4d random_units(std::mt19937& random) {
  std::uniform_int_distribution<int> power(-6, 6);
  Eigen::Vector4d units;
  for (int i = 0; i < 4; ++i) units[i] = std::pow(10.0, power(random));
  return units;
}

TEST(ScaleFreeLinear, AFreeCartsDoublePoleIsAtZeroAtEveryScale) {
  std::mt19937 random(11);
  for (double s : time_scales())
    for (double mu : {1e-9, 1.0, 1e9})
      for (bool in_other_units : {false, true}) {
        CartSystem c(s, mu, in_other_units ? random_units(random) : Eigen::Vector4d::Ones());
        runtime::TransferFunction G = runtime::transfer_function(c.A, c.B, c.reading(0), Eigen::MatrixXd::Zero(1, 1), 0, 0);
        std::string at = fmt::format("s = {:g}, mu = {:g}, units {}", s, mu, in_other_units);
        EXPECT_TRUE(std::isinf(G.dc_gain().real())) << at;
        ASSERT_EQ(G.poles.size(), 4u) << at;
        int at_zero = 0, at_omega = 0;
        for (auto p : G.poles) {
          at_zero += p == std::complex<double>(0, 0);
          at_omega += p.real() == 0 && std::abs(std::abs(p.imag()) - c.omega) <= 1e-9 * c.omega;
        }
        EXPECT_EQ(at_zero, 2) << at;
        EXPECT_EQ(at_omega, 2) << at;
        ASSERT_EQ(G.zeros.size(), 2u) << at;
        for (auto z : G.zeros) EXPECT_NEAR(std::abs(z.imag()), c.omega0, 1e-9 * c.omega0) << at;
        EXPECT_NEAR(G.gain / (1 / (mu * cart)), 1, 1e-9) << at;
      }
}

// The tolerance had been 1e-9 max(1, |A|, |B|) on Kalman's matrix: a cart of 1e-9 kg (|B| = 1e9)
// was "NOT controllable (rank 2 of 4)", one of 1e9 kg "rank 0 of 4".
TEST(ScaleFreeLinear, AFreeCartIsControllableAndObservableFromItsPositionAtEveryScale) {
  std::mt19937 random(12);
  for (double s : time_scales())
    for (double mu : {1e-9, 1.0, 1e9})
      for (bool in_other_units : {false, true}) {
        CartSystem c(s, mu, in_other_units ? random_units(random) : Eigen::Vector4d::Ones());
        std::string at = fmt::format("s = {:g}, mu = {:g}, units {}", s, mu, in_other_units);
        runtime::Reach from_position = runtime::controllability_and_observability(c.A, c.B, c.reading(0));
        EXPECT_EQ(from_position.kalman_controllability_rank, 4) << at;
        EXPECT_EQ(from_position.kalman_observability_rank, 4) << at;
        EXPECT_TRUE(from_position.controllable) << at;
        EXPECT_TRUE(from_position.observable) << at;
        // the angle's equation holds no x: the cart's position and speed are unseen, its double
        // eigenvalue 0 a mode that PBH names, moving x alone
        runtime::Reach from_angle = runtime::controllability_and_observability(c.A, c.B, c.reading(1));
        EXPECT_EQ(from_angle.kalman_observability_rank, 2) << at;
        EXPECT_FALSE(from_angle.observable) << at;
        for (const runtime::ModeReach& m : from_angle.modes) {
          bool at_zero = std::abs(m.eigenvalue) <= 1e-6 * c.omega;
          EXPECT_EQ(m.observable, !at_zero) << at << ", eigenvalue " << m.eigenvalue;
          if (at_zero && !m.observable) {
            ASSERT_EQ(m.unseen.size(), 4) << at;
            EXPECT_GT(std::abs(m.unseen[0]), 0.99 * m.unseen.norm()) << at;
          }
        }
      }
}

}  // namespace
}  // namespace eomgen::test
