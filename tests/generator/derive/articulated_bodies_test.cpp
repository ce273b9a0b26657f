// The articulated-body recursion for trees of particles (derive/articulated_bodies.hpp): its q''
// against M⁻¹ f of the same model at random states, where eomgen chooses it or a test asks for it
// (ModelChoice::forward_dynamics, `generate --forward-dynamics`), and the located refusals when a
// model is not such a tree or a file has the retired key.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>

#include <fmt/format.h>

#include "derive/articulated_bodies.hpp"
#include "pipeline.hpp"
#include "support/test_support.hpp"

namespace eomgen {
namespace {

using GiNaC::ex;
using test::solved_linear_system;
using test::value_at;


constexpr ForwardDynamics articulated = ForwardDynamics::articulated;

std::string diagnostics_of(const std::string& text, ForwardDynamics form = articulated) {
  ModelChoice choice;
  choice.forward_dynamics = form;
  return derive_model_text(text, "tree.toml", choice).diagnostics.format();
}

// derived with its rhs by the articulated-body recursion, whatever its size
Equations derive_articulated(const std::string& text) { return test::derive_text(text, "model.toml", test::solved_by(articulated)); }

// the planar n-link chain of the peer benchmark (absolute angles), with a torsion spring at the
// first joint, a damper at the last, and a force input at the tip
std::string planar_chain(int n) {
  std::string out = "[model]\nname = \"chain\"\n[parameters]\ng = 9.81\nk = 3.0\nd = 0.4\n";
  for (int i = 1; i <= n; ++i) out += fmt::format("m{0} = {1}\nl{0} = {2}\n", i, 0.5 + 0.1 * i, 0.3 + 0.05 * i);
  out += "[coordinates]\n";
  for (int i = 1; i <= n; ++i) out += fmt::format("phi{} = {}\n", i, 0.1 * i);
  out += "[inputs]\nF = 0.0\n";
  std::string x, y;
  for (int i = 1; i <= n; ++i) {
    x += fmt::format("{}l{}*sin(phi{})", i > 1 ? " + " : "", i, i);
    y += fmt::format(" - l{}*cos(phi{})", i, i);
    out += fmt::format("[[particles]]\nname = \"b{}\"\nmass = \"m{}\"\nposition = [\"{}\", \"{}\", \"0\"]\n", i, i, x, y);
  }
  out += "[gravity]\nacceleration = [\"0\", \"-g\", \"0\"]\n";
  out += fmt::format("[energy]\npotential = \"k*phi1^2/2\"\ndissipation = \"d*der(phi{})^2/2\"\n", n);
  out += fmt::format("[[forces]]\nat = [\"{}\", \"{}\", \"0\"]\nforce = [\"F\", \"0\", \"0\"]\n", x, y);
  return out;
}

// A free particle (a joint of three coordinates) on a spring, carrying a pendulum and a ballast fixed
// to it by a constant offset (a joint without coordinates); `driven`: a spring coupling x and z, a
// damped pendulum and a force input at the bob
std::string free_particle_carrying_a_pendulum(const std::string& name, bool driven) {
  std::string out = "[model]\nname = \"" + name + "\"\n"
                    "[parameters]\nm = 1.5\nk = 4.0\nl = 0.7\ng = 9.81\n";
  if (driven) out += "c = 0.3\n";
  out += "[coordinates]\nx = 0.1\ny = 0.2\nz = 0.3\na = 0.4\n";
  if (driven) out += "[inputs]\nF = 0.0\n";
  out += "[[particles]]\nname = \"carrier\"\nmass = \"m\"\nposition = [\"x\", \"y\", \"z\"]\n"
         "[[particles]]\nname = \"ballast\"\nmass = \"m/3\"\nposition = [\"x + 0.2\", \"y\", \"z - 0.1\"]\n"
         "[[particles]]\nname = \"bob\"\nmass = \"2*m\"\nposition = [\"x + l*sin(a)\", \"y\", \"z - l*cos(a)\"]\n"
         "[gravity]\nacceleration = [\"0\", \"0\", \"-g\"]\n";
  if (!driven) return out + "[energy]\npotential = \"k*(x^2 + y^2 + z^2)/2\"\n";
  return out + "[energy]\npotential = \"k*(x^2 + y^2 + z^2)/2 + k*x*z\"\ndissipation = \"c*der(a)^2/2\"\n"
               "[[forces]]\nat = [\"x + l*sin(a)\", \"y\", \"z - l*cos(a)\"]\nforce = [\"F\", \"F\", \"0\"]\n";
}

// a random state with a random held q'', and the recursion's quantities there, in their order
GiNaC::exmap with_intermediates(const Equations& e, const GiNaC::exmap& random, unsigned seed) {
  GiNaC::exmap at = random;
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> uniform(-2, 2);
  for (const GiNaC::symbol& a : e.acceleration_symbols()) at[a] = uniform(generator);
  for (const GiNaC::symbol& b : e.articulated()->inverse_dynamics.forces) at[b] = uniform(generator);
  for (const Intermediate& i : e.articulated()->intermediates) at[i.symbol] = value_at(i.definition, at);
  return at;
}

// the recursion's q'' against M⁻¹ f, and its M⁻¹ b against M⁻¹ b, at random states and b
void expect_recursion_solves_the_equations(const Equations& e, int points, unsigned seed) {
  ASSERT_TRUE(e.articulated());
  std::size_t n = e.symbols.num_coordinates();
  for (const GiNaC::exmap& random : test::random_points(e.symbols, points, seed)) {
    GiNaC::exmap at = with_intermediates(e, random, seed);
    std::vector<std::vector<double>> M(n, std::vector<double>(n));
    std::vector<double> f(n);
    for (unsigned j = 0; j < n; ++j) {
      f[j] = value_at(e.forcing[j], random);
      for (unsigned k = 0; k < n; ++k) M[j][k] = value_at(e.mass_matrix(j, k), random);
    }
    std::vector<double> expected = solved_linear_system(M, f), b;
    for (std::size_t j = 0; j < n; ++j) {
      double got = value_at(e.articulated()->accelerations[j], at);
      EXPECT_NEAR(got, expected[j], 1e-10 * std::max(1.0, std::abs(expected[j])))
          << e.model_name << ": q''[" << j << "] of " << n;
      b.push_back(value_at(e.articulated()->inverse_dynamics.forces[j], at));
    }
    // M⁻¹ b for the Jacobian's columns, by the same recursion without gravity and velocities
    std::vector<double> response = solved_linear_system(M, b);
    for (std::size_t j = 0; j < n; ++j)
      EXPECT_NEAR(value_at(e.articulated()->inverse_dynamics.accelerations_of_forces[j], at), response[j],
                  1e-10 * std::max(1.0, std::abs(response[j])))
          << e.model_name << ": (M^-1 b)[" << j << "] of " << n;
  }
}

double dot_at(const Vector3& a, const Vector3& b, const GiNaC::exmap& at) { return value_at(a[0] * b[0] + a[1] * b[1] + a[2] * b[2], at); }

// the tree's inverse dynamics against the symbolic equations at random states and held q'':
// m̄ S_j · S_l against M, its f against f, m̄ S_j · ∂d''/∂x + rest against ∂(M q'' − f)/∂(q, q', u)
void expect_inverse_dynamics_of_the_equations(const Equations& e, int points, unsigned seed) {
  ASSERT_TRUE(e.articulated());
  const TreeInverseDynamics& tree = e.articulated()->inverse_dynamics;
  ASSERT_FALSE(tree.axes.empty());
  const Symbols& s = e.symbols;
  std::size_t n = s.num_coordinates();
  std::vector<ex> variables(s.coordinates.begin(), s.coordinates.end());
  variables.insert(variables.end(), s.velocities.begin(), s.velocities.end());
  variables.insert(variables.end(), s.inputs.begin(), s.inputs.end());
  std::size_t W = variables.size();
  std::vector<ex> tau(n);
  for (unsigned j = 0; j < n; ++j) {
    tau[j] = -e.forcing[j];
    for (unsigned c = 0; c < n; ++c) tau[j] += e.mass_matrix(j, c) * e.acceleration_symbols()[c];
  }
  for (const GiNaC::exmap& random : test::random_points(s, points, seed)) {
    GiNaC::exmap at = with_intermediates(e, random, seed + 1);
    for (unsigned j = 0; j < n; ++j) {
      double f = value_at(e.forcing[j], at);
      EXPECT_NEAR(value_at(tree.forcing[j], at), f, 1e-10 * std::max(1.0, std::abs(f))) << "f[" << j << "]";
      for (unsigned l = 0; l < n; ++l) {
        int k = tree.coupling[j * n + l];
        double mass = k < 0 ? 0 : value_at(tree.subtree_masses[std::size_t(k)], at);
        double M = value_at(e.mass_matrix(j, l), at);
        EXPECT_NEAR(mass * dot_at(tree.axes[j], tree.axes[l], at), M, 1e-10 * std::max(1.0, std::abs(M)))
            << "M[" << j << "][" << l << "]";
      }
      for (std::size_t v = 0; v < W; ++v) {
        double expected = value_at(tau[j].diff(GiNaC::ex_to<GiNaC::symbol>(variables[v])), at);
        double got = value_at(tree.gradient_rest[j * W + v], at);
        if (v < 2 * n) {
          std::size_t l = v % n;
          int k = tree.coupling[j * n + l];
          const Vector3& by = v < n ? tree.acceleration_by_coordinate[l] : tree.acceleration_by_velocity[l];
          if (k >= 0) got += value_at(tree.subtree_masses[std::size_t(k)], at) * dot_at(tree.axes[j], by, at);
        }
        EXPECT_NEAR(got, expected, 1e-9 * std::max(1.0, std::abs(expected))) << "dtau[" << j << "]/d" << variables[v];
      }
    }
  }
}

TEST(ArticulatedBodies, PlanarChainGivesMInverseF) {
  for (int n : {1, 2, 3, 5, 8}) {
    Equations e = derive_articulated(planar_chain(n));
    expect_recursion_solves_the_equations(e, 6, 40u + unsigned(n));
    expect_inverse_dynamics_of_the_equations(e, 3, 50u + unsigned(n));
  }
}

TEST(ArticulatedBodies, BranchedSpatialTreeGivesMInverseF) {
  // the crane hook: a spherical pendulum (two coordinates in one joint) carrying two planar pendulums
  Equations crane = derive_articulated(test::read_file(test::model_path("crane_hook_tree")));
  expect_recursion_solves_the_equations(crane, 8, 7u);
  expect_inverse_dynamics_of_the_equations(crane, 4, 8u);
  // a free particle (three coordinates, on a spring) carrying a pendulum, and a mass fixed to
  // that particle by a constant offset (a joint without coordinates)
  Equations carrier = derive_articulated(free_particle_carrying_a_pendulum("free", false));
  expect_recursion_solves_the_equations(carrier, 8, 9u);
  expect_inverse_dynamics_of_the_equations(carrier, 4, 10u);
}

// Variants of a tree: holding coordinates keeps a tree, whose recursion still gives M⁻¹ f; tying
// the coordinates of two joints does not, and the header falls back to M = LDLᵀ
TEST(ArticulatedBodies, VariantsOfATreeKeepTheRecursionOrFallBack) {
  std::string path = test::temporary_directory() + "/crane.toml";
  {
    std::ofstream(path) << test::read_file(test::model_path("crane_hook_tree"))
                        << "\n[variants.planar_hook]\nfreeze = [\"psi\"]\n\n[variants.tied]\ntie = { b = \"a\" }\n";
  }
  ModelChoice planar_hook{"", "planar_hook", {}}, tie{"", "tied", {}};
  planar_hook.forward_dynamics = tie.forward_dynamics = articulated;
  Derivation planar = derive_model_file_for(path, planar_hook);
  ASSERT_TRUE(planar.equations) << planar.diagnostics.format();
  EXPECT_EQ(planar.equations->symbols.num_coordinates(), 3u);
  expect_recursion_solves_the_equations(*planar.equations, 6, 3u);
  expect_inverse_dynamics_of_the_equations(*planar.equations, 3, 4u);
  Derivation tied = derive_model_file_for(path, tie);
  ASSERT_TRUE(tied.equations) << tied.diagnostics.format();
  EXPECT_FALSE(tied.equations->articulated());
}

TEST(ArticulatedBodies, AutoChoosesTheRecursionForLongTrees) {
  EXPECT_FALSE(test::derive_text(planar_chain(static_cast<int>(articulated_crossover) - 1)).articulated());
  EXPECT_TRUE(test::derive_text(planar_chain(static_cast<int>(articulated_crossover))).articulated());
  EXPECT_FALSE(test::derive_text(planar_chain(12), "model.toml", test::solved_by(ForwardDynamics::mass_matrix)).articulated());
  EXPECT_FALSE(test::derive_model("n_link_pendulum_4").articulated());
  EXPECT_FALSE(test::derive_model("crane_hook_tree").articulated()) << "4 coordinates";
}

TEST(ArticulatedBodies, ModelsThatAreNoTreeOfParticlesAreLocatedErrors) {
  std::string relative = planar_chain(2);
  relative.replace(relative.find("l2*sin(phi2)"), 12, "l2*sin(phi1 + phi2)");
  std::string message = diagnostics_of(relative);
  EXPECT_NE(message.find("tree.toml:1:1: error: --forward-dynamics: the articulated-body recursion needs a tree of "
                         "particles or of joints, and this model is neither: as particles, coordinate "
                         "'phi1' moves both 'b1' and 'b2'"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("hint: leave --forward-dynamics out, or use mass_matrix"), std::string::npos) << message;
  EXPECT_EQ(diagnostics_of(relative, ForwardDynamics::chosen), "") << "eomgen's choice falls back to M";
  std::string appell = planar_chain(2);
  appell.insert(appell.find("[parameters]"), "method = \"lagrange1\"\n");
  EXPECT_NE(diagnostics_of(appell).find("solves Lagrange's equations of the second kind (Appell's for a tree with ball or "
                                       "free joints), not method 'lagrange1'"),
            std::string::npos)
      << diagnostics_of(appell);
  std::string unused = planar_chain(2);
  unused.insert(unused.find("[inputs]"), "free = 0.0\n");
  EXPECT_NE(diagnostics_of(unused).find("coordinate 'free' moves no particle"), std::string::npos) << diagnostics_of(unused);
}

// The key that chose the form is retired: a file that has it is told where, and what to do instead
TEST(ArticulatedBodies, TheRetiredKeyIsALocatedErrorWithAHint) {
  for (const char* form : {"auto", "articulated", "mass_matrix"}) {
    std::string text = planar_chain(9);
    text.insert(text.find("[parameters]"), fmt::format("forward_dynamics = \"{}\"\n", form));
    std::string message = diagnostics_of(text, ForwardDynamics::chosen);
    EXPECT_NE(message.find("tree.toml:3:20: error: model.forward_dynamics: the key is retired: eomgen chooses how the "
                           "header's rhs solves for q''"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find(fmt::format("a tree of particles of {} coordinates or more", articulated_crossover)),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("hint: remove the line; `eomgen generate --forward-dynamics mass_matrix`"), std::string::npos)
        << message;
  }
}


// The generated header of a long chain (M and ∂τ/∂x as loops over the coupled pairs of joints):
// rhs against M⁻¹ f from mass_matrix and forcing, jacobian_state against central differences of
// rhs, jacobian_input against those of rhs in u, linearization's P, Q, B against central differences
// of forcing, at random states.
const char* header_check = R"cpp(
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <vector>
#include "chain.hpp"
namespace m = eomgen::models::chain;
constexpr int n = int(m::num_coordinates), N = int(m::num_states), k = int(m::num_inputs);

std::vector<double> solve(std::vector<double> A, std::vector<double> b) {
  for (int c = 0; c < n; ++c)
    for (int r = c + 1; r < n; ++r) {
      double factor = A[r * n + c] / A[c * n + c];
      for (int j = c; j < n; ++j) A[r * n + j] -= factor * A[c * n + j];
      b[r] -= factor * b[c];
    }
  for (int r = n - 1; r >= 0; --r) {
    for (int j = r + 1; j < n; ++j) b[r] -= A[r * n + j] * b[j];
    b[r] /= A[r * n + r];
  }
  return b;
}

double worst = 0;
int failures = 0;
void expect(double got, double want, double scale, double tolerance, const char* what) {
  double error = std::abs(got - want) / std::max(1.0, scale);
  if (error > worst) worst = error;
  if (error > tolerance) ++failures, std::printf("%s: %.17g against %.17g\n", what, got, want);
}

int main() {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> uniform(-1, 1);
  auto p = m::Parameters<double>().values();
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<double> x(N), u(k), xdot(N), M(n * n), f(n), J(N * N), P(n * n), Q(n * n), B(n * k), Bx(N * k);
    for (double& v : x) v = 2 * uniform(random);
    for (double& v : u) v = uniform(random);
    m::rhs(0.0, x.data(), u.data(), p.data(), xdot.data());
    m::mass_matrix(0.0, x.data(), p.data(), M.data());
    m::forcing(0.0, x.data(), u.data(), p.data(), f.data());
    std::vector<double> ddq = solve(M, f);
    double scale = 0;
    for (double a : ddq) scale = std::max(scale, std::abs(a));
    for (int i = 0; i < n; ++i) expect(xdot[n + i], ddq[i], scale, 1e-10, "q''");
    m::jacobian_state(0.0, x.data(), u.data(), p.data(), J.data());
    m::linearization(0.0, x.data(), u.data(), p.data(), P.data(), Q.data(), B.data());
    m::jacobian_input(0.0, x.data(), u.data(), p.data(), Bx.data());
    for (int j = 0; j < N + k; ++j) {
      std::vector<double> xp = x, xm = x, up = u, um = u, rp(N), rm(N), fp(n), fm(n);
      double h = 1e-6;
      (j < N ? xp[j] : up[j - N]) += h;
      (j < N ? xm[j] : um[j - N]) -= h;
      m::rhs(0.0, xp.data(), up.data(), p.data(), rp.data());
      m::rhs(0.0, xm.data(), um.data(), p.data(), rm.data());
      m::forcing(0.0, xp.data(), up.data(), p.data(), fp.data());
      m::forcing(0.0, xm.data(), um.data(), p.data(), fm.data());
      for (int i = 0; i < N && j < N; ++i) expect(J[i * N + j], (rp[i] - rm[i]) / (2 * h), scale * 10, 1e-6, "J");
      for (int i = 0; i < N && j >= N; ++i) expect(Bx[i * k + j - N], (rp[i] - rm[i]) / (2 * h), scale * 10, 1e-6, "jacobian_input");
      for (int i = 0; i < n; ++i) {
        double df = (fp[i] - fm[i]) / (2 * h);
        if (j < n) expect(Q[i * n + j], -df, 100, 1e-6, "Q");
        else if (j < N) expect(P[i * n + j - n], -df, 100, 1e-6, "P");
        else expect(B[i * k + j - N], df, 100, 1e-6, "B");
      }
    }
  }
  std::printf("largest relative error %.3g\n", worst);
  return failures > 0 ? 1 : 0;
}
)cpp";

// generates the model (named "chain"), finds each of `expected_code` in the header and runs header_check on it
void expect_header_agrees(const std::string& text, const std::vector<std::string>& expected_code) {
  std::string dir = test::temporary_directory();
  {
    std::ofstream(dir + "/chain.toml") << text;
    std::ofstream(dir + "/check.cpp") << header_check;
  }
  test::CommandOutput generated =
      test::run_eomgen("generate --forward-dynamics articulated '" + dir + "/chain.toml' -o '" + dir + "'");
  ASSERT_EQ(generated.status, 0) << generated.err;
  std::string header = test::read_file(dir + "/chain.hpp");
  for (const std::string& code : expected_code) EXPECT_NE(header.find(code), std::string::npos) << "expected " << code;
  EXPECT_NE(header.find("articulated-body recursion"), std::string::npos);
  EXPECT_EQ(test::run_command("cd '" + dir + "' && c++ -std=c++17 -O1 check.cpp -o check && ./check"), 0);
}

// the planar chain's Jacobian by one carry per step (emit/cpp_articulated_jacobian.cpp); a spring
// between the first two links puts entries of ∂τ/∂q off the carriers' rows, which go through M⁻¹
TEST(ArticulatedBodies, LongChainHeaderAgreesWithItsMassMatrixAndDifferences) {
  std::string text = planar_chain(13);
  std::size_t at = text.find("potential = \"k*phi1^2/2\"");
  ASSERT_NE(at, std::string::npos);
  text.insert(at + 23, " + k*(phi2 - phi1)^2/2");
  expect_header_agrees(text, {"const int k = coupling[j * 13 + l];", "delta[j] = d * carry[m];",
                              "static constexpr int rest_column[2] = {1, 0};"});
}

// a particle free in the plane (two coordinates in one joint) carrying a pendulum: a planar chain whose
// nodes carry different numbers of columns (none at x, four at y, two at phi)
TEST(ArticulatedBodies, PlanarChainWithATwoCoordinateJointAgreesWithItsMassMatrixAndDifferences) {
  std::string text = "[model]\nname = \"chain\"\n"
                     "[parameters]\nm1 = 2.0\nm2 = 0.6\nl = 0.8\ng = 9.81\nk = 5.0\nc = 0.3\n"
                     "[coordinates]\nx = 0.2\ny = -0.1\nphi = 0.7\n[inputs]\nF = 0.0\n"
                     "[[particles]]\nname = \"p1\"\nmass = \"m1\"\nposition = [\"x\", \"y\", \"0\"]\n"
                     "[[particles]]\nname = \"p2\"\nmass = \"m2\"\nposition = [\"x + l*sin(phi)\", \"y - l*cos(phi)\", \"0\"]\n"
                     "[gravity]\nacceleration = [\"0\", \"-g\", \"0\"]\n"
                     "[energy]\npotential = \"k*(x^2 + y^2)/2\"\ndissipation = \"c*(der(x)^2 + der(phi)^2)/2\"\n"
                     "[[forces]]\nat = [\"x + l*sin(phi)\", \"y - l*cos(phi)\", \"0\"]\nforce = [\"F\", \"0\", \"0\"]\n";
  expect_header_agrees(text, {"for (int j = 0; j < m - 1; ++j) delta[j] = delta[j] * carry[m];"});
}

// a spatial chain (two spherical pendulums, four coordinates in two joints) with a mass fixed to the
// second one by a constant offset (a joint without coordinates, its mass carried by the last axis)
TEST(ArticulatedBodies, SpatialChainHeaderAgreesWithItsMassMatrixAndDifferences) {
  std::string r1 = "L1*sin(a1)*cos(b1)\", \"L1*sin(a1)*sin(b1)\", \"-L1*cos(a1)";
  std::string r2 = "L1*sin(a1)*cos(b1) + L2*sin(a2)*cos(b2)\", \"L1*sin(a1)*sin(b1) + L2*sin(a2)*sin(b2)\", "
                   "\"-L1*cos(a1) - L2*cos(a2)";
  std::string r3 = "L1*sin(a1)*cos(b1) + L2*sin(a2)*cos(b2) + 0.1\", \"L1*sin(a1)*sin(b1) + L2*sin(a2)*sin(b2)\", "
                   "\"-L1*cos(a1) - L2*cos(a2) - 0.2";
  std::string text = "[model]\nname = \"chain\"\n"
                     "[parameters]\nm1 = 1.2\nm2 = 0.8\nm3 = 0.3\nL1 = 0.9\nL2 = 0.7\ng = 9.81\nc = 0.2\n"
                     "[coordinates]\na1 = 0.5\nb1 = 0.3\na2 = 0.8\nb2 = -0.4\n[inputs]\nF = 0.0\n"
                     "[[particles]]\nname = \"p1\"\nmass = \"m1\"\nposition = [\"" + r1 + "\"]\n"
                     "[[particles]]\nname = \"p2\"\nmass = \"m2\"\nposition = [\"" + r2 + "\"]\n"
                     "[[particles]]\nname = \"p3\"\nmass = \"m3\"\nposition = [\"" + r3 + "\"]\n"
                     "[gravity]\nacceleration = [\"0\", \"0\", \"-g\"]\n"
                     "[energy]\ndissipation = \"c*(der(a2)^2 + der(b1)^2)/2\"\n"
                     "[[forces]]\nat = [\"" + r2 + "\"]\nforce = [\"0\", \"F\", \"0\"]\n";
  expect_header_agrees(text, {"const T A00 = across[m][0][0], A01 = across[m][0][1], A02 = across[m][0][2]",
                              "T* const out = load_column[k] >= 0 ? J + 32 + load_column[k]"});
}

// the free particle carrying a pendulum, driven: a spatial chain whose first two axes carry no mass,
// with columns of M⁻¹ for the spring coupling x and z
TEST(ArticulatedBodies, FreeParticleCarryingAPendulumHeaderAgreesWithItsMassMatrixAndDifferences) {
  expect_header_agrees(free_particle_carrying_a_pendulum("chain", true), {"static constexpr int first_load[5] = {0, 1, 2, 9, 12};"});
}

// a branched spatial tree with a two-coordinate joint: the crane hook, renamed
TEST(ArticulatedBodies, BranchedTreeHeaderAgreesWithItsMassMatrixAndDifferences) {
  std::string text = test::read_file(test::model_path("crane_hook_tree"));
  std::size_t at = text.find("\"crane_hook_tree\"");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 17, "\"chain\"");
  expect_header_agrees(text, {"if (branching[m]) {", "static constexpr bool branching[4] = {0, 1, 0, 0};"});
}

}  // namespace
}  // namespace eomgen
