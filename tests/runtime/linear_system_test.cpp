// The solution of linear systems (Hiller §6, §8.1) against closed forms written here:
// the Jordan structure of a matrix with a known block of size 3, a nearly defective
// matrix reported as uncertain, e^{At} of a rotation, and the modes of the symmetric
// problem K v = ω² M v: the two-mass chain with Rayleigh damping, a free-free chain
// with its rigid-body mode, and nonproportional damping.
#include <gtest/gtest.h>

#include <cmath>

#include "analyse/jordan_chains.hpp"
#include "analyse/linear_system.hpp"
#include "analyse/linear_stability.hpp"
#include "analyse/modal_analysis.hpp"

namespace eomgen::runtime {
namespace {

TEST(JordanStructure, ABlockOfSizeThreeAndASimpleEigenvalue) {
  // J = J3(2) ⊕ (−1), hidden by a similarity with a well-conditioned P
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(4, 4), P(4, 4);
  J << 2, 1, 0, 0, 0, 2, 1, 0, 0, 0, 2, 0, 0, 0, 0, -1;
  P << 1, 0.5, 0, 0.2, 0, 1, 0.3, 0, 0.1, 0, 1, 0.4, 0, 0.2, 0, 1;
  JordanStructure s = jordan_structure(P * J * P.inverse());
  ASSERT_EQ(s.eigenvalues.size(), 2u);
  EXPECT_NEAR(s.eigenvalues[0].value.real(), 2, 1e-4);
  EXPECT_EQ(s.eigenvalues[0].algebraic_multiplicity, 3);
  EXPECT_EQ(s.eigenvalues[0].geometric_multiplicity, 1);
  EXPECT_EQ(s.eigenvalues[0].jordan_blocks, (std::vector<int>{3}));
  EXPECT_EQ(s.eigenvalues[1].jordan_blocks, (std::vector<int>{1}));
  EXPECT_FALSE(s.uncertain);
}

// V⁻¹ A V against the Jordan form the chains claim
void expect_jordan_form(const Eigen::MatrixXd& A, const JordanBasis& basis) {
  ASSERT_TRUE(basis.refusal.empty()) << basis.refusal;
  Eigen::MatrixXcd J = basis.V.inverse() * A.cast<std::complex<double>>() * basis.V;
  for (const JordanBasis::Block& b : basis.blocks)
    for (int i = 0; i < b.size; ++i) {
      EXPECT_LT(std::abs(J(b.first + i, b.first + i) - b.eigenvalue), 1e-9);
      J(b.first + i, b.first + i) = 0;
      if (i + 1 == b.size) continue;
      EXPECT_LT(std::abs(J(b.first + i, b.first + i + 1) - 1.0), 1e-9);
      J(b.first + i, b.first + i + 1) = 0;
    }
  EXPECT_LT(J.cwiseAbs().maxCoeff(), 1e-9) << "nothing outside the blocks:\n" << J;
  EXPECT_LT(basis.residual, 1e-9);
}

TEST(JordanChains, GeneralizedEigenvectorsGiveTheJordanForm) {
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(4, 4), P(4, 4);
  J << 2, 1, 0, 0, 0, 2, 1, 0, 0, 0, 2, 0, 0, 0, 0, -1;
  P << 1, 0.5, 0, 0.2, 0, 1, 0.3, 0, 0.1, 0, 1, 0.4, 0, 0.2, 0, 1;
  Eigen::MatrixXd A = P * J * P.inverse();
  JordanBasis basis = jordan_basis(A, jordan_structure(A));
  ASSERT_EQ(basis.blocks.size(), 2u);
  EXPECT_EQ(basis.blocks[0].size, 3);
  expect_jordan_form(A, basis);
  // J2(0) ⊕ J1(0) ⊕ (3): two blocks of one eigenvalue, the chain top outside the other block
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(4, 4);
  K(0, 1) = 1, K(3, 3) = 3;
  Eigen::MatrixXd B = P * K * P.inverse();
  JordanStructure s = jordan_structure(B);
  ASSERT_EQ(s.eigenvalues.size(), 2u);
  EXPECT_EQ(s.eigenvalues[1].jordan_blocks, (std::vector<int>{2, 1}));
  expect_jordan_form(B, jordan_basis(B, s));
}

TEST(JordanStructure, SemisimpleDoubleEigenvaluesHaveBlocksOfSizeOne) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(4, 4);
  A << 0, 0, 1, 0, 0, 0, 0, 1, -4, 0, 0, 0, 0, -4, 0, 0;  // two uncoupled oscillators ω = 2
  JordanStructure s = jordan_structure(A);
  ASSERT_EQ(s.eigenvalues.size(), 2u);
  for (const EigenvalueStructure& e : s.eigenvalues) {
    EXPECT_EQ(e.value.real(), 0) << "exactly on the axis";
    EXPECT_NEAR(std::abs(e.value.imag()), 2, 1e-12);
    EXPECT_EQ(e.algebraic_multiplicity, 2);
    EXPECT_EQ(e.geometric_multiplicity, 2);
    EXPECT_EQ(e.jordan_blocks, (std::vector<int>{1, 1}));
  }
}

TEST(JordanStructure, ANearlyDefectiveMatrixIsReportedUncertain) {
  Eigen::MatrixXd A(2, 2);
  A << 1, 1, 1e-10, 1;  // eigenvalues 1 ± 1e-5: distinct, but a perturbation of 1e-10 from a Jordan block
  EXPECT_TRUE(jordan_structure(A).uncertain);
  A(1, 0) = 0.5;  // well separated: decided
  EXPECT_FALSE(jordan_structure(A).uncertain);
}

TEST(FundamentalMatrix, OscillatorAgainstItsClosedForm) {
  // x'' = −ω² x: Φ(t) = [[cos ωt, sin ωt/ω], [−ω sin ωt, cos ωt]]
  const double w = 3;
  Eigen::MatrixXd A(2, 2);
  A << 0, 1, -w * w, 0;
  for (double t : {0.1, 1.0, 10.0}) {
    Eigen::MatrixXd Phi = fundamental_matrix(A, t), exact(2, 2);
    exact << std::cos(w * t), std::sin(w * t) / w, -w * std::sin(w * t), std::cos(w * t);
    EXPECT_LT((Phi - exact).cwiseAbs().maxCoeff(), 1e-12 * std::max(1.0, w * w * t)) << t;
  }
}

TEST(ModalAnalysis, TwoMassChainWithRayleighDamping) {
  const double m = 2, k = 50, alpha = 0.2, beta = 0.003;
  Eigen::MatrixXd M = m * Eigen::MatrixXd::Identity(2, 2), K(2, 2);
  K << 2 * k, -k, -k, 2 * k;
  ModalAnalysis a = modal_analysis(M, alpha * M + beta * K, K);
  ASSERT_TRUE(a.refusal.empty()) << a.refusal;
  ASSERT_EQ(a.modes.size(), 2u);
  double w[2] = {std::sqrt(k / m), std::sqrt(3 * k / m)};
  double shapes[2][2] = {{1, 1}, {1, -1}};
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(a.modes[i].omega, w[i], 1e-12 * w[i]);
    EXPECT_NEAR(a.modes[i].damping_ratio, alpha / (2 * w[i]) + beta * w[i] / 2, 1e-12);
    for (int j = 0; j < 2; ++j) EXPECT_NEAR(a.modes[i].shape(j), shapes[i][j] / std::sqrt(2 * m), 1e-12);
  }
  EXPECT_EQ(a.damping, "proportional");
  EXPECT_NEAR(a.rayleigh_alpha, alpha, 1e-12);
  EXPECT_NEAR(a.rayleigh_beta, beta, 1e-12);
  EXPECT_LT(a.orthonormality_error, 1e-12);
  EXPECT_EQ(a.rigid_body_modes, 0);
  // a constraint: with either mass held, the other oscillates at √(2k/m), between ω₁ and ω₂ (§8.1.4)
  ASSERT_EQ(a.constrained.size(), 2u);
  for (const auto& c : a.constrained) {
    ASSERT_EQ(c.omegas.size(), 1u);
    EXPECT_NEAR(c.omegas[0], std::sqrt(2 * k / m), 1e-12 * w[1]);
    EXPECT_TRUE(c.interlaces);
  }
  EXPECT_LT(a.rayleigh_error, 1e-14);
  // Rayleigh's quotient bounds ω₁² from above and is exact at the first mode (§8.1.4)
  EXPECT_NEAR(rayleigh_quotient(M, K, a.modes[0].shape), w[0] * w[0], 1e-12 * w[0] * w[0]);
  EXPECT_GT(rayleigh_quotient(M, K, Eigen::Vector2d(1, 0.5)), w[0] * w[0]);
}

