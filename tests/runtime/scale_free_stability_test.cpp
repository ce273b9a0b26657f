// Verdicts that do not depend on the units or the time scale of the numbers: the
// two-mass spring-damper chain scaled in time by s (k·s², d·s) and in the units of its
// coordinates by u (every parameter ·u²), s and u from 1e-12 to 1e12, keeps its linear
// verdict, its force-structure theorem, its phase-plane type and its critical-case
// verdict; its eigenvalues scale by s exactly. A MEMS resonator (m = 1e-9, c = 1e-8,
// k = 10: −5 ± 1e5 i) and a heavy oscillator (m = 1e6, c = 1e3, k = 1e12) are damped; an
// undamped oscillator at 22 Hz whose spring is a generalized force stays small in the long
// simulation; a free mass is not asymptotically stable; a well is stable whatever the width of
// its rim; a MEMS cart's mass matrix is regular; a rendezvous near a circular orbit stays near.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <fstream>
#include <tuple>

#include <fmt/format.h>

#include "analyse/critical_case.hpp"
#include "analyse/linear_stability.hpp"
#include "analyse/state_check.hpp"
#include "analyse/system_scales.hpp"
#include "generated/header_registry.hpp"
#include "support/small_models.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

using runtime::Problem;

// the chain with its parameters scaled: time by s, the coordinates' unit by u
Problem scaled_chain(double s, double u, double damping_factor) {
  const eomgen_model_abi* m = generated_model("two_mass_spring_damper").abi;
  Problem p{m, std::vector<double>(m->default_parameters, m->default_parameters + m->num_parameters),
            std::vector<double>(m->num_inputs, 0.0)};
  for (std::size_t i = 0; i < m->num_parameters; ++i) {
    char kind = m->parameter_names[i][0];
    double time_power = kind == 'k' ? 2 : kind == 'd' ? 1 : 0;
    p.parameters[i] *= std::pow(s, time_power) * u * u * (kind == 'd' ? damping_factor : 1.0);
  }
  return p;
}

const std::vector<double>& scales() {
  static const std::vector<double> all{1e-12, 1e-9, 1e-6, 1e-3, 1, 1e3, 1e6, 1e9, 1e12};
  return all;
}

std::string first_theorem(const runtime::StabilityReport& r) { return r.theorems.empty() ? "" : r.theorems[0].substr(0, 20); }

TEST(ScaleFreeStability, DampedChainIsAsymptoticallyStableAtEveryScale) {
  // the default damping, and a light one (Q of about 1e4)
  for (double damping : {1.0, 1e-4}) {
    Problem reference = scaled_chain(1, 1, damping);
    std::vector<double> x(reference.model->num_states, 0.0);
    runtime::StabilityReport base = runtime::analyse_stability(reference, x);
    ASSERT_EQ(base.verdict, "asymptotically_stable");
    for (double s : scales())
      for (double u : scales()) {
        runtime::StabilityReport r = runtime::analyse_stability(scaled_chain(s, u, damping), x);
        EXPECT_EQ(r.verdict, "asymptotically_stable") << "s = " << s << ", u = " << u << ", damping " << damping;
        EXPECT_EQ(first_theorem(r), first_theorem(base)) << "s = " << s << ", u = " << u;
        EXPECT_NEAR(r.stability_degree / s, base.stability_degree, 1e-6 * std::abs(base.stability_degree));
        ASSERT_EQ(r.eigenvalues.size(), base.eigenvalues.size());
        for (std::size_t k = 0; k < r.eigenvalues.size(); ++k)
          EXPECT_NEAR(std::abs(r.eigenvalues[k] / s - base.eigenvalues[k]), 0, 1e-9 * std::abs(base.eigenvalues[k]));
      }
  }
}

TEST(ScaleFreeStability, UndampedChainIsMarginallyStableAtEveryScale) {
  for (double s : scales())
    for (double u : scales()) {
      Problem p = scaled_chain(s, u, 0.0);
      std::vector<double> x(p.model->num_states, 0.0);
      runtime::StabilityReport r = runtime::analyse_stability(p, x);
      EXPECT_EQ(r.verdict, "marginally_stable") << "s = " << s << ", u = " << u;
      EXPECT_EQ(first_theorem(r), "Lagrange-Dirichlet: ") << "s = " << s << ", u = " << u;
    }
}

