// The generated headers against an independent evaluation: rhs, mass matrix,
// forcing, energies and outputs against GiNaC's evaluation of the derived
// equations (M⁻¹f solved exactly on 30-digit numbers) at 20 random states to
// 1e-12 relative; jacobian_state and jacobian_input against central differences
// (1e-6) and against complex-step differentiation (1e-12).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "generated/header_registry.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

struct State {
  double t;
  std::vector<double> x, u, p;
};

// coordinates of magnitude 0.2…1.3 with random sign keep away from the singular
// configurations of Euler and Cardan angles (where M loses rank)
std::vector<State> random_states(const GeneratedModel& m, int count) {
  std::mt19937 g(777);
  auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(g); };
  std::vector<State> states;
  for (int k = 0; k < count; ++k) {
    State s{uniform(0, 2), {}, {}, {}};
    for (std::size_t i = 0; i < m.num_coordinates; ++i) s.x.push_back((uniform(0, 1) < 0.5 ? -1 : 1) * uniform(0.2, 1.3));
    for (std::size_t i = m.num_coordinates; i < m.num_states; ++i) s.x.push_back(uniform(-2, 2));
    for (std::size_t i = 0; i < m.num_inputs; ++i) s.u.push_back(uniform(-1, 1));
    s.u.push_back(0);
    for (std::size_t i = 0; i < m.num_parameters; ++i) s.p.push_back(m.default_parameters[i] * uniform(0.7, 1.3));
    states.push_back(s);
  }
  return states;
}

GiNaC::exmap point_of(const Equations& e, const State& s) {
  const Symbols& y = e.symbols;
  GiNaC::exmap point{{y.time, GiNaC::numeric(s.t)}};
  std::size_t n = y.num_coordinates();
  for (std::size_t i = 0; i < n; ++i) point[y.coordinates[i]] = GiNaC::numeric(s.x[i]);
  for (std::size_t i = 0; i < y.velocities.size(); ++i) point[y.velocities[i]] = GiNaC::numeric(s.x[n + i]);
  for (std::size_t i = 0; i < y.parameters.size(); ++i) point[y.parameters[i]] = GiNaC::numeric(s.p[i]);
  for (std::size_t i = 0; i < y.inputs.size(); ++i) point[y.inputs[i]] = GiNaC::numeric(s.u[i]);
  // recursive kinematics: each intermediate from its definition, in order
  for (const Intermediate& i : e.intermediates) point[i.symbol] = i.definition.subs(point).evalf();
  return point;
}

double real_value(const GiNaC::ex& e) { return GiNaC::ex_to<GiNaC::numeric>(e.evalf()).to_double(); }

::testing::AssertionResult close(double actual, double expected, double tolerance, double scale = 1) {
  if (std::abs(actual - expected) <= tolerance * std::max({1.0, std::abs(expected), scale})) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << actual << " vs " << expected << " (tolerance " << tolerance << ")";
}

// q'' (and λ) solved exactly: M q'' = f, or for Lagrange I the augmented system
// [M −Cᵀ; C 0][q''; λ] = [f; −γ − 2α(C q' + b) − β² g] with the header's default gains
GiNaC::matrix exact_accelerations(const Equations& e, const GiNaC::exmap& point, double alpha, double beta) {
  std::size_t n = e.forcing.size(), m = e.has_multipliers ? e.constraints.size() : 0;
  const ConstraintSet& c = e.constraints;
  GiNaC::matrix K(n + m, n + m), right(n + m, 1), unknown(n + m, 1);
  for (unsigned i = 0; i < n; ++i) {
    right(i, 0) = e.forcing[i].subs(point).evalf();
    for (unsigned j = 0; j < n; ++j) K(i, j) = e.mass_matrix(i, j).subs(point).evalf();
  }
  for (unsigned r = 0; r < m; ++r) {
    GiNaC::ex velocity = c.bias[r];
    for (unsigned j = 0; j < n; ++j) {
      K(n + r, j) = c.jacobian(r, j).subs(point).evalf();
      K(j, n + r) = -K(n + r, j);
      velocity += c.jacobian(r, j) * e.symbols.velocities[j];
    }
    GiNaC::ex gamma = c.acceleration_bias[r] + 2 * alpha * velocity + beta * beta * c.position[r];
    right(n + r, 0) = (-gamma).subs(point).evalf();
  }
  for (unsigned i = 0; i < n + m; ++i) unknown(i, 0) = GiNaC::symbol("a" + std::to_string(i));
  return K.solve(unknown, right);
}