TEST(ModalAnalysis, FreeFreeChainHasARigidBodyMode) {
  // two masses joined by one spring and nothing else: ω = 0 (translation) and √(2k/m)
  Eigen::MatrixXd M = Eigen::MatrixXd::Identity(2, 2), K(2, 2);
  K << 3, -3, -3, 3;
  ModalAnalysis a = modal_analysis(M, Eigen::MatrixXd::Zero(2, 2), K);
  ASSERT_EQ(a.modes.size(), 2u);
  EXPECT_EQ(a.rigid_body_modes, 1);
  EXPECT_TRUE(a.modes[0].rigid_body);
  EXPECT_EQ(a.modes[0].omega, 0);
  EXPECT_NEAR(a.modes[1].omega, std::sqrt(6.0), 1e-12);
  EXPECT_EQ(a.damping, "none");
}

TEST(ModalAnalysis, NonproportionalDampingIsSaidWithItsCoupling) {
  Eigen::MatrixXd M = Eigen::MatrixXd::Identity(2, 2), K(2, 2), D = Eigen::MatrixXd::Zero(2, 2);
  K << 2, -1, -1, 2;
  D(0, 0) = 0.1;  // a damper on the first mass only
  ModalAnalysis a = modal_analysis(M, D, K);
  EXPECT_EQ(a.damping, "nonproportional");
  EXPECT_NEAR(a.coupling, 1.0, 1e-12) << "ΦᵀDΦ = 0.05 [[1, 1], [1, 1]]: off-diagonal as large as diagonal";
  Eigen::MatrixXd unstable = -K;
  EXPECT_FALSE(modal_analysis(M, D, unstable).refusal.empty());
}

