// First integrals against closed forms written here, compared at random points:
// T + V and p_phi = m l² sin²θ der(phi) of the spherical pendulum, the Jacobi
// integral (not T + V) of the bead on a rotating hoop, p_psi and p_phi of the
// heavy symmetric top, the same in Hamilton's variables, and none where
// dissipation or a driven constraint does work.
#include <gtest/gtest.h>

#include <algorithm>

#include "derive/first_integrals.hpp"
#include "pipeline.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

const FirstIntegral* find(const Equations& e, const std::string& name) {
  auto it = std::find_if(e.first_integrals.begin(), e.first_integrals.end(),
                         [&](const FirstIntegral& f) { return f.name == name; });
  return it == e.first_integrals.end() ? nullptr : &*it;
}

std::vector<std::string> names(const Equations& e) {
  std::vector<std::string> out;
  for (const FirstIntegral& f : e.first_integrals) out.push_back(f.name);
  return out;
}

void expect_integral(const Equations& e, const std::string& name, const std::string& closed) {
  const FirstIntegral* f = find(e, name);
  ASSERT_NE(f, nullptr) << name << " is missing from " << e.model_name;
  EXPECT_TRUE(agree_at_points(f->expression, closed_form(e, closed), random_points(e.symbols, 20)))
      << name << " = " << f->expression;
  EXPECT_FALSE(f->reason.empty());
}

// a long momentum (a floating base's, through the tree's quantities) is M's row times the velocities
// for the header, checked at two states; a short one stays an expression of its own
TEST(FirstIntegrals, ALongMomentumIsARowOfTheMassMatrix) {
  Derivation d = derive_model_file(std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/models/quadruped.toml");
  ASSERT_TRUE(d.equations) << d.diagnostics.format();
  const Equations& e = *d.equations;
  EXPECT_EQ(names(e), (std::vector<std::string>{"p_x", "p_y"}));
  EXPECT_EQ(find(e, "p_x")->mass_matrix_row, 0);
  EXPECT_EQ(find(e, "p_y")->mass_matrix_row, 1);
  EXPECT_EQ(find(derive_model("cart_pendulum"), "p_x")->mass_matrix_row, -1) << "(m_c + m) x' + m l cos θ θ' stays";
}

TEST(FirstIntegrals, SphericalPendulumKeepsEnergyAndTheAzimuthalMomentum) {
  Equations e = derive_model("spherical_pendulum");
  EXPECT_EQ(names(e), (std::vector<std::string>{"energy", "p_phi"}));
  expect_integral(e, "energy", "m*l^2*(d_theta^2 + sin(theta)^2*d_phi^2)/2 - m*g*l*cos(theta)");
  expect_integral(e, "p_phi", "m*l^2*sin(theta)^2*d_phi");
  EXPECT_NE(find(e, "p_phi")->reason.find("phi is cyclic"), std::string::npos);
}

TEST(FirstIntegrals, BeadOnARotatingHoopKeepsTheJacobiIntegralNotTPlusV) {
  Equations e = derive_model("bead_on_rotating_hoop");
  EXPECT_EQ(names(e), (std::vector<std::string>{"jacobi_integral"}));
  expect_integral(e, "jacobi_integral", "m*r^2*d_theta^2/2 - m*r^2*Omega^2*sin(theta)^2/2 - m*g*r*cos(theta)");
  EXPECT_NE(find(e, "jacobi_integral")->reason.find("T + V is not"), std::string::npos);
  // T + V differs from h by m r² Ω² sin²θ, the work of the drive
  EXPECT_FALSE(agree_at_points(find(e, "jacobi_integral")->expression, e.kinetic_energy + e.potential_energy,
                               random_points(e.symbols, 5)));
}

// T written in the orbit's turning frame (Clohessy–Wiltshire) has terms linear in and free of the
// velocities, with no t anywhere: h = T2 − T0 + V is conserved, T + V is not, and the header must not
// say it is (a simulation's energy check had refused the bounded drift as "not a solution")
TEST(FirstIntegrals, AKineticEnergyInATurningFrameKeepsTheJacobiIntegralNotTPlusV) {
  Equations e = derive_model("space_rendezvous");
  EXPECT_EQ(names(e), (std::vector<std::string>{"jacobi_integral"}));
  expect_integral(e, "jacobi_integral",
                  "m/2*(d_x^2 + d_y^2 + d_z^2) - m/2*n^2*(x^2 + y^2) - m*n^2*(2*x^2 - y^2 - z^2)/2");
  EXPECT_FALSE(e.conserves_energy_without_inputs);
  EXPECT_TRUE(derive_model("spherical_pendulum").conserves_energy_without_inputs);
}

TEST(FirstIntegrals, HeavySymmetricTopKeepsTwoMomentaAndEnergy) {
  Equations e = derive_model("heavy_symmetric_top");
  EXPECT_EQ(names(e), (std::vector<std::string>{"energy", "p_psi", "p_phi"}));
  expect_integral(e, "p_psi", "(A + m*s^2)*sin(theta)^2*d_psi + C*cos(theta)*(d_phi + cos(theta)*d_psi)");
  expect_integral(e, "p_phi", "C*(d_phi + cos(theta)*d_psi)");
  expect_integral(e, "energy",
                  "(A + m*s^2)*(d_theta^2 + sin(theta)^2*d_psi^2)/2 + C*(d_phi + cos(theta)*d_psi)^2/2 + m*g*s*cos(theta)");
}

TEST(FirstIntegrals, InHamiltonsVariablesTheyAreHAndTheMomenta) {
  Equations e = derive_model("spherical_pendulum_hamilton");
  EXPECT_EQ(names(e), (std::vector<std::string>{"energy", "p_phi"}));
  EXPECT_TRUE(find(e, "energy")->expression.is_equal(e.hamiltonian));
  EXPECT_TRUE(find(e, "p_phi")->expression.is_equal(e.symbols.velocities[1]));
  Equations hoop = derive_model("bead_on_rotating_hoop_hamilton");
  expect_integral(hoop, "jacobi_integral",
                  "p_theta^2/(2*m*r^2) - m*r^2*Omega^2*sin(theta)^2/2 - m*g*r*cos(theta)");
}

TEST(FirstIntegrals, InPseudoVelocitiesOfAppellsEquations) {
  // the knife edge: der(phi) = w is a pseudo-velocity, and phi is cyclic
  Equations e = derive_model("knife_edge");
  expect_integral(e, "p_phi", "J*w");
  ASSERT_NE(find(e, "energy"), nullptr);
}

TEST(FirstIntegrals, NoneWhereForcesDoWork) {
  // pivot damping d der(phi)²/2 (zero by default, but a parameter) and a driven cart
  EXPECT_TRUE(derive_model("pendulum").first_integrals.empty());
  Equations cart = derive_model("cart_pendulum");
  const FirstIntegral* p_x = find(cart, "p_x");
  ASSERT_NE(p_x, nullptr) << "the cart's coordinate is cyclic";
  EXPECT_NE(p_x->reason.find("with the inputs at zero"), std::string::npos) << p_x->reason;
  expect_integral(cart, "p_x", "(m + mc)*d_x + m*l*cos(theta)*d_theta");
}

TEST(FirstIntegrals, RheonomicModelsHaveNoGeneralizedEnergy) {
  // the Kapitza pendulum's pivot moves as a·cos(w t): L depends on t
  Equations e = derive_model("kapitza_pendulum");
  EXPECT_EQ(find(e, "energy"), nullptr);
  EXPECT_EQ(find(e, "jacobi_integral"), nullptr);
}

}  // namespace
}  // namespace eomgen::test
