// jacobian_state of the benchmark's robots against the complex-step derivative of their rhs: the
// derivative of the code that computes q'' (composite-body M, the Newton-Euler bias forces, the
// solve) with no difference taken, against the closed-form gradient of the inverse dynamics. Both
// carry the rounding of a solve with M, relative to the size of J's row (the gantry hand's M has a
// condition number near 1e4): each entry to 1e-12 of its row's largest. The 21-joint tree's and
// the 11-joint gantry hand's gradients (a slide and a fixed link among its links) are the loops of
// detail::hinge_tree_gradient (spatial/joint_tree_derivatives.hpp), the arm's straight-line code.
// The coupled hand is the gantry hand whose fingers' outer joints follow their first (mimic
// joints): its loops add each follower's rows and columns into its leader's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include "branched_tree.hpp"
#include "coupled_hand.hpp"
#include "gantry_hand.hpp"
#include "seven_joint_arm.hpp"

namespace {

template <class Rhs, class Jacobian>
double worst_against_complex_step(std::size_t states, std::size_t inputs, std::vector<double> x,
                                  const std::vector<double>& p, Rhs rhs, Jacobian jacobian_state) {
  using cd = std::complex<double>;
  std::mt19937 random(38);
  std::uniform_real_distribution<double> spread(-1, 1);
  double worst = 0;
  for (int trial = 0; trial < 8; ++trial) {
    for (double& v : x) v += spread(random);
    std::vector<double> u(inputs + 1), J(states * states);
    for (double& v : u) v = spread(random);
    jacobian_state(0.0, x.data(), u.data(), p.data(), J.data());
    std::vector<cd> xc(x.begin(), x.end()), uc(u.begin(), u.end()), pc(p.begin(), p.end()), out(states);
    for (std::size_t j = 0; j < states; ++j) {
      std::vector<cd> shifted = xc;
      shifted[j] += cd(0, 1e-30);
      rhs(cd(0), shifted.data(), uc.data(), pc.data(), out.data());
      for (std::size_t i = 0; i < states; ++i) {
        double row = 1;
        for (std::size_t k = 0; k < states; ++k) row = std::max(row, std::abs(J[i * states + k]));
        worst = std::max(worst, std::abs(J[i * states + j] - out[i].imag() / 1e-30) / row);
      }
    }
  }
  return worst;
}

#define EXPECT_JACOBIAN_IS_THE_COMPLEX_STEP(M)                                                                 \
  {                                                                                                           \
    namespace m = eomgen::models::M;                                                                          \
    double worst = worst_against_complex_step(                                                                \
        m::num_states, m::num_inputs, std::vector<double>(m::default_state.begin(), m::default_state.end()), \
        std::vector<double>(m::default_parameters.begin(), m::default_parameters.end()),                      \
        m::rhs<std::complex<double>>, m::jacobian_state<double>);                                              \
    std::printf(#M ": jacobian_state against the complex step: %.2g\n", worst);                              \
    EXPECT_LT(worst, 1e-12) << #M;                                                                            \
  }

TEST(RobotJacobians, TheTreesLoopsAreTheComplexStepDerivative) {
  EXPECT_JACOBIAN_IS_THE_COMPLEX_STEP(branched_tree);
  EXPECT_JACOBIAN_IS_THE_COMPLEX_STEP(gantry_hand);
}

TEST(RobotJacobians, TheLoopsOfJointsThatFollowACoordinateAreTheComplexStepDerivative) {
  EXPECT_JACOBIAN_IS_THE_COMPLEX_STEP(coupled_hand);
}

TEST(RobotJacobians, TheArmsStraightLineCodeIsTheComplexStepDerivative) { EXPECT_JACOBIAN_IS_THE_COMPLEX_STEP(seven_joint_arm); }

}  // namespace
