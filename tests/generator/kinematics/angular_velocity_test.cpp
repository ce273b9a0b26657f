// The body-frame angular velocity from the product of elementary rotations
// against skew(ω) = Rᵀ·dR/dt formed directly, and against the textbook
// formula for Euler angles 3-1-3 (Hiller §3.9).
#include <gtest/gtest.h>

#include "kinematics/mechanics.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

TEST(AngularVelocity, EulerAnglesMatchTheTextbook) {
  Equations e = derive_model("heavy_symmetric_top");
  const Symbols& s = e.symbols;
  std::vector<ElementaryRotation> sequence = {{2, s.coordinates[0]}, {0, s.coordinates[1]}, {2, s.coordinates[2]}};
  Vector3 w = angular_velocity_of_sequence(sequence, s);
  auto points = random_points(s, 20);
  EXPECT_TRUE(agree_at_points(w[0], closed_form(e, "d_psi*sin(theta)*sin(phi) + d_theta*cos(phi)"), points));
  EXPECT_TRUE(agree_at_points(w[1], closed_form(e, "d_psi*sin(theta)*cos(phi) - d_theta*sin(phi)"), points));
  EXPECT_TRUE(agree_at_points(w[2], closed_form(e, "d_psi*cos(theta) + d_phi"), points));
}

TEST(AngularVelocity, SequenceAgreesWithMatrixRoute) {
  Equations e = derive_model("gimbal_cardan");
  const Symbols& s = e.symbols;
  // a rheonomic product: the third angle is driven in time on top of its coordinate
  std::vector<ElementaryRotation> sequence = {
      {0, s.coordinates[0]}, {1, s.coordinates[1]}, {2, s.coordinates[2] + 3 * s.time}, {0, s.coordinates[0] * s.coordinates[1]}};
  GiNaC::matrix R = GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(3));
  for (const ElementaryRotation& r : sequence) R = R.mul(elementary_rotation(r.axis, r.angle));
  MotionSymbols motion = motion_symbols(s);
  Vector3 a = angular_velocity_of_sequence(sequence, s);
  Vector3 b = angular_velocity_of_matrix(R, s, motion);
  auto points = random_points(s, 20);
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(agree_at_points(a[k], b[k], points)) << k;
}

TEST(Kinematics, RheonomicVelocityHasExplicitTimeTerm) {
  Equations e = derive_model("bead_on_rotating_hoop");
  // T = ½ m r² (θ̇² + Ω² sin²θ)
  EXPECT_TRUE(agree_at_points(e.kinetic_energy, closed_form(e, "m*r^2*(d_theta^2 + Omega^2*sin(theta)^2)/2"),
                              random_points(e.symbols, 20)));
}

TEST(Kinematics, GravityPotentialAndDissipation) {
  Equations e = derive_model("pendulum");
  auto points = random_points(e.symbols, 20);
  EXPECT_TRUE(agree_at_points(e.potential_energy, closed_form(e, "-m*g*l*cos(phi)"), points));
  EXPECT_TRUE(agree_at_points(e.dissipation, closed_form(e, "d*d_phi^2/2"), points));
}

}  // namespace
}  // namespace eomgen::test
