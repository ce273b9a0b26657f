// Hamilton's mass matrix as the state checks take it (runtime/analyse/state_check.hpp): the inverse
// of the kinetic energy's Hessian in the momenta, by polarization. A spherical pendulum's M is
// diag(m l², m l² sin² θ), whatever the momenta are: at p_φ = 2e12 a step of 1 in p_θ had changed
// T, of 1e24, below its rounding, and the Hessian's eigenvalues came out ±2e7 ("not positive
// definite"; a governor written for Hamilton on a time scale of 1e-12 s was refused so).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "analyse/state_check.hpp"
#include "generated/header_registry.hpp"

namespace eomgen::test {
namespace {

TEST(StateCheck, HamiltonsMassMatrixDoesNotDependOnTheMomentaItIsTakenAt) {
  const eomgen_model_abi* hamilton = generated_model("spherical_pendulum_hamilton").abi;
  const double l = 1, g = 9.81, theta = 0.8;
  for (double m : {1e-12, 1.0, 1e12}) {
    runtime::Problem p{hamilton, {m, l, g}, {}};
    const double inertia = m * l * l;
    for (double p_phi : {0.0, 1e-12, 1.0, 2e12, 1e24}) {
      for (double p_theta : {0.0, 3e-6 * inertia, -p_phi}) {
        std::vector<double> x{theta, 0.0, p_theta, p_phi};
        Eigen::MatrixXd M = runtime::mass_matrix_at(p, 0.0, x);
        EXPECT_NEAR(M(0, 0) / inertia, 1, 1e-12) << "m = " << m << ", p = " << p_theta << ", " << p_phi;
        EXPECT_NEAR(M(1, 1) / (inertia * std::sin(theta) * std::sin(theta)), 1, 1e-12) << "m = " << m << ", p_phi = " << p_phi;
        EXPECT_LE(std::max(std::abs(M(0, 1)), std::abs(M(1, 0))), 1e-12 * inertia) << "m = " << m << ", p_phi = " << p_phi;
      }
    }
  }
}

}  // namespace
}  // namespace eomgen::test
