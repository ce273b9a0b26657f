// Hamilton's canonical equations against closed forms written here, compared at
// random points: the Hamiltonian, the kinematic equations der(q) = dH/dp and the
// momentum equations der(p) = -dH/dq + Q of the pendulum, the spherical pendulum,
// the bead on a rotating hoop and the heavy symmetric top; and trajectories in
// canonical variables against the lagrange2 trajectories mapped through p = dT/d der(q).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>

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

TEST(Hamilton, LargerModelsSolveForTheVelocitiesInTheGeneratedCode) {
  // the 4-link chain: H and der(p) in q and der(q), der(q) from M der(q) = p (b = 0, scleronomic)
  Equations h = derive_model("n_link_pendulum_4_hamilton");
  Equations l = derive_model("n_link_pendulum_4");
  ASSERT_TRUE(h.solves_for_velocities());
  // the lagrange2 expressions in the Hamilton derivation's symbols, matched by name
  GiNaC::exmap rename;
  for (std::size_t i = 0; i < l.symbols.parameters.size(); ++i) rename[l.symbols.parameters[i]] = h.symbols.parameters[i];
  for (std::size_t i = 0; i < 4; ++i)
    rename[l.symbols.coordinates[i]] = h.symbols.coordinates[i], rename[l.symbols.velocities[i]] = h.coordinate_velocities[i];
  auto in_h = [&](const GiNaC::ex& x) { return x.subs(rename); };
  std::vector<GiNaC::exmap> points = random_points(h.symbols, 10);
  for (std::size_t k = 0; k < points.size(); ++k)
    for (std::size_t i = 0; i < 4; ++i) points[k][h.coordinate_velocities[i]] = 0.3 * double(i + 1) - 0.2 * double(k);
  EXPECT_TRUE(agree_at_points(h.hamiltonian, in_h(l.kinetic_energy + l.potential_energy), points)) << "H = T + V in q, der(q)";
  ASSERT_TRUE(h.momentum());
  for (unsigned j = 0; j < 4; ++j) {
    EXPECT_TRUE(h.momentum()->bias[j].is_zero());
    for (unsigned k = 0; k < 4; ++k)
      EXPECT_TRUE(agree_at_points(h.momentum()->mass_matrix(j, k), in_h(l.mass_matrix(j, k)), points));
    // der(p) = dL/dq at der(q) = v (Hiller §3.8: dH/dq|_p = -dL/dq|_v)
    const auto& q = l.symbols.coordinates[j];
    EXPECT_TRUE(agree_at_points(h.forcing[j], in_h(l.kinetic_energy.diff(q) - l.potential_energy.diff(q)), points)) << j;
  }
  // trajectories and the spectrum at the hanging equilibrium agree with lagrange2
  std::string dir = temporary_directory();
  std::string common = " --t-end 6 --dt-out 0.1 --integrator cvode-bdf --rtol 1e-12 --atol 1e-13";
  ASSERT_EQ(run_eomgen("simulate '" + model_path("n_link_pendulum_4") + "'" + common + " -o '" + dir + "/l.csv'").status, 0);
  ASSERT_EQ(run_eomgen("simulate '" + model_path("n_link_pendulum_4_hamilton") + "'" + common + " -o '" + dir + "/h.csv'").status, 0);
  auto lagrange = read_numeric_csv(dir + "/l.csv"), hamilton = read_numeric_csv(dir + "/h.csv");
  ASSERT_EQ(lagrange.size(), hamilton.size());
  for (std::size_t k = 0; k < lagrange.size(); ++k)
    for (std::size_t i = 1; i <= 4; ++i) EXPECT_NEAR(hamilton[k][i], lagrange[k][i], 1e-8) << "t = " << lagrange[k][0];
  std::string at = " --at phi1=0 --at phi2=0 --at phi3=0 --at phi4=0 --format json";
  CommandOutput a = run_eomgen("stability '" + model_path("n_link_pendulum_4") + "'" + at);
  CommandOutput b = run_eomgen("stability '" + model_path("n_link_pendulum_4_hamilton") + "'" + at);
  ASSERT_EQ(a.status, 0) << a.err;
  ASSERT_EQ(b.status, 0) << b.err;
  // the frequencies |Im λ|, sorted: the same spectrum in both forms
  auto frequencies = [](const std::string& json) {
    std::string list = json.substr(json.find("\"eigenvalues\""));
    list = list.substr(0, list.find("]]") + 2);
    std::vector<double> out;
    std::regex pair("\\[([^,\\[\\]]+), ([^\\]]+)\\]");
    for (auto it = std::sregex_iterator(list.begin(), list.end(), pair); it != std::sregex_iterator(); ++it)
      out.push_back(std::abs(std::stod((*it)[2].str())));
    std::sort(out.begin(), out.end());
    return out;
  };
  std::vector<double> fa = frequencies(a.out), fb = frequencies(b.out);
  ASSERT_EQ(fa.size(), 8u) << a.out;
  ASSERT_EQ(fb.size(), 8u) << b.out;
  for (std::size_t i = 0; i < fa.size(); ++i) EXPECT_NEAR(fa[i], fb[i], 1e-9 * fa.back());
}

// A three-joint arm written for Hamilton (models/measured_arm.toml): its M, of 277 nodes, is no
// longer inverted in closed form (that had not been simplified after 300 s); the header solves
// M der(q) = p, and the motion is Lagrange II's
TEST(Hamilton, AThreeJointArmSolvesForItsVelocitiesAsLargerModelsDo) {
  std::string text = edited(read_file(model_path("measured_arm")), {{"method     = \"lagrange2\"", "method = \"hamilton\""}});
  Equations h = derive_text(text, "measured_arm_hamilton.toml");
  EXPECT_TRUE(h.solves_for_velocities());
  std::string dir = temporary_directory(), model = write_model("measured_arm_hamilton", text);
  std::string common = " --t-end 2 --dt-out 0.1 --integrator cvode-bdf --rtol 1e-12 --atol 1e-13";
  ASSERT_EQ(run_eomgen("simulate '" + model_path("measured_arm") + "'" + common + " -o '" + dir + "/l.csv'").status, 0);
  CommandOutput r = run_eomgen("simulate '" + model + "'" + common + " -o '" + dir + "/h.csv'");
  ASSERT_EQ(r.status, 0) << r.err;
  auto lagrange = read_numeric_csv(dir + "/l.csv"), hamilton = read_numeric_csv(dir + "/h.csv");
  ASSERT_EQ(lagrange.size(), hamilton.size());
  for (std::size_t k = 0; k < lagrange.size(); ++k)
    for (std::size_t i = 1; i <= 3; ++i) EXPECT_NEAR(hamilton[k][i], lagrange[k][i], 1e-8) << "t = " << lagrange[k][0];
}

}  // namespace
}  // namespace eomgen::test
