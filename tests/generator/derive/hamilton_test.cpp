// Hamilton's canonical equations against closed forms written here, compared at
// random points: the Hamiltonian, the kinematic equations der(q) = dH/dp and the
// momentum equations der(p) = -dH/dq + Q of the pendulum, the spherical pendulum,
// the bead on a rotating hoop and the heavy symmetric top; and trajectories in
// canonical variables against the lagrange2 trajectories mapped through p = dT/d der(q).
#include <gtest/gtest.h>

#include <cmath>

#include "pipeline.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

Equations derive_as_hamilton(const std::string& name) {
  std::string text = read_file(model_path(name));
  std::size_t title = text.find("\ntitle");
  text.insert(title, "\nmethod = \"hamilton\"");
  Derivation d = derive_model_text(text, model_path(name));
  EXPECT_TRUE(d.diagnostics.empty()) << d.diagnostics.format();
  return d.equations ? *d.equations : Equations{};
}

void expect_canonical(const Equations& e, const std::string& H, const std::vector<std::string>& rates,
                      const std::vector<std::string>& momentum_rates) {
  ASSERT_EQ(e.method, "hamilton");
  auto points = random_points(e.symbols, 20);
  EXPECT_TRUE(agree_at_points(e.hamiltonian, closed_form(e, H), points)) << "H = " << e.hamiltonian;
  for (std::size_t j = 0; j < rates.size(); ++j) {
    EXPECT_TRUE(agree_at_points(e.coordinate_rates[j], closed_form(e, rates[j]), points)) << e.coordinate_rates[j];
    EXPECT_TRUE(agree_at_points(e.forcing[j], closed_form(e, momentum_rates[j]), points)) << e.forcing[j];
    EXPECT_TRUE(e.mass_matrix(j, j).is_equal(1)) << "M = I: f is der(p)";
  }
}

TEST(Hamilton, Pendulum) {
  expect_canonical(derive_model("pendulum_hamilton"), "p_phi^2/(2*m*l^2) - m*g*l*cos(phi)", {"p_phi/(m*l^2)"},
                   {"-m*g*l*sin(phi) - d*p_phi/(m*l^2)"});
}

TEST(Hamilton, SphericalPendulumConservesTheAzimuthalMomentum) {
  Equations e = derive_model("spherical_pendulum_hamilton");
  expect_canonical(e, "p_theta^2/(2*m*l^2) + p_phi^2/(2*m*l^2*sin(theta)^2) - m*g*l*cos(theta)",
                   {"p_theta/(m*l^2)", "p_phi/(m*l^2*sin(theta)^2)"},
                   {"-m*g*l*sin(theta) + p_phi^2*cos(theta)/(m*l^2*sin(theta)^3)", "0"});
  EXPECT_TRUE(e.forcing[1].is_zero()) << "der(p_phi) = 0 exactly";
  EXPECT_EQ(e.pseudo_velocity_definitions[1].name, "p_phi");
}

TEST(Hamilton, BeadOnARotatingHoopHasATimeFreeHamiltonian) {
  Equations e = derive_model("bead_on_rotating_hoop_hamilton");
  expect_canonical(e, "p_theta^2/(2*m*r^2) - m*r^2*Omega^2*sin(theta)^2/2 - m*g*r*cos(theta)", {"p_theta/(m*r^2)"},
                   {"m*r^2*Omega^2*sin(theta)*cos(theta) - m*g*r*sin(theta)"});
  EXPECT_FALSE(e.hamiltonian.has(e.symbols.time)) << "H is the Jacobi integral although the hoop is driven";
}

TEST(Hamilton, HeavySymmetricTopConservesTwoMomenta) {
  Equations e = derive_as_hamilton("heavy_symmetric_top");
  ASSERT_EQ(e.method, "hamilton");
  std::size_t conserved = 0;
  for (std::size_t j = 0; j < e.forcing.size(); ++j) conserved += e.forcing[j].is_zero();
  EXPECT_EQ(conserved, 2u) << "p_psi and p_phi: the precession and spin angles are cyclic";
  // H = T + V for this scleronomic system: compare with the Lagrangian energy at q' = dH/dp
  Equations lagrange = derive_model("heavy_symmetric_top");
  GiNaC::exmap velocity_of;
  for (std::size_t j = 0; j < e.coordinate_rates.size(); ++j) velocity_of[lagrange.symbols.velocities[j]] = e.coordinate_rates[j];
  GiNaC::exmap same_symbols;
  for (std::size_t i = 0; i < e.symbols.parameters.size(); ++i) same_symbols[lagrange.symbols.parameters[i]] = e.symbols.parameters[i];
  for (std::size_t i = 0; i < e.symbols.coordinates.size(); ++i) same_symbols[lagrange.symbols.coordinates[i]] = e.symbols.coordinates[i];
  GiNaC::ex energy = (lagrange.kinetic_energy + lagrange.potential_energy).subs(velocity_of).subs(same_symbols);
  EXPECT_TRUE(agree_at_points(e.hamiltonian, energy, random_points(e.symbols, 20)));
}

TEST(Hamilton, ConstrainedModelsAreRefused) {
  std::string text = read_file(model_path("slider_crank"));
  text.replace(text.find("method = \"lagrange1\""), 20, "method = \"hamilton\"");
  Derivation d = derive_model_text(text, "slider_crank.toml");
  ASSERT_FALSE(d.diagnostics.empty());
  EXPECT_NE(d.diagnostics.format().find("use method = \"lagrange1\""), std::string::npos) << d.diagnostics.format();
}

TEST(Hamilton, TrajectoriesAgreeWithLagrangeTwo) {
  // m = 2, l = 0.7: p_phi = m l² der(phi) = 0.98 der(phi); several periods (about 1.7 s each)
  std::string dir = temporary_directory();
  std::string common = " --set m=2 --set l=0.7 --set d=0.3 --t-end 8 --dt-out 0.1 --integrator arkode-dp5 --rtol 1e-12 --atol 1e-14";
  ASSERT_EQ(run_eomgen("simulate '" + model_path("pendulum") + "'" + common + " -o '" + dir + "/l.csv'").status, 0);
  ASSERT_EQ(run_eomgen("simulate '" + model_path("pendulum_hamilton") + "'" + common + " -o '" + dir + "/h.csv'").status, 0);
  auto lagrange = read_numeric_csv(dir + "/l.csv"), hamilton = read_numeric_csv(dir + "/h.csv");
  ASSERT_EQ(lagrange.size(), hamilton.size());
  ASSERT_EQ(lagrange.size(), 81u);
  for (std::size_t k = 0; k < lagrange.size(); ++k) {
    EXPECT_NEAR(hamilton[k][1], lagrange[k][1], 1e-9) << "phi at t = " << lagrange[k][0];
    EXPECT_NEAR(hamilton[k][2], 2 * 0.49 * lagrange[k][2], 1e-9) << "p_phi at t = " << lagrange[k][0];
    EXPECT_NEAR(hamilton[k][3], lagrange[k][3], 1e-9) << "T + V at t = " << lagrange[k][0];
  }
}

}  // namespace
}  // namespace eomgen::test
