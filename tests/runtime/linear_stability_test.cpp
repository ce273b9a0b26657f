// Linear stability against closed forms (Hiller §7, §8), the linearization
// against central differences of the nonlinear forcing, and each verdict against
// a simulation of a small perturbation of the nonlinear model.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "analyse/equilibrium.hpp"
#include "analyse/floquet.hpp"
#include "analyse/linear_stability.hpp"
#include "analyse/unbalanced_rate.hpp"
#include "generated/header_registry.hpp"

namespace eomgen::test {
namespace {

using runtime::Problem;

Problem problem_of(const std::string& name, const std::vector<std::pair<std::string, double>>& set = {}) {
  const eomgen_model_abi* m = generated_model(name).abi;
  Problem p{m, std::vector<double>(m->default_parameters, m->default_parameters + m->num_parameters),
            std::vector<double>(m->default_inputs, m->default_inputs + m->num_inputs)};
  for (const auto& [key, value] : set)
    for (std::size_t i = 0; i < m->num_parameters; ++i)
      if (key == m->parameter_names[i]) p.parameters[i] = value;
  return p;
}

double parameter(const Problem& p, const std::string& name) {
  for (std::size_t i = 0; i < p.model->num_parameters; ++i)
    if (name == p.model->parameter_names[i]) return p.parameters[i];
  throw std::runtime_error(name);
}

bool has_theorem(const runtime::StabilityReport& r, const std::string& name) {
  for (const std::string& t : r.theorems)
    if (t.rfind(name, 0) == 0) return true;
  return false;
}

TEST(Hurwitz, DeterminantsOfAKnownPolynomial) {
  // (λ+1)(λ+2)(λ+3) = λ³ + 6λ² + 11λ + 6: Δ1 = 6, Δ2 = 6·11 − 6 = 60, Δ3 = 6·Δ2 = 360
  auto h = runtime::hurwitz_determinants({1, 6, 11, 6});
  ASSERT_EQ(h.size(), 3u);
  EXPECT_NEAR(h[0], 6, 1e-12);
  EXPECT_NEAR(h[1], 60, 1e-12);
  EXPECT_NEAR(h[2], 360, 1e-10);
}

TEST(PhasePlane, ClassifiesTheTwoStateTypes) {
  auto type = [](double a, double b, double c, double d) {
    Eigen::Matrix2d A;
    A << a, b, c, d;
    return runtime::phase_plane_type(A);
  };
  EXPECT_EQ(type(1, 0, 0, -1), "saddle");
  EXPECT_EQ(type(-1, 0, 0, -2), "stable node");
  EXPECT_EQ(type(1, 0, 0, 2), "unstable node");
  EXPECT_EQ(type(-1, 2, -2, -1), "stable focus");
  EXPECT_EQ(type(1, 2, -2, 1), "unstable focus");
  EXPECT_EQ(type(0, 1, -1, 0), "centre");
  EXPECT_EQ(type(-1, 0, 0, -1), "stable star (proper node)");
  EXPECT_EQ(type(-1, 1, 0, -1), "stable degenerate node");
  EXPECT_EQ(type(0, 1, 0, -1), "degenerate: a line of equilibria (one zero eigenvalue)");
}

TEST(LinearStability, UndampedPendulumIsACentreByLagrangeDirichlet) {
  Problem p = problem_of("pendulum");
  auto eq = runtime::find_equilibrium(p, {0.5, 0.0});
  ASSERT_TRUE(eq.converged);
  EXPECT_NEAR(eq.state[0], 0.0, 1e-12);
  auto r = runtime::analyse_stability(p, eq.state);
  double omega = std::sqrt(parameter(p, "g") / parameter(p, "l"));
  ASSERT_EQ(r.eigenvalues.size(), 2u);
  EXPECT_NEAR(std::abs(r.eigenvalues[0].imag()), omega, 1e-10);
  EXPECT_NEAR(r.eigenvalues[0].real(), 0.0, 1e-12);
  EXPECT_EQ(r.verdict, "marginally_stable");
  EXPECT_EQ(r.phase_plane, "centre");
  EXPECT_TRUE(has_theorem(r, "Lagrange-Dirichlet"));
}

// an equilibrium is decided in the model's own scales: the pendulum at 0.5 rad is none and
// hanging is one for masses from 1e-12 to 1e12 kg and gravities from 1e-6 to 1e6 (a tolerance of
// at least 1e-9 in absolute units took 0.5 rad for one at 1e-12 kg)
TEST(LinearStability, AnEquilibriumIsOneAtEveryScale) {
  for (double mass : {1e-12, 1.0, 1e12})
    for (double g : {1e-6, 9.81, 1e6}) {
      SCOPED_TRACE(testing::Message() << "m = " << mass << ", g = " << g);
      Problem p = problem_of("pendulum", {{"m", mass}, {"g", g}});
      EXPECT_FALSE(runtime::check_equilibrium(p, {0.5, 0.0}).converged);
      EXPECT_TRUE(runtime::check_equilibrium(p, {0.0, 0.0}).converged);
      runtime::Equilibrium found = runtime::find_equilibrium(p, {0.5, 0.0});
      ASSERT_TRUE(found.converged);
      EXPECT_NEAR(found.state[0], 0.0, 1e-9);
    }
}

// a free body under gravity has no equilibrium, and says why: at rest, der(z) changes at -g in
// every configuration, at every g; a pendulum's rates change with its angle
TEST(LinearStability, AFallingBodyHasARateThatNothingBalances) {
  for (double g : {1e-6, 9.81, 1e6}) {
    Problem falling = problem_of("tumbling_body", {{"g", g}});
    std::vector<double> start(falling.model->default_state, falling.model->default_state + falling.model->num_states);
    runtime::Equilibrium searched = runtime::find_equilibrium(falling, start);
    EXPECT_FALSE(searched.converged) << "residual " << searched.residual << ", tolerance " << searched.tolerance;
    std::optional<runtime::UnbalancedRate> unbalanced = runtime::unbalanced_rate(falling, start);
    ASSERT_TRUE(unbalanced) << "g = " << g;
    EXPECT_EQ(std::string(falling.model->state_names[falling.model->num_coordinates + unbalanced->velocity]), "der(z)");
    EXPECT_NEAR(unbalanced->rate, -g, 1e-12 * g);
  }
  Problem pendulum = problem_of("pendulum");
  EXPECT_FALSE(runtime::unbalanced_rate(pendulum, {0.5, 0.0}));
  EXPECT_FALSE(runtime::unbalanced_rate(problem_of("tumbling_body", {{"g", 0.0}}), std::vector<double>{0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0}))
      << "without gravity it rests anywhere";
}

// the chain of three springs k with a force F = 1 on the second mass rests at x = F/(3k) (1, 2): found
// for k from 1e-12 (3e11 m away: a step limited to half a unit did not get there) to 1e12 N/m;
// without springs, der(x2) changes at F/m2 everywhere
TEST(LinearStability, AnEquilibriumFarAwayOrCloseByIsFoundInOneStep) {
  for (double k : {1e-12, 1e-6, 1.0, 1e6, 1e12}) {
    SCOPED_TRACE(testing::Message() << "k = " << k);
    Problem p = problem_of("two_mass_chain", {{"k1", k}, {"k2", k}, {"k3", k}});
    p.inputs = {1.0};
    runtime::Equilibrium e = runtime::find_equilibrium(p, {0.01, 0.0, 0.0, 0.0});
    ASSERT_TRUE(e.converged) << "residual " << e.residual << ", tolerance " << e.tolerance;
    EXPECT_NEAR(e.state[0], 1 / (3 * k), 1e-9 / (3 * k));
    EXPECT_NEAR(e.state[1], 2 / (3 * k), 1e-9 / (3 * k));
    EXPECT_FALSE(runtime::unbalanced_rate(p, {0.01, 0.0, 0.0, 0.0}));
  }
  Problem loose = problem_of("two_mass_chain", {{"k1", 0.0}, {"k2", 0.0}, {"k3", 0.0}});
  loose.inputs = {1.0};
  std::optional<runtime::UnbalancedRate> pushed = runtime::unbalanced_rate(loose, {0.01, 0.0, 0.0, 0.0});
  ASSERT_TRUE(pushed);
  EXPECT_EQ(std::string(loose.model->state_names[2 + pushed->velocity]), "der(x2)");
  EXPECT_NEAR(pushed->rate, 1.0, 1e-15);
}

// Kapitza's pendulum in time scales from 1e-6 to 1e6 (g and the drive's frequency scaled): its
// linearized equations repeat with the drive's period, and not with a period 0.1 % longer
TEST(LinearStability, PeriodicEquationsArePeriodicInEveryTimeScale) {
  for (double s : {1e-6, 1.0, 1e6}) {
    SCOPED_TRACE(testing::Message() << "time scale " << s);
    Problem p = problem_of("kapitza_pendulum", {{"g", 9.81 * s * s}, {"w", 60.0 * s}});
    double period = 2 * M_PI / (60.0 * s);
    EXPECT_LT(runtime::periodicity_defect(p, {M_PI, 0.0}, period), 1e-9);
    EXPECT_GT(runtime::periodicity_defect(p, {M_PI, 0.0}, 1.001 * period), 1e-6);
  }
}

// Kapitza's pendulum upright, its Floquet multipliers in time scales from 1e-6 to 1e6: the same
// multipliers from the same number of steps a period, which the balanced A's rate sets. |A| itself
// mixes the states' units (1 in q' = v against a w² / l = 360 at s = 1): it asked for 2e6 steps a
// period at s = 1e-6 and 7.5e8 at s = 1e6.
TEST(LinearStability, FloquetMultipliersAreTheSameInEveryTimeScale) {
  runtime::FloquetReport reference;
  for (double s : {1.0, 1e-6, 1e6}) {
    SCOPED_TRACE(testing::Message() << "time scale " << s);
    Problem p = problem_of("kapitza_pendulum", {{"g", 9.81 * s * s}, {"w", 60.0 * s}});
    runtime::FloquetReport r = runtime::floquet_analysis(p, {M_PI, 0.0}, 2 * M_PI / (60.0 * s));
    if (s == 1.0) {
      reference = r;
      continue;
    }
    EXPECT_EQ(r.steps_per_period, reference.steps_per_period);
    EXPECT_EQ(r.verdict, reference.verdict);
    ASSERT_EQ(r.multipliers.size(), reference.multipliers.size());
    for (std::size_t k = 0; k < r.multipliers.size(); ++k)
      EXPECT_LT(std::abs(r.multipliers[k] - reference.multipliers[k]), 1e-9);
  }
}

TEST(LinearStability, DampedPendulumDecaysAtTheClassicalRate) {
  Problem p = problem_of("pendulum", {{"d", 0.5}});
  auto r = runtime::analyse_stability(p, {0.0, 0.0});
  double m = parameter(p, "m"), l = parameter(p, "l"), g = parameter(p, "g"), delta = 0.5 / (2 * m * l * l);
  EXPECT_NEAR(r.eigenvalues[0].real(), -delta, 1e-10);
  EXPECT_NEAR(std::abs(r.eigenvalues[0].imag()), std::sqrt(g / l - delta * delta), 1e-10);
  EXPECT_EQ(r.verdict, "asymptotically_stable");
  EXPECT_EQ(r.phase_plane, "stable focus");
  EXPECT_TRUE(has_theorem(r, "Thomson-Tait-Chetaev"));
  EXPECT_NEAR(r.modes[0].damping_ratio, delta / std::sqrt(g / l), 1e-10);
}

TEST(LinearStability, UprightPendulumIsASaddle) {
  Problem p = problem_of("pendulum");
  auto eq = runtime::check_equilibrium(p, {M_PI, 0.0});
  ASSERT_TRUE(eq.converged) << eq.residual;
  auto r = runtime::analyse_stability(p, eq.state);
  EXPECT_NEAR(r.eigenvalues[0].real(), std::sqrt(parameter(p, "g") / parameter(p, "l")), 1e-10);
  EXPECT_EQ(r.verdict, "unstable");
  EXPECT_EQ(r.phase_plane, "saddle");
  EXPECT_TRUE(has_theorem(r, "Lyapunov-Chetaev"));
}

// equal masses and lengths: ω² = (g/l)(2 ∓ √2)
TEST(LinearStability, DoublePendulumNormalModes) {
  Problem p = problem_of("double_pendulum");
  auto r = runtime::analyse_stability(p, {0, 0, 0, 0});
  std::vector<double> frequencies;
  for (const auto& mode : r.modes) frequencies.push_back(mode.frequency);
  std::sort(frequencies.begin(), frequencies.end());
  double g = parameter(p, "g"), l = parameter(p, "l1");
  ASSERT_EQ(frequencies.size(), 2u);
  EXPECT_NEAR(frequencies[0], std::sqrt(g / l * (2 - std::sqrt(2.0))), 1e-10);
  EXPECT_NEAR(frequencies[1], std::sqrt(g / l * (2 + std::sqrt(2.0))), 1e-10);
  EXPECT_EQ(r.verdict, "marginally_stable");
}

// det(λ²M + λD + K) for the chain wall–k1,d1–m1–k2,d2–m2
TEST(LinearStability, TwoMassOscillatorCharacteristicPolynomial) {
  Problem p = problem_of("two_mass_spring_damper");
  double m1 = parameter(p, "m1"), m2 = parameter(p, "m2"), k1 = parameter(p, "k1"), k2 = parameter(p, "k2"),
         d1 = parameter(p, "d1"), d2 = parameter(p, "d2");
  std::vector<double> expected = {m1 * m2, m1 * d2 + m2 * (d1 + d2), m1 * k2 + m2 * (k1 + k2) + d1 * d2,
                                  d1 * k2 + d2 * k1, k1 * k2};
  auto r = runtime::analyse_stability(p, {0, 0, 0, 0});
  ASSERT_EQ(r.characteristic_polynomial.size(), 5u);
  for (std::size_t k = 0; k < 5; ++k)
    EXPECT_NEAR(r.characteristic_polynomial[k], expected[k] / expected[0], 1e-9 * std::abs(expected[k] / expected[0]));
  EXPECT_EQ(r.verdict, "asymptotically_stable");
  for (double h : r.hurwitz) EXPECT_GT(h, 0);
}

// κ cos θ0 = P and n² ω0² l cos θ0 = g
TEST(LinearStability, GovernorSteadyMotionAndVyshnegradskyBoundary) {
  Problem p = problem_of("watt_governor");
  auto eq = runtime::find_equilibrium(p, {0.0, 0.3, 2.0, 0.0});
  ASSERT_TRUE(eq.converged) << eq.residual;
  double theta = std::acos(parameter(p, "P") / parameter(p, "kappa"));
  double omega = std::sqrt(parameter(p, "g") / (parameter(p, "l") * std::pow(parameter(p, "n"), 2) * std::cos(theta)));
  EXPECT_NEAR(eq.state[1], theta, 1e-10);
  EXPECT_NEAR(eq.state[2], omega, 1e-9);
  EXPECT_EQ(runtime::analyse_stability(p, eq.state).verdict, "asymptotically_stable");
  // b (J + 2ml²n²s² + 8ml²n²c²) ω0 = 4 m l² c κ on the boundary
  double m = parameter(p, "m"), l = parameter(p, "l"), n = parameter(p, "n"), J = parameter(p, "J");
  double s = std::sin(theta), c = std::cos(theta);
  double b_boundary = 4 * m * l * l * c * parameter(p, "kappa") /
                      (omega * (J + 2 * m * l * l * n * n * s * s + 8 * m * l * l * n * n * c * c));
  for (double factor : {0.98, 1.02}) {
    Problem q = problem_of("watt_governor", {{"b", b_boundary * factor}});
    EXPECT_EQ(runtime::analyse_stability(q, eq.state).verdict, factor < 1 ? "unstable" : "asymptotically_stable");
  }
}

// P = −∂f/∂q', Q = −∂f/∂q, B = ∂f/∂u against central differences of the generated forcing
TEST(Linearization, MatchesCentralDifferencesForEveryModel) {
  std::mt19937 random(99);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (const GeneratedModel& g : generated_models()) {
    const eomgen_model_abi& m = *g.abi;
    std::size_t nq = m.num_coordinates, n = m.num_velocities;  // Appell: Q is n × nq
    std::vector<double> x(m.num_states), u(m.num_inputs + 1), p(m.default_parameters, m.default_parameters + m.num_parameters);
    for (double& v : x) v = uniform(random);
    for (double& v : u) v = uniform(random);
    std::vector<double> P(n * n), Q(n * nq), B(n * m.num_inputs + 1), plus(n), minus(n);
    m.linearization(0.3, x.data(), u.data(), p.data(), P.data(), Q.data(), B.data());
    for (std::size_t j = 0; j < nq + n; ++j) {
      std::vector<double> xp = x, xm = x;
      double h = 1e-6;
      xp[j] += h, xm[j] -= h;
      m.forcing(0.3, xp.data(), u.data(), p.data(), plus.data());
      m.forcing(0.3, xm.data(), u.data(), p.data(), minus.data());
      for (std::size_t i = 0; i < n; ++i) {
        double derivative = (plus[i] - minus[i]) / (2 * h);
        double analytic = j < nq ? -Q[i * nq + j] : -P[i * n + (j - nq)];
        // the central difference carries the rounding error of the row's largest terms
        double row = 0;
        for (std::size_t k = 0; k < nq; ++k) row = std::max(row, std::abs(Q[i * nq + k]));
        for (std::size_t k = 0; k < n; ++k) row = std::max(row, std::abs(P[i * n + k]));
        EXPECT_NEAR(analytic, derivative, 1e-6 * std::max({1.0, std::abs(derivative), 1e-3 * row}))
            << g.name << " (" << i << ", " << j << ")";
      }
    }
    // B = ∂f/∂u
    for (std::size_t j = 0; j < m.num_inputs; ++j) {
      std::vector<double> up = u, um = u;
      double h = 1e-6;
      up[j] += h, um[j] -= h;
      m.forcing(0.3, x.data(), up.data(), p.data(), plus.data());
      m.forcing(0.3, x.data(), um.data(), p.data(), minus.data());
      for (std::size_t i = 0; i < n; ++i) {
        double derivative = (plus[i] - minus[i]) / (2 * h), row = 0;
        for (std::size_t k = 0; k < nq; ++k) row = std::max(row, std::abs(Q[i * nq + k]));
        EXPECT_NEAR(B[i * m.num_inputs + j], derivative, 1e-6 * std::max({1.0, std::abs(derivative), 1e-3 * row}))
            << g.name << " B(" << i << ", " << j << ")";
      }
    }
  }
}

// distance from the equilibrium over the non-cyclic coordinates and all velocities
double distance(const eomgen_model_abi& m, const std::vector<double>& x, const std::vector<double>& eq) {
  double d = 0;
  for (std::size_t i = 0; i < m.num_states; ++i)
    if (i >= m.num_coordinates || !m.is_cyclic[i]) d = std::max(d, std::abs(x[i] - eq[i]));
  return d;
}

struct Case {
  const char* model;
  std::vector<std::pair<std::string, double>> set;
  std::vector<double> near;  // start of the equilibrium search
};

TEST(LinearStability, VerdictAgreesWithASimulatedPerturbation) {
  std::vector<Case> cases = {
      {"pendulum", {{"d", 0.3}}, {0.4, 0}},
      {"pendulum", {}, {0.4, 0}},
      {"double_pendulum", {}, {0.2, 0.1, 0, 0}},
      {"two_mass_spring_damper", {}, {0.01, 0, 0, 0}},
      {"watt_governor", {}, {0, 0.4, 3, 0}},
      {"watt_governor", {{"b", 0.2}}, {0, 0.4, 3, 0}},
      {"cart_pendulum", {}, {0, 3.0, 0, 0}},
      {"bead_on_rotating_hoop", {}, {0.9, 0}},
      {"bead_on_rotating_hoop", {{"Omega", 3.0}}, {0.2, 0}},
      {"n_link_pendulum_4", {}, {0.1, 0.1, 0.1, 0.1, 0, 0, 0, 0}},
  };
  for (const Case& c : cases) {
    Problem p = problem_of(c.model, c.set);
    auto eq = runtime::find_equilibrium(p, c.near);
    ASSERT_TRUE(eq.converged) << c.model;
    auto r = runtime::analyse_stability(p, eq.state);
    std::vector<double> x0 = eq.state;
    for (std::size_t i = 0; i < x0.size(); ++i) x0[i] += 1e-6 * (1 + 0.3 * static_cast<double>(i));
    runtime::SimulationSettings s;
    double rate = std::abs(r.stability_degree);
    s.t_end = r.verdict == "marginally_stable" ? 20.0 : std::min(40.0, 6.0 / std::max(rate, 0.05));
    s.dt_out = s.t_end / 200, s.rtol = 1e-11, s.atol = 1e-14;
    auto result = runtime::simulate(p, x0, s);
    ASSERT_FALSE(result.failed) << c.model << ": " << result.failure;
    const auto& states = result.trajectory.states;
    double d0 = distance(*p.model, x0, eq.state), d_end = distance(*p.model, states.back(), eq.state);
    SCOPED_TRACE(std::string(c.model) + " " + r.verdict);
    if (r.verdict == "asymptotically_stable") {
      EXPECT_LT(d_end, d0 * std::exp(-0.5 * rate * s.t_end));
    } else if (r.verdict == "marginally_stable") {
      double largest = 0;
      for (const auto& x : states) largest = std::max(largest, distance(*p.model, x, eq.state));
      EXPECT_LT(largest, 20 * d0);
    } else {
      // grows like exp(λ t): the envelope (largest distance over windows longer than a period)
      // at [T/4, T/2] and [3T/4, T], while the perturbation is still small
      auto envelope = [&](std::size_t from, std::size_t to) {
        double e = 0;
        for (std::size_t k = from; k < to; ++k) e = std::max(e, distance(*p.model, states[k], eq.state));
        return e;
      };
      std::size_t n = states.size() - 1;
      double grown = std::log(envelope(3 * n / 4, n + 1) / envelope(n / 4, n / 2 + 1)) / (s.t_end / 2);
      EXPECT_NEAR(grown, r.stability_degree, 0.1 * r.stability_degree);
    }
  }
}

}  // namespace
}  // namespace eomgen::test