// the chain declares dissipation, so the energy function does not apply and the long simulation
// (eight perturbed runs of 200 periods) decides: at the corners and the middle of the scales
TEST(ScaleFreeStability, UndampedChainStaysSmallInTheLongSimulationAtExtremeScales) {
  for (auto [s, u] : std::vector<std::pair<double, double>>{{1e-12, 1e12}, {1e12, 1e-12}, {1, 1}, {1e-12, 1e-12}, {1e12, 1e12}}) {
    Problem p = scaled_chain(s, u, 0.0);
    std::vector<double> x(p.model->num_states, 0.0);
    runtime::StabilityReport r = runtime::analyse_stability(p, x);
    runtime::CriticalCase c = runtime::check_critical_case(p, x, r);
    EXPECT_TRUE(c.critical) << "s = " << s << ", u = " << u;
    EXPECT_EQ(c.nonlinear_verdict, "stable") << "s = " << s << ", u = " << u << ": " << c.energy << " / " << c.simulation;
  }
}

// a theorem whose hypotheses hold and the eigenvalues disagree: the verdict says so
TEST(ScaleFreeStability, AVerdictThatContradictsATheoremIsUndecided) {
  runtime::StabilityReport r;
  r.verdict = "marginally_stable";
  r.theorems = {"Thomson-Tait-Chetaev: complete damping added to a positive definite K makes the equilibrium "
                "asymptotically stable, gyroscopic forces or not"};
  runtime::reconcile_with_theorems(r);
  EXPECT_EQ(r.verdict, "undecided");
  EXPECT_NE(r.disagreement.find("the eigenvalues say marginally_stable but Thomson-Tait-Chetaev says asymptotically_stable"),
            std::string::npos) << r.disagreement;
  // agreeing ones stay as they are
  r.verdict = "asymptotically_stable", r.disagreement.clear();
  runtime::reconcile_with_theorems(r);
  EXPECT_EQ(r.verdict, "asymptotically_stable");
  EXPECT_TRUE(r.disagreement.empty());
  r.theorems = {"Kelvin-Thomson-Tait: gyroscopic forces cannot stabilize an odd number (1) of unstable degrees of freedom: unstable"};
  r.verdict = "marginally_stable";
  runtime::reconcile_with_theorems(r);
  EXPECT_EQ(r.verdict, "undecided");
}

TEST(ScaleFreeStability, PhasePlaneTypeDoesNotDependOnTheScale) {
  for (double s : scales())
    for (double u : scales()) {
      // x'' + 2ζω x' + ω² x = 0 with ω = s and the velocity in units u: A = [[0, u], [−ω²/u, −2ζω]]
      auto type = [&](double zeta) {
        Eigen::Matrix2d A;
        A << 0, u, -s * s / u, -2 * zeta * s;
        return runtime::phase_plane_type(A);
      };
      EXPECT_EQ(type(5e-5), "stable focus") << "s = " << s << ", u = " << u;
      EXPECT_EQ(type(0), "centre") << "s = " << s << ", u = " << u;
      EXPECT_EQ(type(2), "stable node") << "s = " << s << ", u = " << u;
      EXPECT_EQ(type(-5e-5), "unstable focus") << "s = " << s << ", u = " << u;
    }
}

TEST(ScaleFreeStability, BalancingKeepsTheEigenvaluesAndShowsTheirScale) {
  Eigen::Matrix2d A;
  A << 0, 1, -1e10, -10;  // the MEMS resonator
  Eigen::MatrixXd B = runtime::balanced(A);
  EXPECT_NEAR(B.trace(), A.trace(), 1e-12);
  EXPECT_NEAR(B.determinant() / A.determinant(), 1, 1e-12);
  EXPECT_LT(runtime::spectral_scale(A), 1e6);
  EXPECT_GT(runtime::spectral_scale(A), 1e4);
  EXPECT_EQ(runtime::spectral_scale(Eigen::MatrixXd::Zero(3, 3)), 0);
}

const char* const oscillator = R"toml([model]
name = "oscillator"
title = "mass, damper and spring, the spring FORCE"
[parameters]
m = 1.0
c = 0.0
k = 1.0
[coordinates]
x = { initial = 0.0, rate = 0.0 }
[[particles]]
name = "mass"
mass = "m"
position = ["x", "0", "0"]
[energy]
dissipation = "c*der(x)^2/2"
)toml";