// Hamilton's equations in mass-matrix form: der(q) solves M der(q) = p − b at the point
void add_velocities_from_momenta(const Equations& e, GiNaC::exmap& point) {
  const MomentumSolve& momentum = *e.momentum();
  std::size_t n = momentum.bias.size();
  GiNaC::matrix M(n, n), right(n, 1), unknown(n, 1);
  for (unsigned i = 0; i < n; ++i) {
    right(i, 0) = (e.symbols.velocities[i] - momentum.bias[i]).subs(point).evalf();
    for (unsigned j = 0; j < n; ++j) M(i, j) = momentum.mass_matrix(i, j).subs(point).evalf();
    unknown(i, 0) = GiNaC::symbol("v" + std::to_string(i));
  }
  GiNaC::matrix v = M.solve(unknown, right);
  for (unsigned i = 0; i < n; ++i) point[e.coordinate_velocities[i]] = v(i, 0);
}

class GeneratedHeader : public ::testing::TestWithParam<GeneratedModel> {};

TEST_P(GeneratedHeader, AgreesWithGinacEvaluation) {
  const GeneratedModel& m = GetParam();
  Equations e = derive_model(m.name);
  std::size_t nq = m.num_coordinates, n = m.num_states - nq;
  GiNaC::Digits = 30;
  for (const State& s : random_states(m, 20)) {
    GiNaC::exmap point = point_of(e, s);
    if (e.solves_for_velocities()) add_velocities_from_momenta(e, point);
    GiNaC::matrix accelerations = exact_accelerations(e, point, m.abi->baumgarte_alpha, m.abi->baumgarte_beta);
    std::vector<double> xdot(nq + n), Mh(n * n), fh(n), y(m.num_outputs + 1), lambda(m.abi->num_multipliers + 1);
    m.rhs(s.t, s.x.data(), s.u.data(), s.p.data(), xdot.data());
    m.mass_matrix(s.t, s.x.data(), s.p.data(), Mh.data());
    m.forcing(s.t, s.x.data(), s.u.data(), s.p.data(), fh.data());
    m.outputs(s.t, s.x.data(), s.u.data(), s.p.data(), y.data());
    double size = 0;
    for (unsigned i = 0; i < n; ++i) size = std::max(size, std::abs(real_value(accelerations(i, 0))));
    for (unsigned i = 0; i < nq; ++i) {
      if (e.uses_pseudo_velocities())
        EXPECT_TRUE(close(xdot[i], real_value(e.coordinate_rates[i].subs(point)), 1e-12)) << m.name << " q'[" << i << "]";
      else
        EXPECT_EQ(xdot[i], s.x[nq + i]);
    }
    for (unsigned i = 0; i < n; ++i) {
      EXPECT_TRUE(close(xdot[nq + i], real_value(accelerations(i, 0)), 1e-12, size)) << m.name << " q''[" << i << "]";
      EXPECT_TRUE(close(fh[i], real_value(e.forcing[i].subs(point)), 1e-12)) << m.name << " f[" << i << "]";
      for (unsigned j = 0; j < n; ++j)
        EXPECT_TRUE(close(Mh[i * n + j], real_value(e.mass_matrix(i, j).subs(point)), 1e-12)) << m.name;
    }
    if (e.has_multipliers) {  // the multipliers have no Baumgarte terms
      GiNaC::matrix plain = exact_accelerations(e, point, 0, 0);
      m.abi->multipliers(s.t, s.x.data(), s.u.data(), s.p.data(), lambda.data());
      for (unsigned r = 0; r < e.constraints.size(); ++r)
        EXPECT_TRUE(close(lambda[r], real_value(plain(n + r, 0)), 1e-11)) << m.name << " lambda[" << r << "]";
    }
    EXPECT_TRUE(close(m.kinetic_energy(s.t, s.x.data(), s.p.data()), real_value(e.kinetic_energy.subs(point)), 1e-12));
    EXPECT_TRUE(close(m.potential_energy(s.t, s.x.data(), s.p.data()), real_value(e.potential_energy.subs(point)), 1e-12));
    for (std::size_t k = 0; k < m.num_outputs; ++k)
      EXPECT_TRUE(close(y[k], real_value(e.outputs[k].expression.subs(point)), 1e-12)) << m.name;
  }
  GiNaC::Digits = 17;
}

