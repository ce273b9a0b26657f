// Routh's reduction against closed forms written here, at random points: the
// spherical pendulum with p_phi held (M = m l², f = -m g l sinθ + p² cosθ/(m l² sin³θ),
// the Routhian and der(phi)), the heavy symmetric top with p_psi and p_phi held
// (f = -dV_eff/dθ of the amended potential), and the refusals.
#include <gtest/gtest.h>

#include "pipeline.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

Equations reduce(const std::string& name, const std::vector<std::string>& cyclic) {
  Derivation d = derive_reduced_model_file(model_path(name), cyclic);
  EXPECT_TRUE(d.diagnostics.empty()) << d.diagnostics.format();
  return d.equations ? *d.equations : Equations{};
}

TEST(Routh, SphericalPendulumWithTheAzimuthalMomentumHeld) {
  Equations e = reduce("spherical_pendulum", {"phi"});
  ASSERT_EQ(e.symbols.coordinate_names, (std::vector<std::string>{"theta"}));
  EXPECT_EQ(e.method, "routh");
  auto points = random_points(e.symbols, 20);
  EXPECT_TRUE(agree_at_points(e.mass_matrix(0, 0), closed_form(e, "m*l^2"), points));
  EXPECT_TRUE(agree_at_points(e.forcing[0], closed_form(e, "-m*g*l*sin(theta) + p_phi^2*cos(theta)/(m*l^2*sin(theta)^3)"),
                              points)) << e.forcing[0];
  EXPECT_TRUE(agree_at_points(e.routhian,
                              closed_form(e, "m*l^2*d_theta^2/2 - p_phi^2/(2*m*l^2*sin(theta)^2) + m*g*l*cos(theta)"), points));
  ASSERT_EQ(e.eliminated_coordinates.size(), 1u);
  EXPECT_TRUE(agree_at_points(e.eliminated_coordinates[0].expression, closed_form(e, "p_phi/(m*l^2*sin(theta)^2)"), points));
  // the amended potential, and T + V is the energy of the full motion
  EXPECT_TRUE(agree_at_points(e.potential_energy, closed_form(e, "p_phi^2/(2*m*l^2*sin(theta)^2) - m*g*l*cos(theta)"), points));
  ASSERT_EQ(e.first_integrals.size(), 1u);
  EXPECT_EQ(e.first_integrals[0].name, "energy");
  EXPECT_TRUE(agree_at_points(e.first_integrals[0].expression, e.kinetic_energy + e.potential_energy, points));
}

TEST(Routh, HeavySymmetricTopWithBothMomentaHeld) {
  Equations e = reduce("heavy_symmetric_top", {"psi", "phi"});
  ASSERT_EQ(e.symbols.coordinate_names, (std::vector<std::string>{"theta"}));
  auto points = random_points(e.symbols, 20);
  GiNaC::ex amended = closed_form(e, "(p_psi - p_phi*cos(theta))^2/(2*(A + m*s^2)*sin(theta)^2) + p_phi^2/(2*C) + m*g*s*cos(theta)");
  EXPECT_TRUE(agree_at_points(e.mass_matrix(0, 0), closed_form(e, "A + m*s^2"), points));
  EXPECT_TRUE(agree_at_points(e.forcing[0], -amended.diff(e.symbols.coordinates[0]), points)) << e.forcing[0];
  EXPECT_TRUE(agree_at_points(e.potential_energy, amended, points)) << e.potential_energy;
}

TEST(Routh, OnlyCyclicCoordinatesAreEliminated) {
  Derivation theta = derive_reduced_model_file(model_path("spherical_pendulum"), {"theta"});
  ASSERT_FALSE(theta.diagnostics.empty());
  EXPECT_NE(theta.diagnostics.format().find("L depends on theta"), std::string::npos) << theta.diagnostics.format();
  Derivation unknown = derive_reduced_model_file(model_path("spherical_pendulum"), {"chi"});
  EXPECT_NE(unknown.diagnostics.format().find("chi is not a coordinate"), std::string::npos);
  // the cart's coordinate is cyclic, but the input force acts on it
  Derivation cart = derive_reduced_model_file(model_path("cart_pendulum"), {"x"});
  EXPECT_NE(cart.diagnostics.format().find("an applied force or dissipation acts on x"), std::string::npos)
      << cart.diagnostics.format();
}

}  // namespace
}  // namespace eomgen::test
