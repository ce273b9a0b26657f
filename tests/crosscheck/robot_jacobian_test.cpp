// jacobian_state of the benchmark's robots against the complex-step derivative of their rhs, to
// 1e-12 of each entry's size: the derivative of the code that computes q'' (composite-body M, the
// Newton-Euler bias forces, the solve) with no difference taken, against the closed-form gradient
// of the inverse dynamics. The 21-joint tree's gradient is the loops of
// detail::hinge_tree_gradient (spatial/joint_tree_derivatives.hpp), the arm's straight-line code.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include "branched_tree.hpp"
#include "seven_joint_arm.hpp"

namespace {

template <class Rhs, class Jacobian>
double worst_against_complex_step(std::size_t states, std::size_t inputs, std::vector<double> x,
                                  const std::vector<double>& p, Rhs rhs, Jacobian jacobian_state) {
  using cd = std::complex<double>;
  std::mt19937 random(38);
  std::uniform_real_distribution<double> spread(-1, 1);
  double worst = 0;
  for (int trial = 0; trial < 4; ++trial) {
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
        double exact = out[i].imag() / 1e-30;
        worst = std::max(worst, std::abs(J[i * states + j] - exact) / std::max(1.0, std::abs(exact)));
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

TEST(RobotJacobians, TheTreesLoopsAreTheComplexStepDerivative) { EXPECT_JACOBIAN_IS_THE_COMPLEX_STEP(branched_tree); }

TEST(RobotJacobians, TheArmsStraightLineCodeIsTheComplexStepDerivative) { EXPECT_JACOBIAN_IS_THE_COMPLEX_STEP(seven_joint_arm); }

}  // namespace