// the modes of K v = ω² M v leave out G and N: a G of 1 % of the system's rate refuses them in
// every unit of mass and of time (measured against |K| + |D| with a floor of 1 before, a small
// rotor's G counted as zero), one of 1e-14 does not
TEST(ModalAnalysis, GyroscopicAndCirculatoryForcesRefuseTheModesAtEveryScale) {
  for (double mass : {1e-12, 1.0, 1e12})
    for (double rate : {1e-6, 1.0, 1e6}) {
      SCOPED_TRACE(testing::Message() << "mass " << mass << ", rate " << rate);
      StabilityReport s;
      s.M = mass * Eigen::MatrixXd::Identity(2, 2);
      s.K = Eigen::MatrixXd(2, 2);
      s.K << 2, -1, -1, 2;
      s.K *= mass * rate * rate;
      s.D = Eigen::MatrixXd::Zero(2, 2);
      Eigen::MatrixXd skew(2, 2);
      skew << 0, 1, -1, 0;
      s.N = Eigen::MatrixXd::Zero(2, 2);
      s.G = 1e-2 * mass * rate * skew;
      EXPECT_NE(symmetric_problem_refusal(s).find("gyroscopic forces G"), std::string::npos);
      s.G *= 1e-12;
      EXPECT_EQ(symmetric_problem_refusal(s), "");
      s.N = 1e-2 * mass * rate * rate * skew;
      EXPECT_NE(symmetric_problem_refusal(s).find("circulatory forces N"), std::string::npos);
    }
}

}  // namespace
}  // namespace eomgen::runtime