std::string oscillator_with(bool spring_as_force) {
  std::string text = oscillator;
  text.replace(text.find("FORCE"), 5, spring_as_force ? "as a generalized force" : "as a potential");
  // [energy] is the text's last table: a potential line goes into it
  text += spring_as_force ? "[[forces]]\ngeneralized = { x = \"-k*x\" }\n" : "potential = \"k*x^2/2\"\n";
  return text;
}

TEST(ScaleFreeStability, MemsAndHeavyOscillatorsAreDamped) {
  std::string model = write_model("oscillator", oscillator_with(false));
  for (const char* set : {"--set m=1e-9 --set c=1e-8 --set k=10", "--set m=1e6 --set c=1e3 --set k=1e12"}) {
    JsonValue r = run_json("stability '" + model + "' " + set);
    EXPECT_EQ(field(r, "verdict").text, "asymptotically_stable") << set;
    EXPECT_EQ(field(r, "phase_plane").text, "stable focus") << set;
    EXPECT_NE(field(field(r, "critical_case"), "nonlinear_verdict").text, "unstable") << set;
  }
}

TEST(ScaleFreeStability, UndampedOscillatorStaysSmallInTheLongSimulationAtEveryTimeScale) {
  std::string model = write_model("oscillator_force", oscillator_with(true));
  // 22 Hz, then that frequency scaled by 1e-6 and 1e6
  for (double s : {1.0, 1e-6, 1e6}) {
    double k = std::pow(2 * M_PI * 22 * s, 2);
    JsonValue r = run_json("stability '" + model + "' " + fmt::format("--set k={:.17g}", k));
    EXPECT_EQ(field(r, "verdict").text, "marginally_stable") << "k = " << k;
    EXPECT_EQ(field(field(r, "critical_case"), "nonlinear_verdict").text, "stable")
        << "k = " << k << ": " << field(field(r, "critical_case"), "simulation").text;
  }
}

// models/stiff_chain.toml: three masses, one stiff damped link (K = 1e8 k, rates from 0.47 to 3.4e4
// 1/s). Its slow modes' damping, about 1e-12 1/s, is below the rounding of A's eigenvalues, so the
// critical case's runs decide. Measured per state, a velocity pushed by its coordinate's size times
// the fastest rate poured into the slow modes as a 3e4-fold "growth", and the damped chain was
// called unstable; in the linearization's energy no mode of it grows. At time scales T of 1e-12, 1
// and 1e12 s (k, K over T², c over T).
TEST(ScaleFreeStability, AStiffDampedChainStaysSmallInItsLinearizationsEnergyAtEveryTimeScale) {
  for (double T : {1.0, 1e-12, 1e12}) {
    JsonValue r = run_json(fmt::format("stability '{}' --set k={:.17g} --set K={:.17g} --set c={:.17g}", model_path("stiff_chain"),
                                       1 / (T * T), 1e8 / (T * T), 2e4 / T));
    EXPECT_EQ(field(r, "verdict").text, "marginally_stable") << "T = " << T;
    const JsonValue& critical = field(r, "critical_case");
    EXPECT_EQ(field(critical, "nonlinear_verdict").text, "stable") << "T = " << T << ": " << field(critical, "simulation").text;
    EXPECT_NE(field(critical, "simulation").text.find("in the linearization's energy"), std::string::npos)
        << field(critical, "simulation").text;
  }
}

