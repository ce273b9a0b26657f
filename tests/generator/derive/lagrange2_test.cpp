// Known answers: for every model in models/, the mass matrix and forcing of
// Lagrange II against closed forms written out here from the textbook
// equations, compared at 20 random points to 1e-12 relative.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "support/test_support.hpp"
#include "symbolic/canonical_print.hpp"

namespace eomgen::test {
namespace {

using Rows = std::vector<std::vector<std::string>>;

void expect_equations(const std::string& model, const Rows& mass_matrix, const std::vector<std::string>& forcing) {
  Equations e = derive_model(model);
  std::size_t n = forcing.size();
  ASSERT_EQ(e.forcing.size(), n);
  ASSERT_EQ(e.degrees_of_freedom, n);
  auto points = random_points(e.symbols, 20);
  for (unsigned j = 0; j < n; ++j) {
    for (unsigned k = 0; k < n; ++k)
      EXPECT_TRUE(agree_at_points(e.mass_matrix(j, k), closed_form(e, mass_matrix[j][k]), points))
          << model << " M[" << j << "][" << k << "]";
    EXPECT_TRUE(agree_at_points(e.forcing[j], closed_form(e, forcing[j]), points)) << model << " f[" << j << "]";
  }
}

TEST(Lagrange2KnownAnswers, Pendulum) {
  expect_equations("pendulum", {{"m*l^2"}}, {"-m*g*l*sin(phi) - d*d_phi"});
}

// Pythagoras fires whatever the sign inside the argument: -l*sin(-phi) is l*sin(phi)
TEST(Lagrange2KnownAnswers, PendulumWrittenWithNegatedAngle) {
  Equations e = derive_text(R"toml([model]
name = "negated_angle"
[parameters]
m = 1.0
l = 1.0
g = 9.81
[coordinates]
phi = 0.1
[[particles]]
name = "bob"
mass = "m"
position = ["-l*sin(-phi)", "-l*cos(phi)", "0"]
[gravity]
acceleration = ["0", "-g", "0"]
)toml");
  EXPECT_EQ(canonical_text(e.mass_matrix(0, 0)), "l^2*m");
  EXPECT_TRUE(agree_at_points(e.forcing[0], closed_form(e, "-m*g*l*sin(phi)"), random_points(e.symbols, 5)));
}

TEST(Lagrange2KnownAnswers, DoublePendulum) {
  expect_equations("double_pendulum",
                   {{"(m1+m2)*l1^2", "m2*l1*l2*cos(phi1-phi2)"}, {"m2*l1*l2*cos(phi1-phi2)", "m2*l2^2"}},
                   {"-m2*l1*l2*d_phi2^2*sin(phi1-phi2) - (m1+m2)*g*l1*sin(phi1) + tau",
                    "m2*l1*l2*d_phi1^2*sin(phi1-phi2) - m2*g*l2*sin(phi2)"});
}

TEST(Lagrange2KnownAnswers, SphericalPendulum) {
  expect_equations("spherical_pendulum", {{"m*l^2", "0"}, {"0", "m*l^2*sin(theta)^2"}},
                   {"m*l^2*sin(theta)*cos(theta)*d_phi^2 - m*g*l*sin(theta)",
                    "-2*m*l^2*sin(theta)*cos(theta)*d_theta*d_phi"});
}

TEST(Lagrange2KnownAnswers, CartPendulum) {
  expect_equations("cart_pendulum", {{"mc+m", "m*l*cos(theta)"}, {"m*l*cos(theta)", "m*l^2"}},
                   {"F + m*l*d_theta^2*sin(theta)", "-m*g*l*sin(theta)"});
}

TEST(Lagrange2KnownAnswers, TwoMassSpringDamper) {
  expect_equations("two_mass_spring_damper", {{"m1", "0"}, {"0", "m2"}},
                   {"-k1*x1 + k2*(x2-x1) - d1*d_x1 + d2*(d_x2-d_x1)", "-k2*(x2-x1) - d2*(d_x2-d_x1) + F"});
}

TEST(Lagrange2KnownAnswers, PhysicalPendulumUsesSteiner) {
  expect_equations("physical_pendulum", {{"Izz + m*s^2"}}, {"-m*g*s*sin(phi) + M"});
}

TEST(Lagrange2KnownAnswers, BeadOnRotatingHoopIsRheonomic) {
  expect_equations("bead_on_rotating_hoop", {{"m*r^2"}},
                   {"m*r^2*Omega^2*sin(theta)*cos(theta) - m*g*r*sin(theta)"});
}

TEST(Lagrange2KnownAnswers, WattGovernor) {
  expect_equations("watt_governor", {{"J + 2*m*l^2*n^2*sin(theta)^2", "0"}, {"0", "2*m*l^2"}},
                   {"kappa*cos(theta) - P - 4*m*l^2*n^2*sin(theta)*cos(theta)*d_theta*d_phi",
                    "2*m*l^2*n^2*sin(theta)*cos(theta)*d_phi^2 - 2*m*g*l*sin(theta) - b*d_theta"});
}

// T = ½A'(θ̇² + ψ̇² sin²θ) + ½C(φ̇ + ψ̇ cosθ)², V = m g s cosθ, A' = A + m s²
TEST(Lagrange2KnownAnswers, HeavySymmetricTop) {
  const std::string Ap = "(A + m*s^2)";
  expect_equations(
      "heavy_symmetric_top",
      {{Ap + "*sin(theta)^2 + C*cos(theta)^2", "0", "C*cos(theta)"}, {"0", Ap, "0"}, {"C*cos(theta)", "0", "C"}},
      {"-2*(" + Ap + " - C)*sin(theta)*cos(theta)*d_theta*d_psi + C*sin(theta)*d_theta*d_phi",
       Ap + "*d_psi^2*sin(theta)*cos(theta) - C*(d_phi + d_psi*cos(theta))*d_psi*sin(theta) + m*g*s*sin(theta)",
       "C*sin(theta)*d_theta*d_psi"});
}

// ω_B of cardan123 from the textbook, T = ½ ωᵀ diag(A,B,C) ω, Q = Wᵀ M_B with ω = W q̇;
// the Lagrange equations are formed here by plain differentiation.
TEST(Lagrange2KnownAnswers, GimbalCardanAgainstDirectLagrange) {
  Equations e = derive_model("gimbal_cardan");
  const Symbols& s = e.symbols;
  std::vector<GiNaC::ex> w = {closed_form(e, "d_alpha*cos(beta)*cos(gamma) + d_beta*sin(gamma)"),
                              closed_form(e, "-d_alpha*cos(beta)*sin(gamma) + d_beta*cos(gamma)"),
                              closed_form(e, "d_alpha*sin(beta) + d_gamma")};
  std::vector<GiNaC::ex> inertia = {closed_form(e, "A"), closed_form(e, "B"), closed_form(e, "C")};
  std::vector<GiNaC::ex> torque = {closed_form(e, "Mx"), closed_form(e, "My"), closed_form(e, "Mz")};
  GiNaC::ex T = 0;
  for (int a = 0; a < 3; ++a) T += inertia[a] * w[a] * w[a] / 2;
  auto points = random_points(s, 20);
  for (unsigned j = 0; j < 3; ++j) {
    GiNaC::ex p = T.diff(s.velocities[j]);
    GiNaC::ex f = T.diff(s.coordinates[j]);
    for (unsigned k = 0; k < 3; ++k) {
      EXPECT_TRUE(agree_at_points(e.mass_matrix(j, k), p.diff(s.velocities[k]), points));
      f -= p.diff(s.coordinates[k]) * s.velocities[k];
    }
    for (int a = 0; a < 3; ++a) f += w[a].diff(s.velocities[j]) * torque[a];
    EXPECT_TRUE(agree_at_points(e.forcing[j], f, points)) << "f[" << j << "]";
  }
}

// M_jk = (Σ_{i ≥ max(j,k)} m_i) l_j l_k cos(φ_j − φ_k),
// f_j = −Σ_k (Σ_{i ≥ max(j,k)} m_i) l_j l_k sin(φ_j − φ_k) φ̇_k² − (Σ_{i ≥ j} m_i) g l_j sin φ_j
TEST(Lagrange2KnownAnswers, FourLinkPendulum) {
  const int n = 4;
  auto tail_mass = [](int from) {
    std::string s;
    for (int i = from; i <= n; ++i) s += fmt::format("{}m{}", i == from ? "" : "+", i);
    return "(" + s + ")";
  };
  Rows M(n, std::vector<std::string>(n));
  std::vector<std::string> f(n);
  for (int j = 1; j <= n; ++j) {
    f[j - 1] = fmt::format("-{}*g*l{}*sin(phi{})", tail_mass(j), j, j);
    for (int k = 1; k <= n; ++k) {
      M[j - 1][k - 1] = fmt::format("{}*l{}*l{}*cos(phi{}-phi{})", tail_mass(std::max(j, k)), j, k, j, k);
      f[j - 1] += fmt::format(" - {}*l{}*l{}*sin(phi{}-phi{})*d_phi{}^2", tail_mass(std::max(j, k)), j, k, j, k, k);
    }
  }
  expect_equations("n_link_pendulum_4", M, f);
}


TEST(Lagrange2KnownAnswers, FollowerForcePendulum) {
  expect_equations("follower_force_pendulum",
                   {{"3*m*l^2", "m*l^2*cos(phi1-phi2)"}, {"m*l^2*cos(phi1-phi2)", "m*l^2"}},
                   {"-m*l^2*d_phi2^2*sin(phi1-phi2) - c*phi1 + c*(phi2-phi1) + P*l*sin(phi1-phi2)",
                    "m*l^2*d_phi1^2*sin(phi1-phi2) - c*(phi2-phi1)"});
}

// T = ½ m ((ξ' − Ωη)² + (η' + Ωξ)²) in the frame turning with the shaft
TEST(Lagrange2KnownAnswers, JeffcottRotorInTheRotatingFrame) {
  expect_equations("jeffcott_rotor", {{"m", "0"}, {"0", "m"}},
                   {"2*m*Omega*d_eta + m*Omega^2*xi - k*xi - d*d_xi", "-2*m*Omega*d_xi + m*Omega^2*eta - k*eta - d*d_eta"});
}

TEST(Lagrange2KnownAnswers, DampedTwoMassOscillator) {
  expect_equations("damped_two_mass_oscillator", {{"m1", "0"}, {"0", "m2"}},
                   {"-k1*x1 + k2*(x2-x1) + d*(d_x2-d_x1) + F", "-k2*(x2-x1) - d*(d_x2-d_x1)"});
}

// ω_B = Cardan rates (as for the gimbal) plus the orbit rate −Ω e_y seen in the body:
// R_OBᵀ(0, −Ω, 0) with R_OB = rot_x(φ) rot_y(θ) rot_z(ψ); T = ½ ωᵀ diag(A,B,C) ω, V as in the model
TEST(Lagrange2KnownAnswers, SatelliteAgainstDirectLagrange) {
  Equations e = derive_model("satellite_gravity_gradient");
  const Symbols& s = e.symbols;
  auto c = [&](const std::string& text) { return closed_form(e, text); };
  // second row of R_OB: (cφ sψ + sφ sθ cψ, cφ cψ − sφ sθ sψ, −sφ cθ)
  std::vector<GiNaC::ex> row2 = {c("cos(phi)*sin(psi) + sin(phi)*sin(theta)*cos(psi)"),
                                 c("cos(phi)*cos(psi) - sin(phi)*sin(theta)*sin(psi)"), c("-sin(phi)*cos(theta)")};
  std::vector<GiNaC::ex> w = {c("d_phi*cos(theta)*cos(psi) + d_theta*sin(psi)"),
                              c("-d_phi*cos(theta)*sin(psi) + d_theta*cos(psi)"), c("d_phi*sin(theta) + d_psi")};
  for (int a = 0; a < 3; ++a) w[a] += -c("Omega") * row2[a];
  std::vector<GiNaC::ex> inertia = {c("A"), c("B"), c("C")};
  GiNaC::ex T = 0;
  for (int a = 0; a < 3; ++a) T += inertia[a] * w[a] * w[a] / 2;
  GiNaC::ex V = c("3/2*Omega^2*(A*(sin(phi)*sin(psi) - cos(phi)*sin(theta)*cos(psi))^2 + "
                  "B*(sin(phi)*cos(psi) + cos(phi)*sin(theta)*sin(psi))^2 + C*(cos(phi)*cos(theta))^2)");
  auto points = random_points(s, 20);
  for (unsigned j = 0; j < 3; ++j) {
    GiNaC::ex p = T.diff(s.velocities[j]);
    GiNaC::ex f = T.diff(s.coordinates[j]) - V.diff(s.coordinates[j]);
    for (unsigned k = 0; k < 3; ++k) {
      EXPECT_TRUE(agree_at_points(e.mass_matrix(j, k), p.diff(s.velocities[k]), points));
      f -= p.diff(s.coordinates[k]) * s.velocities[k];
    }
    EXPECT_TRUE(agree_at_points(e.forcing[j], f, points)) << "f[" << j << "]";
  }
}

// For every scleronomic model, T = ½ q̇ᵀ M q̇: the kinetic energy printed and the
// mass matrix derived agree (Hiller §3.5).
TEST(Lagrange2Consistency, KineticEnergyIsQuadraticFormOfMassMatrix) {
  for (const char* name : {"pendulum", "double_pendulum", "spherical_pendulum", "cart_pendulum", "physical_pendulum",
                           "watt_governor", "heavy_symmetric_top", "gimbal_cardan", "n_link_pendulum_4",
                           "two_mass_spring_damper", "follower_force_pendulum", "damped_two_mass_oscillator"}) {
    Equations e = derive_model(name);
    GiNaC::ex quadratic = 0;
    std::size_t n = e.forcing.size();
    for (unsigned j = 0; j < n; ++j)
      for (unsigned k = 0; k < n; ++k)
        quadratic += e.symbols.velocities[j] * e.mass_matrix(j, k) * e.symbols.velocities[k] / 2;
    EXPECT_TRUE(agree_at_points(e.kinetic_energy, quadratic, random_points(e.symbols, 20))) << name;
  }
}

TEST(Lagrange2Consistency, MassMatrixIsSymmetric) {
  Equations e = derive_model("heavy_symmetric_top");
  for (unsigned j = 0; j < 3; ++j)
    for (unsigned k = 0; k < 3; ++k) EXPECT_TRUE((e.mass_matrix(j, k) - e.mass_matrix(k, j)).is_zero());
}

}  // namespace
}  // namespace eomgen::test

namespace eomgen::test {
namespace {

// rotating-frame rotor: P = d I + 2mΩ [[0, −1], [1, 0]], Q = (k − mΩ²) I (Hiller §8.2)
TEST(Linearization, JeffcottRotorSplitsIntoDampingGyroscopicAndStiffness) {
  Equations e = derive_model("jeffcott_rotor");
  add_linearization(e);
  ASSERT_TRUE(e.has_linearization);
  const char* P[2][2] = {{"d", "-2*m*Omega"}, {"2*m*Omega", "d"}};
  const char* Q[2][2] = {{"k - m*Omega^2", "0"}, {"0", "k - m*Omega^2"}};
  for (unsigned i = 0; i < 2; ++i)
    for (unsigned j = 0; j < 2; ++j) {
      EXPECT_TRUE((e.linear_damping_gyroscopic(i, j) - closed_form(e, P[i][j])).expand().is_zero()) << i << j;
      EXPECT_TRUE((e.linear_stiffness_circulatory(i, j) - closed_form(e, Q[i][j])).expand().is_zero()) << i << j;
    }
}

}  // namespace
}  // namespace eomgen::test