namespace eomgen::test {
namespace {

// Ziegler: flutter at P = (7/2 − √2) c/l for masses 2m and m
TEST(KnownStabilityResults, ZieglerPendulumFluttersAtTheClassicalLoad) {
  double critical = 3.5 - std::sqrt(2.0);  // c = l = 1
  for (double factor : {1 - 1e-4, 1 + 1e-4}) {
    Problem p = problem_of("follower_force_pendulum", {{"P", critical * factor}});
    auto r = runtime::analyse_stability(p, {0, 0, 0, 0});
    EXPECT_EQ(r.verdict, factor < 1 ? "marginally_stable" : "unstable") << factor;
    EXPECT_TRUE(has_theorem(r, "Merkin"));
    if (factor > 1) {
      EXPECT_GT(std::abs(r.eigenvalues[0].imag()), 0.1) << "flutter: an oscillating instability";
    }
  }
}

// rotating frame: eigenvalues ±i(Ω ± √(k/m)) without damping, below and above the critical speed
TEST(KnownStabilityResults, JeffcottRotorGyroscopicStabilizationAndItsLoss) {
  for (double Omega : {4.0, 17.0}) {
    Problem p = problem_of("jeffcott_rotor", {{"Omega", Omega}, {"d", 0.0}});
    auto r = runtime::analyse_stability(p, {0, 0, 0, 0});
    std::vector<double> frequencies;
    for (const auto& mode : r.modes) frequencies.push_back(mode.frequency);
    std::sort(frequencies.begin(), frequencies.end());
    double omega0 = std::sqrt(parameter(p, "k") / parameter(p, "m"));
    ASSERT_EQ(frequencies.size(), 2u);
    EXPECT_NEAR(frequencies[0], std::abs(Omega - omega0), 1e-9);
    EXPECT_NEAR(frequencies[1], Omega + omega0, 1e-9);
    EXPECT_EQ(r.verdict, "marginally_stable");
  }
  Problem damped = problem_of("jeffcott_rotor", {{"Omega", 17.0}, {"d", 0.5}});
  auto r = runtime::analyse_stability(damped, {0, 0, 0, 0});
  EXPECT_EQ(r.verdict, "unstable");
  EXPECT_TRUE(has_theorem(r, "Thomson-Tait-Chetaev: with complete damping"));
  EXPECT_EQ(runtime::analyse_stability(problem_of("jeffcott_rotor", {{"Omega", 5.0}}), {0, 0, 0, 0}).verdict,
            "asymptotically_stable");
}

// gravity gradient: stable in the Lagrange region B > A > C, unstable with the pitch inertia smallest
TEST(KnownStabilityResults, SatelliteGravityGradientLagrangeRegion) {
  EXPECT_EQ(runtime::analyse_stability(problem_of("satellite_gravity_gradient"), {0, 0, 0, 0, 0, 0}).verdict,
            "marginally_stable");
  EXPECT_EQ(runtime::analyse_stability(problem_of("satellite_gravity_gradient", {{"B", 40.0}}), {0, 0, 0, 0, 0, 0}).verdict,
            "unstable");
}

// pervasive damping: asymptotically stable for every positive choice
TEST(KnownStabilityResults, DampedAbsorberIsAsymptoticallyStable) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> uniform(0.1, 10.0);
  for (int k = 0; k < 20; ++k) {
    Problem p = problem_of("damped_two_mass_oscillator", {{"m1", uniform(random)}, {"k1", uniform(random)},
                                                           {"m2", uniform(random)}, {"k2", uniform(random)}, {"d", uniform(random)}});
    EXPECT_EQ(runtime::analyse_stability(p, {0, 0, 0, 0}).verdict, "asymptotically_stable");
  }
}

}  // namespace
}  // namespace eomgen::test