// models/space_rendezvous.toml (Clohessy–Wiltshire, n = 1.1e-3/T for T of 1e-12, 1 and 1e12 s): its
// equations are linear and their reduced state's motion bounded (x oscillates about 2 p_y/(m n)
// wherever the conserved p_y = m (y' + 2 n x) puts it), so the critical case's runs must find it
// stable. A radial push δ sets the along-track velocity y' swinging between 0 and −12 n δ:
// measured in the size the cyclic y's default gave y' (1.1e-6 against x's 1e-2), that read as a
// 120-fold growth, and T + V, which the header had claimed conserved, "changed" 1e8-fold: the run
// was refused as "not a solution". In the linearization's modal amplitudes nothing grows.
TEST(ScaleFreeStability, ARendezvousNearACircularOrbitStaysNearItsEquilibriumAtEveryTimeScale) {
  for (double T : {1.0, 1e-12, 1e12}) {
    JsonValue r = run_json(fmt::format("stability '{}' --at x=0 --set n={:.17g}", model_path("space_rendezvous"), 1.1e-3 / T));
    EXPECT_EQ(field(r, "verdict").text, "marginally_stable") << "T = " << T;
    const JsonValue& critical = field(r, "critical_case");
    const std::string& runs = field(critical, "simulation").text;
    EXPECT_EQ(field(critical, "nonlinear_verdict").text, "stable") << "T = " << T << ": " << runs;
    EXPECT_NE(runs.find("in the linearization's modal amplitudes"), std::string::npos) << runs;
    CommandOutput run = run_eomgen(fmt::format("simulate '{}' --initial x=0.01 --set n={:.17g} --t-end {:.17g} --dt-out {:.17g}",
                                               model_path("space_rendezvous"), 1.1e-3 / T, 2e5 * T, 1e3 * T));
    EXPECT_EQ(run.status, 0) << "T = " << T << ": " << run.err;
    EXPECT_NE(run.out.find("the model does not conserve T + V"), std::string::npos) << run.out;
  }
}

TEST(ScaleFreeStability, FreeMassIsNotAsymptoticallyStable) {
  std::string text = oscillator_with(false);
  text.replace(text.find("potential = \"k*x^2/2\"\n"), 22, "");
  JsonValue r = run_json("stability '" + write_model("free", text) + "'");
  EXPECT_EQ(field(r, "verdict").text, "marginally_stable");
  EXPECT_EQ(field(field(r, "critical_case"), "energy").text.find("strict minimum"), std::string::npos);
}

// A particle in a well whose rim lies at x = L, for L from 1e-12 to 1e12: V = k x²/2 − k x⁴/(4L²),
// the same with the linear stiffness gone (x⁴/4 − x⁶/(6L²), K = 0: only V's quartic rise shows the
// minimum), and the first with a dissipation declared (c = 0), so that the long simulation decides.
// Each is stable. Probing V at radii fixed in units (1e-2, 1e-3) stepped over rims closer than
// 1e-2, and the simulation's push of 1e-3 threw the particle out of the well: "unstable".
TEST(ScaleFreeStability, AWellIsStableWhateverTheWidthOfItsRim) {
  auto written = [](const std::string& name, const std::string& energy) {
    return write_model(name, particle_on_a_line_model(name, "m = 1.0\nk = 1.0\nc = 0.0\nL = 1.0\n", energy));
  };
  struct Case {
    std::string model, decided_by;
  };
  std::vector<Case> cases{
      {written("rimmed_well", "potential = \"k*x^2/2 - k*x^4/(4*L^2)\"\n"), "energy"},
      {written("quartic_well", "potential = \"k*x^4/4 - k*x^6/(6*L^2)\"\n"), "energy"},
      {written("damped_rimmed_well", "dissipation = \"c*der(x)^2/2\"\npotential = \"k*x^2/2 - k*x^4/(4*L^2)\"\n"),
       "simulation"}};
  for (const Case& c : cases)
    for (double L : scales()) {
      JsonValue r = run_json("stability '" + c.model + "' " + fmt::format("--set L={:.17g}", L));
      const JsonValue& critical = field(r, "critical_case");
      EXPECT_EQ(field(critical, "nonlinear_verdict").text, "stable")
          << c.model << ", L = " << L << ": " << field(critical, "energy").text << " / " << field(critical, "simulation").text;
      if (c.decided_by == "energy")
        EXPECT_NE(field(critical, "energy").text.find("strict minimum"), std::string::npos) << c.model << ", L = " << L;
      else
        EXPECT_NE(field(critical, "simulation").text.find("stable as far as"), std::string::npos) << c.model << ", L = " << L;
    }
}

