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
#include "analyse/jordan_chains.hpp"
#include "analyse/linear_stability.hpp"
#include "analyse/principal_coordinates.hpp"
#include "analyse/system_scales.hpp"
#include "analyse/transfer_function.hpp"

namespace eomgen::test {
namespace {

constexpr double cart = 1.0, bob = 0.2, rod = 0.5;

// states x, θ, x', θ', each in units scaled by `units` (x = D x̃): (D⁻¹ A D, D⁻¹ B, C D)
struct CartSystem {
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(4, 4), B = Eigen::MatrixXd::Zero(4, 1);
  double omega = 0, omega0 = 0;  // the pendulum's frequency on the cart, and with the cart held
  double mu;                     // the masses' scale
  CartSystem(double s, double masses, const Eigen::Vector4d& units) : mu(masses) {
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

// `check(c, at)` on the cart at every time scale, masses 1e-9, 1 and 1e9, in its own units and in
// random ones (drawn from `seed`), `at` naming the case
template <class Check>
void for_each_cart(unsigned seed, const Check& check) {
  std::mt19937 random(seed);
  for (double s : time_scales())
    for (double mu : {1e-9, 1.0, 1e9})
      for (bool in_other_units : {false, true}) {
        CartSystem c(s, mu, in_other_units ? random_units(random) : Eigen::Vector4d::Ones());
        check(c, fmt::format("s = {:g}, mu = {:g}, units {}", s, mu, in_other_units));
      }
}

TEST(ScaleFreeLinear, AFreeCartsDoublePoleIsAtZeroAtEveryScale) {
  for_each_cart(11, [](const CartSystem& c, const std::string& at) {
    runtime::TransferFunction G = runtime::transfer_function(c.A, c.B, c.reading(0), Eigen::MatrixXd::Zero(1, 1), 0, 0);
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
    EXPECT_NEAR(G.gain / (1 / (c.mu * cart)), 1, 1e-9) << at;
  });
}

// The come-to-rest searches step by the fastest rate and damp by the slowest: the free cart's
// double pole at 0 (split by rounding to about √ε of ω) sets no rate, so both are the pendulum's
// ω, in any units; a NaN in A gives NaN rates, not the finite ones of its other entries.
TEST(ScaleFreeLinear, AFreeCartsRatesAreItsPendulumsAtEveryScale) {
  for_each_cart(17, [](const CartSystem& c, const std::string& at) {
    runtime::RateRange range = runtime::rate_range(c.A);
    EXPECT_NEAR(range.fastest / c.omega, 1, 1e-9) << at;
    EXPECT_NEAR(range.slowest / c.omega, 1, 1e-9) << at;
    Eigen::MatrixXd broken = c.A;
    broken(0, 1) = std::nan("");
    runtime::RateRange none = runtime::rate_range(broken);
    EXPECT_TRUE(std::isnan(none.fastest) && std::isnan(none.slowest)) << at;
  });
}

// The tolerance had been 1e-9 max(1, |A|, |B|) on Kalman's matrix: a cart of 1e-9 kg (|B| = 1e9)
// was "NOT controllable (rank 2 of 4)", one of 1e9 kg "rank 0 of 4".
TEST(ScaleFreeLinear, AFreeCartIsControllableAndObservableFromItsPositionAtEveryScale) {
  for_each_cart(12, [](const CartSystem& c, const std::string& at) {
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
  });
}

// |A V − V J| column by column in the states' own units (D the units times (1, 1, rate, rate),
// where every entry of D⁻¹ A D is of the rate's size), against the rounding of each column
void expect_similar(const Eigen::MatrixXd& A, const Eigen::MatrixXcd& V, const Eigen::MatrixXcd& J,
                    const Eigen::Vector4d& units, double rate, const std::string& at) {
  Eigen::Vector4d d = units.cwiseProduct(Eigen::Vector4d(1, 1, rate, rate));
  auto in_units = [&](const Eigen::MatrixXcd& X) { return Eigen::MatrixXcd(d.cwiseInverse().cast<std::complex<double>>().asDiagonal() * X); };
  Eigen::MatrixXcd residual = in_units(A.cast<std::complex<double>>() * V - V * J), columns = in_units(V);
  for (Eigen::Index k = 0; k < V.cols(); ++k) {
    double bound = rate * columns.col(k).norm() + (k > 0 ? std::abs(J(k - 1, k)) * columns.col(k - 1).norm() : 0.0);
    EXPECT_LE(residual.col(k).norm(), 1e-9 * bound) << at << ", column " << k;
  }
}

// The chains had been the null spaces of (A − λI)^k in the states' units: with the cart's
// position in μm and its speed in km/s, they are (nearly) dependent, or miss the block.
TEST(ScaleFreeLinear, AFreeCartsJordanChainIsFoundAtEveryScale) {
  for_each_cart(13, [](const CartSystem& c, const std::string& at) {
    runtime::JordanBasis basis = runtime::jordan_basis(c.A, runtime::jordan_structure(c.A));
    ASSERT_TRUE(basis.refusal.empty()) << at << ": " << basis.refusal;
    Eigen::MatrixXcd J = Eigen::MatrixXcd::Zero(4, 4);
    int double_zero = 0;
    for (const runtime::JordanBasis::Block& b : basis.blocks) {
      bool at_zero = std::abs(b.eigenvalue) <= 1e-9 * c.omega;
      double_zero += at_zero && b.size == 2;
      if (!at_zero) {
        EXPECT_NEAR(std::abs(b.eigenvalue.imag()), c.omega, 1e-9 * c.omega) << at;
      }
      for (int i = 0; i < b.size; ++i) {
        J(b.first + i, b.first + i) = b.eigenvalue;
        if (i + 1 < b.size) J(b.first + i, b.first + i + 1) = 1;
      }
    }
    EXPECT_EQ(double_zero, 1) << at;
    expect_similar(c.A, basis.V, J, c.units, c.omega, at);
    EXPECT_LT(basis.residual, 1e-12) << at;  // as reported, relative to each column's terms
  });
}

// A cart held by a spring and a damper (damping not proportional): the principal coordinates are
// A's eigenvectors. Eigen's solver, which does not balance, had put them 1 % off on a time
// scale of 1e6; here V Λ V⁻¹ = A and V (V⁻¹ B) = B in the states' own units at every scale.
TEST(ScaleFreeLinear, ADampedCartsEigenvectorsAreAccurateAtEveryScale) {
  std::mt19937 random(14);
  for (double s : time_scales())
    for (bool in_other_units : {false, true}) {
      CartSystem c(s, 1.0, in_other_units ? random_units(random) : Eigen::Vector4d::Ones());
      // k = m_cart ω² and d = 0.1 m_cart ω on the cart, in the system's units
      Eigen::MatrixXd A = c.A, to_units = c.units.asDiagonal();
      Eigen::MatrixXd spring = Eigen::MatrixXd::Zero(4, 4);
      spring(2, 0) = -c.omega * c.omega, spring(2, 2) = -0.1 * c.omega;
      Eigen::MatrixXd Mi = Eigen::MatrixXd::Identity(4, 4);
      Mi.bottomRightCorner(2, 2) << cart + bob, bob * rod, bob * rod, bob * rod * rod;
      Mi.bottomRightCorner(2, 2) = Eigen::Matrix2d(Mi.bottomRightCorner(2, 2)).inverse() * cart;
      A += to_units.inverse() * Mi * spring * to_units;
      std::string at = fmt::format("s = {:g}, units {}", s, in_other_units);
      runtime::PrincipalCoordinates p =
          runtime::principal_coordinates(runtime::ModalAnalysis{}, Eigen::MatrixXd(2, 1), A, c.B, runtime::jordan_structure(A));
      ASSERT_EQ(p.kind, "eigenvectors") << at;
      Eigen::MatrixXcd L = Eigen::MatrixXcd::Zero(4, 4);
      for (Eigen::Index k = 0; k < 4; ++k) L(k, k) = p.eigenvalues[std::size_t(k)];
      expect_similar(A, p.eigenvectors, L, c.units, c.omega, at);
      Eigen::Vector4d d = c.units.cwiseProduct(Eigen::Vector4d(1, 1, c.omega, c.omega));
      Eigen::VectorXcd input = d.cwiseInverse().cast<std::complex<double>>().asDiagonal() *
                               (p.eigenvectors * p.eigen_inputs - c.B.cast<std::complex<double>>());
      EXPECT_LE(input.norm(), 1e-9 * d.cwiseInverse().cwiseProduct(c.B.col(0)).norm()) << at;
      // det(λ² M + λ D + K) / det M with k = m_c ω², d = 0.1 m_c ω, m_b g r for the pendulum
      double g = 9.81 * s * s, k = cart * c.omega * c.omega, damping = 0.1 * cart * c.omega;
      std::vector<double> exact{1, damping / cart, (cart + bob) * g / (cart * rod) + k / cart, damping * g / (cart * rod),
                                k * g / (cart * rod)};
      std::vector<double> coefficients = runtime::polynomial_from_roots(runtime::balanced_eigenvalues(A));
      ASSERT_EQ(coefficients.size(), exact.size()) << at;
      for (std::size_t i = 0; i < exact.size(); ++i)
        EXPECT_NEAR(coefficients[i], exact[i], 1e-9 * std::pow(c.omega, double(i)) * (i + 1)) << at << ", λ^" << 4 - i;
    }
}

}  // namespace
}  // namespace eomgen::test