namespace eomgen::test {
namespace {

// Upright straight rolling of the thin disk (theta = pi/2, der(psi) = 0, der(phi) = Omega),
// linearized by hand from Appell's equations: theta = pi/2 + d, then d' = s_theta,
// s_psi' = 2 Omega s_theta, s_theta' = (4/5)(g/R) d − (6/5) Omega s_psi, s_phi' = 0, so
// lambda² = (4/5)(g/R − 3 Omega²) besides zeros: stable above Omega² = g/(3R) (Routh).
TEST(AppellStability, RollingDiskIsStableAboveItsCriticalSpeed) {
  const GeneratedModel& g = generated_model("rolling_disk");
  runtime::Problem problem{g.abi, g.default_parameters, g.default_inputs};
  double R = g.default_parameters[1], gravity = g.default_parameters[2], critical = std::sqrt(gravity / (3 * R));
  for (double ratio : {0.5, 0.9, 1.1, 3.0}) {
    double omega = ratio * critical;
    std::vector<double> x = {0.3, -0.2, 0.7, M_PI / 2, 1.0, 0, 0, omega};
    runtime::Equilibrium eq = runtime::check_equilibrium(problem, x);
    ASSERT_TRUE(eq.converged) << eq.residual;
    runtime::StabilityReport r = runtime::analyse_stability(problem, x);
    EXPECT_EQ(r.verdict, ratio > 1 ? "marginally_stable" : "unstable") << "Omega/Omega_c = " << ratio;
    double lambda2 = 0.8 * (gravity / R - 3 * omega * omega), largest = 0;
    for (auto l : r.eigenvalues) largest = std::max(largest, std::abs(l));
    EXPECT_NEAR(largest, std::sqrt(std::abs(lambda2)), 1e-9 * largest) << ratio;
  }
}

TEST(AppellStability, FindsTheUprightTiltFromNearby) {
  const GeneratedModel& g = generated_model("rolling_disk");
  runtime::Problem problem{g.abi, g.default_parameters, g.default_inputs};
  std::vector<double> x = {0, 0, 0, 1.4, 0, 0, 0, 20};
  runtime::Equilibrium eq = runtime::find_equilibrium(problem, x);
  ASSERT_TRUE(eq.converged);
  EXPECT_NEAR(eq.state[3], M_PI / 2, 1e-12);
}

}  // namespace
}  // namespace eomgen::test