// No eigenvalue sets a time scale where every one is zero. A damped x'' = −k x³ (the damping
// declared, c = 0, so that the runs decide), k = 1/T² for T from 1e-12 to 1e12 s: its runs take the
// rate √k s of the force a push s meets and last 200 over it, about 30 of the oscillation's periods
// at that size, and stay within a few times the push.
// A free rigid body at rest (models/free_rigid_body.toml, inertias times 1e-12 to 1e12) meets no
// force at all: a push of a rate turns it on, its angles drift without bound, and it is unstable,
// where 100 s at 0.01 1/s had drifted them by once their push and called it stable.
TEST(ScaleFreeStability, WithoutATimeScaleAQuarticWellIsStableAndAFreeBodyAtRestIsNot) {
  std::string well = write_model("damped_quartic_well", particle_on_a_line_model("damped_quartic_well", "m = 1.0\nk = 1.0\nc = 0.0\n",
                                                                                 "dissipation = \"c*der(x)^2/2\"\npotential = \"k*x^4/4\"\n"));
  for (double T : scales()) {
    JsonValue r = run_json(fmt::format("stability '{}' --set k={:.17g}", well, 1 / (T * T)));
    const JsonValue& critical = field(r, "critical_case");
    EXPECT_EQ(field(critical, "nonlinear_verdict").text, "stable") << "T = " << T << ": " << field(critical, "simulation").text;
    EXPECT_NE(field(critical, "simulation").text.find("the rate of the forces the pushes meet"), std::string::npos)
        << field(critical, "simulation").text;
  }
  for (double u : scales()) {
    JsonValue r = run_json(fmt::format("stability '{}' --at 'der(alpha)=0' --at 'der(gamma)=0' --set A={:.17g} --set B={:.17g} "
                                       "--set C={:.17g}", model_path("free_rigid_body"), u, 2 * u, 3 * u));
    EXPECT_EQ(field(r, "verdict").text, "unstable") << "u = " << u;
    const JsonValue& critical = field(r, "critical_case");
    EXPECT_EQ(field(critical, "nonlinear_verdict").text, "unstable") << "u = " << u << ": " << field(critical, "simulation").text;
  }
}

// A steady motion with no eigenvalue or force to set a time scale sets its own: models/rolling_ball.toml
// spun at 2/T rad/s and models/knife_edge.toml turning at 0.5/T rad/s (its speed 1/T m/s), T from
// 1e-12 to 1e12 s, keep every velocity constant (rolling ball) or turn them with the blade (knife
// edge): stable, the pushes a thousandth of the motion's rate at every T. Runs of 1000 s at a rate of
// 1 1/s had broken off at CVODE's step limit from 2e6 rad/s on and called both unstable.
TEST(ScaleFreeStability, ASteadyMotionWithoutForcesSetsItsOwnTimeScale) {
  for (double T : scales()) {
    for (const auto& [model, at, rate] : {std::tuple{"rolling_ball", fmt::format("--at omega_x={:.17g}", 2 / T), 2 / T},
                                          std::tuple{"knife_edge", fmt::format("--at v={:.17g} --at w={:.17g}", 1 / T, 0.5 / T),
                                                     0.5 / T}}) {
      JsonValue r = run_json(fmt::format("stability '{}' {}", model_path(model), at));
      EXPECT_EQ(field(r, "verdict").text, "marginally_stable") << model << ", T = " << T;
      const std::string simulation = field(field(r, "critical_case"), "simulation").text;
      EXPECT_EQ(field(field(r, "critical_case"), "nonlinear_verdict").text, "stable") << model << ", T = " << T << ": " << simulation;
      EXPECT_NE(simulation.find(fmt::format("the system's rate {:.3g} 1/s", rate)), std::string::npos) << simulation;
      EXPECT_NE(simulation.find("200 over the steady motion's rate"), std::string::npos) << simulation;
    }
  }
}

