// jacobian_state of the benchmark's robots against the complex-step derivative of their rhs: the
// derivative of the code that computes q'' (composite-body M, the Newton-Euler bias forces, the
// solve) with no difference taken, against the closed-form gradient of the inverse dynamics. Both
// carry the rounding of a solve with M, relative to the size of J's row (the gantry hand's M has a
// condition number near 1e4): each entry to 1e-12 of its row's largest. The 21-joint tree's and
// the 11-joint gantry hand's gradients (a slide and a fixed link among its links) are the loops of
// detail::hinge_tree_gradient (spatial/joint_tree_derivatives.hpp), the arm's straight-line code.
// The coupled hand is the gantry hand whose fingers' outer joints follow their first (mimic
// joints): its loops add each follower's rows and columns into its leader's. The quadruped's loops
// start from its floating base's free joint, the ball-hung chain's from a ball joint; the ragdoll's
// have ball joints below its free root, links of three columns and four directions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstring>
#include <random>
#include <type_traits>
#include <vector>

#include "ball_chain_imported.hpp"
#include "ball_hung_chain.hpp"
#include "ball_ragdoll_imported.hpp"
#include "branched_tree.hpp"
#include "coupled_hand.hpp"
#include "gantry_hand.hpp"
#include "gyroscopic_arm.hpp"
#include "quadruped.hpp"
#include "ragdoll_beside_free_objects_imported.hpp"
#include "seven_joint_arm.hpp"
#include "snake_beside_free_objects_imported.hpp"

