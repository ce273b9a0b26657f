// M and f of trees of particles formed from their subtree masses (derive/particle_tree_terms.hpp)
// against the closed form of the planar n-link pendulum in absolute angles,
//   M_jl = l_j l_l cos(φ_j − φ_l) Σ_{k ≥ max(j,l)} m_k,
//   f_j = −l_j Σ_l l_l sin(φ_j − φ_l) φ_l'² Σ_{k ≥ max(j,l)} m_k − g l_j sin φ_j Σ_{k ≥ j} m_k,
// and a branched tree against the sums over its particles written out by hand.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "pipeline.hpp"
#include "support/test_support.hpp"

namespace eomgen {
namespace {

using GiNaC::ex;
using test::value_at;


std::string planar_chain(int n) {
  std::string out = "[model]\nname = \"chain\"\n[parameters]\ng = 9.81\n";
  for (int i = 1; i <= n; ++i) out += fmt::format("m{0} = {1}\nl{0} = {2}\n", i, 0.5 + 0.1 * i, 0.3 + 0.05 * i);
  out += "[coordinates]\n";
  for (int i = 1; i <= n; ++i) out += fmt::format("phi{} = {}\n", i, 0.1 * i);
  std::string x, y;
  for (int i = 1; i <= n; ++i) {
    x += fmt::format("{}l{}*sin(phi{})", i > 1 ? " + " : "", i, i);
    y += fmt::format(" - l{}*cos(phi{})", i, i);
    out += fmt::format("[[particles]]\nname = \"b{}\"\nmass = \"m{}\"\nposition = [\"{}\", \"{}\", \"0\"]\n", i, i, x, y);
  }
  return out + "[gravity]\nacceleration = [\"0\", \"-g\", \"0\"]\n";
}


TEST(ParticleTreeTerms, PlanarChainHasTheClosedFormMAndF) {
  for (int n : {2, 5, 9}) {
    Equations e = test::derive_text(planar_chain(n), "model.toml", test::solved_by(ForwardDynamics::mass_matrix));
    const Symbols& s = e.symbols;
    auto mass_beyond = [&](int j) {
      ex m = 0;
      for (int k = j; k < n; ++k) m += test::parameter_named(s, fmt::format("m{}", k + 1));
      return m;
    };
    auto l = [&](int j) { return test::parameter_named(s, fmt::format("l{}", j + 1)); };
    ex g = test::parameter_named(s, "g");
    for (const GiNaC::exmap& at : test::random_points(s, 4, 30u + unsigned(n))) {
      for (int j = 0; j < n; ++j) {
        const ex& phi_j = s.coordinates[std::size_t(j)];
        ex f = -g * l(j) * sin(phi_j) * mass_beyond(j);
        for (int k = 0; k < n; ++k) {
          const ex& phi_k = s.coordinates[std::size_t(k)];
          ex coupling = l(j) * l(k) * mass_beyond(std::max(j, k));
          double M = value_at(coupling * cos(phi_j - phi_k), at);
          EXPECT_NEAR(value_at(e.mass_matrix(unsigned(j), unsigned(k)), at), M, 1e-12 * std::max(1.0, std::abs(M)))
              << "n = " << n << ": M[" << j << "][" << k << "]";
          f -= coupling * sin(phi_j - phi_k) * pow(s.velocities[std::size_t(k)], 2);
        }
        double expected = value_at(f, at);
        EXPECT_NEAR(value_at(e.forcing[std::size_t(j)], at), expected, 1e-12 * std::max(1.0, std::abs(expected)))
            << "n = " << n << ": f[" << j << "]";
      }
    }
  }
}

// a carrier on a slider (x) with two pendulums on it (a, b), one carrying a third (c), derived with
// the articulated-body recursion asked for, which refuses a model that is no tree. M and f against Σ_k m_k (J_kᵀ J_k, −J_kᵀ a_k) with the particles' Jacobians and accelerations by hand
TEST(ParticleTreeTerms, BranchedTreeIsTheSumOverItsParticles) {
  Equations e = test::derive_text(R"toml([model]
name = "branched"
[parameters]
m0 = 2.0
m1 = 0.7
m2 = 0.9
m3 = 0.4
l = 0.8
g = 9.81
[coordinates]
x = 0.1
a = 0.3
b = -0.2
c = 0.5
[[particles]]
name = "carrier"
mass = "m0"
position = ["x", "0", "0"]
[[particles]]
name = "left"
mass = "m1"
position = ["x + l*sin(a)", "-l*cos(a)", "0"]
[[particles]]
name = "right"
mass = "m2"
position = ["x + l*sin(b)", "0", "-l*cos(b)"]
[[particles]]
name = "tip"
mass = "m3"
position = ["x + l*sin(b) + l*sin(c)", "l*cos(c)", "-l*cos(b)"]
[gravity]
acceleration = ["0", "0", "-g"]
)toml", "model.toml", test::solved_by(ForwardDynamics::articulated));
  const Symbols& s = e.symbols;
  const std::vector<std::string> masses{"m0", "m1", "m2", "m3"};
  ex l = test::parameter_named(s, "l"), g = test::parameter_named(s, "g");
  const ex &x = s.coordinates[0], &a = s.coordinates[1], &b = s.coordinates[2], &c = s.coordinates[3];
  std::vector<std::array<ex, 3>> positions{{x, 0, 0},
                                           {x + l * sin(a), -l * cos(a), 0},
                                           {x + l * sin(b), 0, -l * cos(b)},
                                           {x + l * sin(b) + l * sin(c), l * cos(c), -l * cos(b)}};
  std::vector<ex> f(4, 0);
  GiNaC::matrix M(4, 4);
  for (std::size_t k = 0; k < 4; ++k) {
    ex m = test::parameter_named(s, masses[k]);
    for (unsigned d = 0; d < 3; ++d) {
      ex velocity = 0;
      for (unsigned q = 0; q < 4; ++q) velocity += positions[k][d].diff(GiNaC::ex_to<GiNaC::symbol>(s.coordinates[q])) * s.velocities[q];
      ex bias = 0;  // the acceleration at q'' = 0
      for (unsigned q = 0; q < 4; ++q) bias += velocity.diff(GiNaC::ex_to<GiNaC::symbol>(s.coordinates[q])) * s.velocities[q];
      for (unsigned j = 0; j < 4; ++j) {
        ex Jj = positions[k][d].diff(GiNaC::ex_to<GiNaC::symbol>(s.coordinates[j]));
        f[j] -= m * Jj * (bias + (d == 2 ? g : ex(0)));
        for (unsigned q = 0; q < 4; ++q) M(j, q) += m * Jj * positions[k][d].diff(GiNaC::ex_to<GiNaC::symbol>(s.coordinates[q]));
      }
    }
  }
  for (const GiNaC::exmap& at : test::random_points(s, 5, 77u))
    for (unsigned j = 0; j < 4; ++j) {
      double expected = value_at(f[j], at);
      EXPECT_NEAR(value_at(e.forcing[j], at), expected, 1e-12 * std::max(1.0, std::abs(expected))) << "f[" << j << "]";
      for (unsigned q = 0; q < 4; ++q) {
        double Mjq = value_at(M(j, q), at);
        EXPECT_NEAR(value_at(e.mass_matrix(j, q), at), Mjq, 1e-12 * std::max(1.0, std::abs(Mjq))) << "M[" << j << "][" << q << "]";
      }
    }
}

}  // namespace
}  // namespace eomgen