TEST_P(GeneratedHeader, JacobiansMatchDifferences) {
  const GeneratedModel& m = GetParam();
  std::size_t N = m.num_states, n_u = m.num_inputs;
  using cd = std::complex<double>;
  for (const State& s : random_states(m, 5)) {
    std::vector<double> J(N * N), B(N * n_u + 1), plus(N), minus(N);
    m.jacobian_state(s.t, s.x.data(), s.u.data(), s.p.data(), J.data());
    m.jacobian_input(s.t, s.x.data(), s.u.data(), s.p.data(), B.data());
    std::vector<cd> xc(s.x.begin(), s.x.end()), uc(s.u.begin(), s.u.end()), pc(s.p.begin(), s.p.end()), out(N);
    for (std::size_t j = 0; j < N; ++j) {
      double h = 1e-6 * std::max(1.0, std::abs(s.x[j]));
      std::vector<double> xp = s.x, xm = s.x;
      xp[j] += h;
      xm[j] -= h;
      m.rhs(s.t, xp.data(), s.u.data(), s.p.data(), plus.data());
      m.rhs(s.t, xm.data(), s.u.data(), s.p.data(), minus.data());
      std::vector<cd> xs = xc;
      xs[j] += cd(0, 1e-30);
      m.rhs_complex(cd(s.t), xs.data(), uc.data(), pc.data(), out.data());
      for (std::size_t i = 0; i < N; ++i) {
        // a central difference carries the rounding error of the whole row's terms, ε·Σ_k |J_ik x_k| / h
        double row = 0;
        for (std::size_t k = 0; k < N; ++k) row = std::max(row, std::abs(J[i * N + k]));
        EXPECT_TRUE(close(J[i * N + j], (plus[i] - minus[i]) / (2 * h), 1e-6, 1e-3 * row))
            << m.name << " J[" << i << "][" << j << "]";
        EXPECT_TRUE(close(J[i * N + j], out[i].imag() / 1e-30, 1e-12)) << m.name << " complex step J[" << i << "][" << j << "]";
      }
    }
    for (std::size_t j = 0; j < n_u; ++j) {
      std::vector<cd> us = uc;
      us[j] += cd(0, 1e-30);
      m.rhs_complex(cd(s.t), xc.data(), us.data(), pc.data(), out.data());
      for (std::size_t i = 0; i < N; ++i)
        EXPECT_TRUE(close(B[i * n_u + j], out[i].imag() / 1e-30, 1e-12)) << m.name << " B[" << i << "][" << j << "]";
    }
    // the complex instantiation of jacobian_state agrees with the real one
    std::vector<cd> Jc(N * N);
    m.jacobian_state_complex(cd(s.t), xc.data(), uc.data(), pc.data(), Jc.data());
    for (std::size_t k = 0; k < N * N; ++k) EXPECT_TRUE(close(Jc[k].real(), J[k], 1e-14));
  }
}

INSTANTIATE_TEST_SUITE_P(EveryModel, GeneratedHeader, ::testing::ValuesIn(generated_models()),
                         [](const ::testing::TestParamInfo<GeneratedModel>& info) { return info.param.name; });

// float keeps about 6 digits through the unrolled solve; long double and the
// awkward scalar (which computes in double, in the same order) agree closely
TEST(GeneratedHeader, EveryScalarTypeAgreesWithDouble) {
  auto results = scalar_agreement();
  EXPECT_EQ(results.size(), generated_models().size());
  for (const ScalarAgreement& r : results) {
    EXPECT_LT(r.float_error, 1e-4) << r.model;
    EXPECT_LT(r.long_double_error, 1e-12) << r.model;
    EXPECT_LT(r.awkward_error, 1e-15) << r.model;
  }
}

}  // namespace
}  // namespace eomgen::test