namespace {

template <class Real, class Rhs, class Jacobian>
double worst_against_complex_step(std::size_t states, std::size_t inputs, std::vector<Real> x, const std::vector<Real>& p,
                                  Rhs rhs, Jacobian jacobian_state) {
  using cd = std::complex<Real>;
  const Real step = Real(1e-30);
  std::mt19937 random(38);
  std::uniform_real_distribution<double> spread(-1, 1);
  double worst = 0;
  for (int trial = 0; trial < 8; ++trial) {
    for (Real& v : x) v += Real(spread(random));
    std::vector<Real> u(inputs + 1), J(states * states);
    for (Real& v : u) v = Real(spread(random));
    jacobian_state(Real(0), x.data(), u.data(), p.data(), J.data());
    std::vector<cd> xc(x.begin(), x.end()), uc(u.begin(), u.end()), pc(p.begin(), p.end()), out(states);
    for (std::size_t j = 0; j < states; ++j) {
      std::vector<cd> shifted = xc;
      shifted[j] += cd(0, step);
      rhs(cd(0), shifted.data(), uc.data(), pc.data(), out.data());
      for (std::size_t i = 0; i < states; ++i) {
        Real row = 1;
        for (std::size_t k = 0; k < states; ++k) row = std::max(row, std::abs(J[i * states + k]));
        worst = std::max(worst, double(std::abs(J[i * states + j] - out[i].imag() / step) / row));
      }
    }
  }
  return worst;
}

// detail::inverse_dynamics_gradient at random accelerations, not those of the state, against the
// complex step of τ = M q'' − f: there a floating base's whole force is not zero, and every term of
// its own pairs counts. Each entry to 1e-12 of its row's largest.
template <class MassMatrix, class Forcing, class Gradient>
double worst_inverse_dynamics_gradient(std::size_t coordinates, std::size_t velocities, std::size_t inputs,
                                       std::vector<double> x, const std::vector<double>& p, MassMatrix mass_matrix,
                                       Forcing forcing, Gradient inverse_dynamics_gradient) {
  using cd = std::complex<double>;
  std::size_t states = coordinates + velocities;
  std::mt19937 random(41);
  std::uniform_real_distribution<double> spread(-1, 1);
  double worst = 0;
  for (int trial = 0; trial < 4; ++trial) {
    for (double& v : x) v += spread(random);
    std::vector<double> u(inputs + 1), ddq(velocities), F(velocities * states);
    for (double& v : u) v = spread(random);
    for (double& v : ddq) v = 5 * spread(random);
    inverse_dynamics_gradient(0.0, x.data(), ddq.data(), u.data(), p.data(), F.data());
    std::vector<cd> uc(u.begin(), u.end()), pc(p.begin(), p.end()), M(velocities * velocities), f(velocities);
    for (std::size_t j = 0; j < states; ++j) {
      std::vector<cd> shifted(x.begin(), x.end());
      shifted[j] += cd(0, 1e-30);
      mass_matrix(cd(0), shifted.data(), pc.data(), M.data());
      forcing(cd(0), shifted.data(), uc.data(), pc.data(), f.data());
      for (std::size_t i = 0; i < velocities; ++i) {
        cd tau = -f[i];
        for (std::size_t k = 0; k < velocities; ++k) tau += M[i * velocities + k] * ddq[k];
        double row = 1;
        for (std::size_t k = 0; k < states; ++k) row = std::max(row, std::abs(F[i * states + k]));
        worst = std::max(worst, std::abs(F[i * states + j] - tau.imag() / 1e-30) / row);
      }
    }
  }
  return worst;
}

#define EXPECT_INVERSE_DYNAMICS_GRADIENT_IS_THE_COMPLEX_STEP(M)                                                  \
  {                                                                                                           \
    namespace m = eomgen::models::M;                                                                          \
    double worst = worst_inverse_dynamics_gradient(                                                           \
        m::num_coordinates, m::num_states - m::num_coordinates, m::num_inputs,                                \
        std::vector<double>(m::default_state.begin(), m::default_state.end()),                               \
        std::vector<double>(m::default_parameters.begin(), m::default_parameters.end()),                      \
        m::mass_matrix<std::complex<double>>, m::forcing<std::complex<double>>,                                \
        m::detail::inverse_dynamics_gradient<double>);                                                         \
    std::printf(#M ": inverse_dynamics_gradient against the complex step: %.2g\n", worst);                   \
    EXPECT_LT(worst, 1e-12) << #M;                                                                            \
  }

// in `Real` arithmetic: double, or long double where double's rounding alone comes near 1e-12
#define EXPECT_JACOBIAN_IS_THE_COMPLEX_STEP_IN(M, Real)                                                         \
  {                                                                                                           \
    namespace m = eomgen::models::M;                                                                          \
    double worst = worst_against_complex_step(                                                                \
        m::num_states, m::num_inputs, std::vector<Real>(m::default_state.begin(), m::default_state.end()),   \
        std::vector<Real>(m::default_parameters.begin(), m::default_parameters.end()),                        \
        m::rhs<std::complex<Real>>, m::jacobian_state<Real>);                                                  \
    std::printf(#M " in " #Real ": jacobian_state against the complex step: %.2g\n", worst);                \
    EXPECT_LT(worst, 1e-12) << #M;                                                                            \
  }
#define EXPECT_JACOBIAN_IS_THE_COMPLEX_STEP(M) EXPECT_JACOBIAN_IS_THE_COMPLEX_STEP_IN(M, double)

TEST(RobotJacobians, TheTreesLoopsAreTheComplexStepDerivative) {
  EXPECT_JACOBIAN_IS_THE_COMPLEX_STEP(branched_tree);
  EXPECT_JACOBIAN_IS_THE_COMPLEX_STEP(gantry_hand);
}

TEST(RobotJacobians, TheLoopsOfJointsThatFollowACoordinateAreTheComplexStepDerivative) {
  EXPECT_JACOBIAN_IS_THE_COMPLEX_STEP(coupled_hand);
}

// The quadruped's root joint is free (detail::tree_jointed_root), its legs' hinges in the loops. In
// double its rounding alone reaches 1e-12 of a row, with the loops (1.05e-12) as with straight-line
// code (9.5e-13), M's condition number near 1.2e3: checked in long double, where both are 1.6e-15.
TEST(RobotJacobians, TheLoopsBelowAFloatingBaseAreTheComplexStepDerivative) {
  EXPECT_JACOBIAN_IS_THE_COMPLEX_STEP_IN(quadruped, long double);
  EXPECT_INVERSE_DYNAMICS_GRADIENT_IS_THE_COMPLEX_STEP(quadruped);
}

// a ball joint's three columns all turn with its link
TEST(RobotJacobians, TheLoopsBelowABallJointAreTheComplexStepDerivative) {
  EXPECT_JACOBIAN_IS_THE_COMPLEX_STEP(ball_hung_chain);
  EXPECT_INVERSE_DYNAMICS_GRADIENT_IS_THE_COMPLEX_STEP(ball_hung_chain);
}

// The ragdoll's ball joints below its free root are links of three columns and four directions in
// the loops. Its light hands make M's condition number about 3e5: in double jacobian_state's rounding
// reaches 2.7e-11 of a row (inverse_dynamics_gradient's, before the solve, 7e-14), so it is checked in
// long double.
TEST(RobotJacobians, TheLoopsOverBallJointsBelowTheRootAreTheComplexStepDerivative) {
  EXPECT_JACOBIAN_IS_THE_COMPLEX_STEP_IN(ball_ragdoll_imported, long double);
  EXPECT_INVERSE_DYNAMICS_GRADIENT_IS_THE_COMPLEX_STEP(ball_ragdoll_imported);
}

// Trees beside free objects: three jointed roots in the loops, over links of one column and of three
TEST(RobotJacobians, TheLoopsOverSeveralJointedRootsAreTheComplexStepDerivative) {
  EXPECT_JACOBIAN_IS_THE_COMPLEX_STEP(snake_beside_free_objects_imported);
  EXPECT_INVERSE_DYNAMICS_GRADIENT_IS_THE_COMPLEX_STEP(snake_beside_free_objects_imported);
  EXPECT_JACOBIAN_IS_THE_COMPLEX_STEP_IN(ragdoll_beside_free_objects_imported, long double);
  EXPECT_INVERSE_DYNAMICS_GRADIENT_IS_THE_COMPLEX_STEP(ragdoll_beside_free_objects_imported);
}

TEST(RobotJacobians, TheArmsStraightLineCodeIsTheComplexStepDerivative) {
  EXPECT_JACOBIAN_IS_THE_COMPLEX_STEP(seven_joint_arm);
  EXPECT_INVERSE_DYNAMICS_GRADIENT_IS_THE_COMPLEX_STEP(seven_joint_arm);
}

// whether the header's jacobian_state solves for q'' inside its closed-form gradient
template <class F>
constexpr bool solves_inside_the_gradient(F*) {
  return std::is_invocable_v<F, double, const double*, const double*, const double*, const double*, double*, double*, double*>;
}

// M and f from the closed form's own quantities, q'' solved inside it, and forces of the
// velocities and coordinates swept through their own code (a sweep that ran through M's and f's
// temporaries had lost the gyroscopic terms' derivatives)
TEST(RobotJacobians, AGradientThatSolvesForTheAccelerationsIsTheComplexStepDerivative) {
  namespace m = eomgen::models::gyroscopic_arm;
  ASSERT_TRUE(solves_inside_the_gradient(&m::detail::tree_acceleration_gradient<double>));
  EXPECT_JACOBIAN_IS_THE_COMPLEX_STEP(gyroscopic_arm);
  EXPECT_INVERSE_DYNAMICS_GRADIENT_IS_THE_COMPLEX_STEP(gyroscopic_arm);
}

// A gradient of some thousands of operations is also compiled for AVX2 and FMA, and the processor
// chooses (emit/cpp_avx_dispatch.hpp): the copy must do the template's arithmetic, which g++ fuses
// into multiply-adds only where it optimizes (-O2), not at this binary's -O0. Checked to the last
// bit against the template's double instance, compiled for the target alone, at random states
// and accelerations, both for jacobian_state (given_ddq null: q'' solved inside, M's factors) and
// for linearization (given q''); tests/generator/emit/avx_dispatch_test.cpp checks the fused copy
// at -O2 within rounding, and with -ffp-contract=off to the last bit.
#if defined(__GNUC__) && !defined(__clang__) && !defined(__OPTIMIZE__) && defined(__x86_64__) && !defined(__AVX__) && \
    !defined(EOMGEN_NO_AVX_DISPATCH)
template <class Portable, class Wide>
void expect_the_same_bits(std::size_t states, std::size_t velocities, std::vector<double> x, const std::vector<double>& p,
                          Portable portable, Wide wide) {
  std::mt19937 random(43);
  std::uniform_real_distribution<double> spread(-1, 1);
  for (int trial = 0; trial < 6; ++trial) {
    for (double& v : x) v += spread(random);
    std::vector<double> u(velocities + 1), ddq(velocities);
    for (double& v : u) v = spread(random);
    for (double& v : ddq) v = 5 * spread(random);
    for (const double* given : {static_cast<const double*>(nullptr), static_cast<const double*>(ddq.data())}) {
      std::vector<double> L(velocities * velocities), D(velocities), F(velocities * states);
      std::vector<double> L_copy = L, D_copy = D, F_copy = F;
      portable(0.0, x.data(), u.data(), p.data(), given, L.data(), D.data(), F.data());
      wide(0.0, x.data(), u.data(), p.data(), given, L_copy.data(), D_copy.data(), F_copy.data());
      EXPECT_EQ(0, std::memcmp(F.data(), F_copy.data(), F.size() * sizeof(double))) << "trial " << trial;
      EXPECT_EQ(0, std::memcmp(L.data(), L_copy.data(), L.size() * sizeof(double))) << "trial " << trial;
      EXPECT_EQ(0, std::memcmp(D.data(), D_copy.data(), D.size() * sizeof(double))) << "trial " << trial;
      EXPECT_TRUE(std::all_of(F.begin(), F.end(), [](double v) { return std::isfinite(v); }));
    }
  }
}

#define EXPECT_THE_COPY_DOES_THE_SAME_ARITHMETIC(M)                                                          \
  {                                                                                                        \
    namespace m = eomgen::models::M;                                                                       \
    expect_the_same_bits(m::num_states, m::num_states - m::num_coordinates,                                \
                         std::vector<double>(m::default_state.begin(), m::default_state.end()),           \
                         std::vector<double>(m::default_parameters.begin(), m::default_parameters.end()), \
                         m::detail::tree_acceleration_gradient<double>, m::detail::tree_acceleration_gradient_fma); \
  }

TEST(RobotJacobians, TheCopyOfAGradientDoesTheTemplatesArithmetic) {
  if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) GTEST_SKIP() << "this processor has no AVX2 and FMA";
  EXPECT_THE_COPY_DOES_THE_SAME_ARITHMETIC(seven_joint_arm);
  EXPECT_THE_COPY_DOES_THE_SAME_ARITHMETIC(ball_chain_imported);  // ball joints, quaternions
}
#endif

}  // namespace