// models/car_braking.toml at rest on time scales T from 1e-12 to 1e12 s (small_models.hpp):
// der(x)'s row of A is exactly zero, and its eigenvalue is reported as 0, not as the −1.8e-16/T
// rad/s that rounding in the eigensolver leaves; the other four, the damped heave and pitch, are
// those at T = 1 over T. The zero is no conserved momentum (air drag acts on x, so p_x is no first
// integral): it counts, and the car at rest is marginally stable in its linearization (it had been
// called asymptotically stable, the zero left out as "of conserved cyclic momenta"), stable by its
// runs, where a push of der(x) dies away as drag ~ v |v| slows it.
TEST(ScaleFreeStability, AnEigenvalueWithinRoundingOfZeroIsReportedAsZero) {
  const BrakingCar car;
  std::vector<std::complex<double>> unscaled;
  for (double T : {1.0, 1e-12, 1e-9, 1e-6, 1e-3, 1e3, 1e6, 1e9, 1e12}) {
    JsonValue r = run_json(fmt::format("stability '{}' {}", model_path("car_braking"), car.on_time_scale(T)));
    EXPECT_EQ(field(r, "verdict").text, "marginally_stable") << "T = " << T;
    EXPECT_EQ(at(r, "cyclic_zero_eigenvalues"), 0) << "T = " << T;
    EXPECT_EQ(field(field(r, "critical_case"), "nonlinear_verdict").text, "stable") << "T = " << T;
    int zeros = 0;
    std::vector<std::complex<double>> moving;
    for (const JsonValue& e : r.find("eigenvalues")->items) {
      std::complex<double> l{e.items.at(0).value, e.items.at(1).value};
      if (l == 0.0) ++zeros;
      else moving.push_back(l * T);
    }
    EXPECT_EQ(zeros, 1) << "T = " << T;
    if (T == 1.0) unscaled = moving;
    ASSERT_EQ(moving.size(), 4u) << "T = " << T;
    for (std::size_t i = 0; i < 4; ++i) {
      EXPECT_LT(moving[i].real(), 0) << "T = " << T;
      EXPECT_NEAR(std::abs(moving[i] - unscaled[i]) / std::abs(unscaled[i]), 0, 1e-9) << "T = " << T;
    }
  }
}

// models/gimbal_cardan.toml from its initial rates 0.2, −0.1, 1 rad/s times 1/T, T from 1e-12 to
// 1e12 s: a free body's steady motion is a spin about a principal axis, here the minor one (A),
// stable. Stepping the cyclic rate in units of 1 rad/s, the search had halved it toward the double
// root of f ~ ω² at T = 1 and stopped at 2.6e-8 rad/s ("marginally stable", its Jordan blocks split),
// and found the spin at T = 1e-12.
TEST(ScaleFreeStability, AFreeBodysSearchFindsItsSteadySpinAtEveryTimeScale) {
  double unscaled_spin = NAN;
  for (double T : {1.0, 1e-12, 1e-6, 1e6, 1e12}) {
    std::string model = write_model("gimbal_cardan", edited(read_file(model_path("gimbal_cardan")),
                                                            {{"rate = 0.2", fmt::format("rate = {:.17g}", 0.2 / T)},
                                                             {"rate = -0.1", fmt::format("rate = {:.17g}", -0.1 / T)},
                                                             {"rate = 1.0", fmt::format("rate = {:.17g}", 1 / T)}}));
    JsonValue r = run_json(fmt::format("stability '{}'", model));
    const JsonValue& found = field(r, "equilibrium");
    // a spin about the world x axis, which β = γ = 0 makes the body's principal axis of A
    if (T == 1.0) unscaled_spin = at(found, "der(alpha)");
    EXPECT_GT(std::abs(unscaled_spin), 0) << "T = " << T;
    EXPECT_NEAR(at(found, "der(alpha)") * T / unscaled_spin, 1, 1e-9) << "T = " << T;
    EXPECT_NEAR(at(found, "beta"), 0, 1e-12) << "T = " << T;
    EXPECT_NEAR(at(found, "gamma"), 0, 1e-12) << "T = " << T;
    EXPECT_EQ(field(r, "verdict").text, "marginally_stable") << "T = " << T;
    EXPECT_EQ(field(field(r, "critical_case"), "nonlinear_verdict").text, "stable") << "T = " << T;
  }
}

// models/car_braking.toml from 20 m/s (and from 2e-11 and 2e13): air drag's force ~ v |v| has a
// double root at rest, toward which Newton halves the speed at every step and stopped at 2.4e-6 m/s,
// within tolerance. A cyclic rate below a millionth of its start where rest balances too is rest.
TEST(ScaleFreeStability, ABrakingCarsSearchEndsAtRestNotAtASpeedLeftByNewton) {
  for (double speed : {20.0, 2e-11, 2e13}) {
    std::string model = write_model("car_braking", edited(read_file(model_path("car_braking")),
                                                          {{"rate = 20.0 }", fmt::format("rate = {:.17g} }}", speed)}}));
    JsonValue r = run_json(fmt::format("stability '{}'", model));
    EXPECT_EQ(at(field(r, "equilibrium"), "der(x)"), 0.0) << "from " << speed << " m/s";
    EXPECT_EQ(field(r, "verdict").text, "marginally_stable") << "from " << speed << " m/s";
  }
}

// The pendulum on a cart with its masses scaled by μ and its rod by λ (g by λ too, so that the time
// scale stays): M = [[μ(mc + m), μλ m l cos θ], [·, μλ² m l²]] has eigenvalues as far apart as λ²
// (1e-9 kg against 5e-23 kg m² for a MEMS cart), which a threshold on them called singular; without
// the velocities' units it is the same matrix at every scale.
TEST(ScaleFreeStability, ACartsMassMatrixIsRegularInAnyUnits) {
  const eomgen_model_abi* m = generated_model("cart_pendulum").abi;
  std::vector<double> x(m->num_states, 0.0);
  for (double mu : scales())
    for (double lambda : scales()) {
      Problem p{m, std::vector<double>(m->default_parameters, m->default_parameters + m->num_parameters),
                std::vector<double>(m->num_inputs, 0.0)};
      for (std::size_t i = 0; i < m->num_parameters; ++i) {
        std::string name = m->parameter_names[i];
        p.parameters[i] *= name == "l" || name == "g" ? lambda : mu;
      }
      runtime::MassMatrixRank r = runtime::mass_matrix_rank(p, 0.0, x);
      EXPECT_FALSE(r.singular()) << "mu = " << mu << ", lambda = " << lambda << ": " << r.null_velocities;
      EXPECT_EQ(runtime::unfit_state(p, 0.0, x), "") << "mu = " << mu << ", lambda = " << lambda;
    }
}

// A body hanging on a ball joint, with damping about every axis and a torsion spring about the
// vertical (V = 2 k qz², ½ k ψ² for a small turn ψ): asymptotically stable. Its quaternion's length
// gives one more zero eigenvalue, which says nothing about the system and is left out, at every
// time scale (g, k scaled by s², c by s).
TEST(ScaleFreeStability, ABallJointsQuaternionLengthIsLeftOut) {
  std::string model = write_model("ball_pendulum", R"toml([model]
name = "ball_pendulum"
[parameters]
g = 9.81
c = 0.1
k = 2.0
[gravity]
acceleration = ["0", "0", "-g"]
[energy]
dissipation = "2*c*(der(qw)^2 + der(qx)^2 + der(qy)^2 + der(qz)^2)"
potential = "2*k*qz^2"
[coordinates]
qw = 1
qx = 0
qy = 0
qz = 0
[[frames]]
name = "bob"
joint = { type = "ball", quaternion = ["qw", "qx", "qy", "qz"], angular_velocity = ["wx", "wy", "wz"] }
[[rigid_bodies]]
name = "b"
frame = "bob"
mass = "1"
center = ["0", "0", "-1"]
inertia = ["0.1", "0.1", "0.05"]
)toml");
  for (double s : {1e-6, 1.0, 1e6}) {
    JsonValue r = run_json("stability '" + model + "' " + fmt::format("--set g={:.17g} --set k={:.17g} --set c={:.17g}",
                                                                      9.81 * s * s, 2.0 * s * s, 0.1 * s));
    EXPECT_EQ(field(r, "verdict").text, "asymptotically_stable") << "s = " << s;
    EXPECT_EQ(field(r, "quaternion_zero_eigenvalues").value, 1) << "s = " << s;
    EXPECT_EQ(field(r, "cyclic_zero_eigenvalues").value, 0) << "s = " << s;
    EXPECT_EQ(field(r, "symmetry_zero_eigenvalues").value, 0) << "its spring sees the turn about the vertical: s = " << s;
    EXPECT_EQ(field(field(r, "critical_case"), "first_approximation").text, "") << "not a critical case: s = " << s;
  }
  CommandOutput linear = run_eomgen("linear '" + model + "'");
  EXPECT_EQ(linear.status, 0) << linear.err;
  EXPECT_NE(linear.out.find("1 of the zero eigenvalues: the length of each quaternion"), std::string::npos) << linear.out;
}

}  // namespace
}  // namespace eomgen::test
