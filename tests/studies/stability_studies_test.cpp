// The studies behind `stability`, `sweep` and `linear` (generator/studies/), called in the
// test process: the equilibrium they are about, their refusals, the swept parameters, the
// Floquet analysis, Routh's reduction and the linear report, each against its closed form.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <regex>

#include <fmt/format.h>

#include "analyse/eigenvalue_sweep.hpp"
#include "derive/initial_state.hpp"
#include "studies/equilibrium_choice.hpp"
#include "studies/linear_report.hpp"
#include "studies/periodic_stability.hpp"
#include "studies/routh_reduction.hpp"
#include "studies/stability_study.hpp"
#include "studies/sweep_axes.hpp"
#include "study_support.hpp"

namespace eomgen::test {
namespace {

using namespace eomgen::studies;

// m x'' + c x' + k x = 0, with g pulling along x: the equilibrium is x = m g / k
const char* const hanging_oscillator = R"toml(
[model]
name = "hanging_oscillator"
title = "a mass on a spring and a damper, pulled along x"
[parameters]
m = 1.0
c = 0.5
k = 400.0
g = 9.81
[coordinates]
x = { initial = 0.1, rate = 0.0 }
[[particles]]
name = "mass"
mass = "m"
position = ["x", "0", "0"]
[energy]
potential = "k*x^2/2 - m*g*x"
dissipation = "c*der(x)^2/2"
)toml";

std::string verdict_in(const std::string& json) {
  std::smatch m;
  return std::regex_search(json, m, std::regex(R"re("verdict": "([a-z_]+)")re")) ? m[1].str() : "";
}

TEST(EquilibriumChoice, FoundFromTheInitialStateOrCheckedWhereGiven) {
  LoadedProblem loaded = load(write_model("hanging_oscillator", hanging_oscillator));
  ASSERT_TRUE(loaded.compiled);
  runtime::Equilibrium eq;
  StudyOutput found = run_study(
      [&] { return equilibrium_of(loaded.problem, {}, loaded.initial_state, eq).value_or(exit_success); });
  ASSERT_EQ(found.status, exit_success) << found.err;
  EXPECT_NEAR(eq.state[0], 9.81 / 400.0, 1e-12);
  EXPECT_EQ(eq.state[1], 0.0);
  // x = 0.1 is where the spring outweighs gravity: refused, with the residual named
  StudyOutput given = run_study(
      [&] { return equilibrium_of(loaded.problem, {"x=0.1"}, loaded.initial_state, eq).value_or(exit_success); });
  EXPECT_EQ(given.status, exit_user_error);
  EXPECT_NE(given.err.find("is not an equilibrium"), std::string::npos) << given.err;
  StudyOutput unknown = run_study(
      [&] { return equilibrium_of(loaded.problem, {"y=0"}, loaded.initial_state, eq).value_or(exit_success); });
  EXPECT_EQ(unknown.status, exit_user_error);
  EXPECT_NE(unknown.err.find("y"), std::string::npos) << unknown.err;
}

TEST(EquilibriumChoice, ALagrangeIModelIsRefusedForSymbolicConditions) {
  LoadedProblem loaded = load(model_path("pendulum_cartesian"));
  StudyOutput symbolic = run_study(
      [&] { return stability_refusal(loaded, "pendulum_cartesian.toml", true, true).value_or(exit_success); });
  EXPECT_EQ(symbolic.status, exit_user_error);
  EXPECT_NE(symbolic.err.find("Lagrange I model"), std::string::npos) << symbolic.err;
  StudyOutput numeric = run_study(
      [&] { return stability_refusal(loaded, "pendulum_cartesian.toml", false, true).value_or(exit_success); });
  EXPECT_EQ(numeric.status, exit_success) << "the numeric analysis works on the constraint manifold";
}

TEST(StabilityStudy, TheDampedOscillatorIsAsymptoticallyStableAtEveryScale) {
  // k·s², c·s, m: time scaled by s; eigenvalues −c/(2m) ± i·sqrt(k/m − c²/4m²), times s
  std::string path = write_model("hanging_oscillator", hanging_oscillator);
  for (double s : {1e-6, 1.0, 1e6}) {
    StabilityOptions o;
    o.model = path;
    o.sets = {fmt::format("k={:.17g}", 400 * s * s), fmt::format("c={:.17g}", 0.5 * s), fmt::format("g={:.17g}", 9.81 * s * s)};
    o.json = true;
    StudyOutput r = run_study([&] { return stability(o); });
    ASSERT_EQ(r.status, exit_success) << r.err;
    EXPECT_EQ(verdict_in(r.out), "asymptotically_stable") << "s = " << s << "\n" << r.out;
  }
}

TEST(SweepAxes, EveryCharacterOfEachFieldIsRead) {
  LoadedProblem loaded = load(write_model("hanging_oscillator", hanging_oscillator));
  const eomgen_model_abi& m = *loaded.compiled->abi();
  std::string name;
  std::optional<runtime::SweepAxis> axis;
  StudyOutput good = run_study([&] {
    axis = parse_axis(m, "k=100:400:7", name);
    return axis ? 0 : 2;
  });
  ASSERT_EQ(good.status, 0) << good.err;
  EXPECT_EQ(name, "k");
  EXPECT_EQ(axis->count, 7);
  EXPECT_EQ(axis->value(6), 400.0);
  EXPECT_EQ(axis->value(3), 250.0);
  // std::stoi("2e9") is 2: a count written so was once two points, silently
  for (const char* bad : {"k=0:20:2e9", "k=0:20:1", "k=20:0:5", "k=0:x:5", "k=0:20"}) {
    StudyOutput r = run_study([&] { return parse_axis(m, bad, name) ? 0 : 2; });
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_NE(r.err.find("--param"), std::string::npos) << r.err;
  }
  StudyOutput misspelt = run_study([&] { return parse_axis(m, "kk=0:1:3", name) ? 0 : 2; });
  EXPECT_EQ(misspelt.status, 2);
  EXPECT_NE(misspelt.err.find("did you mean 'k'"), std::string::npos) << misspelt.err;
}

// The sleeping top in Cardan angles, spinning at c' = w about its upright axis: the steady motion
// is stable when C² w² > 4 (A + m s²) m g s (Maievskii's criterion), w > 67.054 rad/s here, and
// then only marginally (gyroscopic stabilization, no damping)
const char* const sleeping_top = R"toml(
[model]
name = "sleeping_top"
title = "a heavy symmetric top spinning upright about a fixed point"
[parameters]
m = 0.5
s = 0.05
A = 0.0004
C = 0.0006
g = 9.81
w = 80.0
[coordinates]
a = 0.0
b = 0.0
c = { initial = 0.0, rate = "w" }
[[rigid_bodies]]
name = "top"
mass = "m"
center = ["s*sin(b)", "-s*sin(a)*cos(b)", "s*cos(a)*cos(b)"]
rotation = "cardan123(a, b, c)"
inertia = ["A", "A", "C"]
[gravity]
acceleration = ["0", "0", "-g"]
)toml";

// 2 √((A + m s²) m g s) / C from the loaded model's parameters
double maievskii_speed(const LoadedProblem& top) {
  const eomgen_model_abi& abi = *top.compiled->abi();
  auto value = [&](const char* name) {
    return top.problem.parameters[std::size_t(index_of(abi.parameter_names, abi.num_parameters, name))];
  };
  double m = value("m"), s = value("s"), A = value("A"), C = value("C"), g = value("g");
  return 2 * std::sqrt((A + m * s * s) * m * g * s) / C;
}

TEST(StabilityStudy, TheSleepingTopIsStableAboveMaievskiisSpeedAndOnlyMarginally) {
  std::string path = write_model("sleeping_top", sleeping_top);
  double critical = maievskii_speed(load(path));
  ASSERT_NEAR(critical, 67.054, 1e-3) << "the speed issue 37 names";
  for (double w : {0.95 * critical, 1.05 * critical}) {
    StabilityOptions o;
    o.model = path;
    o.sets = {fmt::format("w={:.17g}", w)};
    o.json = true;
    StudyOutput r = run_study([&] { return stability(o); });
    ASSERT_EQ(r.status, exit_success) << r.err;
    EXPECT_EQ(verdict_in(r.out), w < critical ? "unstable" : "marginally_stable") << "w = " << w << "\n" << r.out;
  }
  // w sets only the initial spin: no condition can be stated in it
  StabilityOptions symbolic;
  symbolic.model = path;
  symbolic.symbolic = "w";
  StudyOutput refused = run_study([&] { return stability(symbolic); });
  EXPECT_EQ(refused.status, exit_user_error);
  EXPECT_NE(refused.err.find("appears neither in the characteristic polynomial"), std::string::npos) << refused.err;
}

TEST(SweepStudy, TheSleepingTopsSweepEndsItsUnstableRunAtTheCrossingAndSaysMarginal) {
  LoadedProblem loaded = load(write_model("sleeping_top", sleeping_top));
  const eomgen_model_abi& m = *loaded.compiled->abi();
  std::string name;
  std::optional<runtime::SweepAxis> axis = parse_axis(m, "w=40:100:7", name);
  ASSERT_TRUE(axis);
  runtime::StartState spinning = [&](const std::vector<double>& parameters) {
    std::string failed;
    return initial_state(loaded.equations, parameters, failed);
  };
  std::atomic<bool> stop{false};
  runtime::EigenvalueSweep sweep =
      runtime::sweep_eigenvalues(loaded.problem, spinning, false, *axis, 1e-10, 1, [](long, long) {}, stop);
  ASSERT_EQ(sweep.crossings.size(), 1u);
  EXPECT_NEAR(sweep.crossings[0].parameter, maievskii_speed(loaded), 1e-6);
  EXPECT_LE(sweep.resolution, 6e-9);
  EXPECT_TRUE(sweep.stable.empty()) << "no damping: never asymptotically stable";
  ASSERT_EQ(sweep.marginal.size(), 1u);
  EXPECT_EQ(sweep.marginal[0].low, 70.0);
  EXPECT_EQ(sweep.marginal[0].high, 100.0);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(sweep.verdicts[std::size_t(k)], "unstable") << axis->value(k);
}

TEST(PeriodicStudy, TheMonodromyOfMathieuWithoutExcitationIsTheClosedForm) {
  // q = 0: x'' + a x = 0 over T = π: Φ = [[cos(sπ), sin(sπ)/s], [−s sin(sπ), cos(sπ)]], s = √a
  LoadedProblem loaded = load(model_path("mathieu"), {"q=0", "a=2.5"});
  PeriodicOptions o;
  o.json = true;
  StudyOutput r = run_study([&] { return periodic_stability(loaded, o).value_or(-1); });
  ASSERT_EQ(r.status, exit_success) << r.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"re("monodromy": \[\[([-0-9.e+]+), ([-0-9.e+]+)\], \[([-0-9.e+]+), ([-0-9.e+]+)\]\])re")))
      << r.out;
  double s = std::sqrt(2.5);
  EXPECT_NEAR(std::stod(m[1]), std::cos(s * M_PI), 1e-10);
  EXPECT_NEAR(std::stod(m[2]), std::sin(s * M_PI) / s, 1e-10);
  EXPECT_NEAR(std::stod(m[3]), -s * std::sin(s * M_PI), 1e-10);
  EXPECT_NEAR(std::stod(m[4]), std::cos(s * M_PI), 1e-10);
  // an autonomous model is not this study's
  LoadedProblem pendulum = load(model_path("pendulum"));
  EXPECT_FALSE(periodic_stability(pendulum, o).has_value());
}

TEST(RouthStudy, AMomentumGivenWithAtEliminatesItsCyclicCoordinate) {
  LoadedProblem loaded = load(model_path("spherical_pendulum"));
  RouthRequest request = routh_request(*loaded.compiled->abi(), {"p_phi=0.5", "theta=1"});
  EXPECT_EQ(request.eliminated, std::vector<std::string>{"phi"});
  EXPECT_EQ(request.momentum_sets, std::vector<std::string>{"p_phi=0.5"});
  EXPECT_EQ(request.at, std::vector<std::string>{"theta=1"});
  EXPECT_TRUE(routh_request(*loaded.compiled->abi(), {"theta=1"}).eliminated.empty());
  // the reduced model: theta alone, with p_phi a parameter
  LoadedProblem reduced;
  StudyOutput r = run_study(
      [&] { return load_reduced_problem(model_path("spherical_pendulum"), {}, request, reduced).value_or(exit_success); });
  ASSERT_EQ(r.status, exit_success) << r.err;
  EXPECT_EQ(reduced.compiled->abi()->num_coordinates, 1u);
  EXPECT_NE(routh_text(reduced.equations, request).find("phi"), std::string::npos);
}

TEST(LinearStudy, TheOscillatorsMatricesAndEigenvalues) {
  LoadedProblem loaded = load(write_model("hanging_oscillator", hanging_oscillator));
  std::vector<double> x{9.81 / 400.0, 0.0};
  LinearReport r = linear_report(loaded.problem, x, LinearRequest{{0.1}, {}, {}, false}, &loaded.equations);
  ASSERT_EQ(r.A.rows(), 2);
  EXPECT_NEAR(r.A(0, 0), 0.0, 1e-15);
  EXPECT_NEAR(r.A(0, 1), 1.0, 1e-15);
  EXPECT_NEAR(r.A(1, 0), -400.0, 1e-9);
  EXPECT_NEAR(r.A(1, 1), -0.5, 1e-12);
  // λ² + 0.5 λ + 400
  ASSERT_EQ(r.characteristic_polynomial.size(), 3u);
  EXPECT_NEAR(r.characteristic_polynomial[1], 0.5, 1e-12);
  EXPECT_NEAR(r.characteristic_polynomial[2], 400.0, 1e-9);
  ASSERT_EQ(r.system.eigenvalues.size(), 2u);
  EXPECT_NEAR(r.system.eigenvalues[0].real(), -0.25, 1e-12);
  EXPECT_NEAR(std::abs(r.system.eigenvalues[0].imag()), std::sqrt(400 - 0.0625), 1e-9);
  // Φ(0.1) = e^{0.1 A}: its first entry e^{−0.025}(cos ωd t + 0.25/ωd sin ωd t)
  ASSERT_EQ(r.fundamental.size(), 1u);
  double wd = std::sqrt(400 - 0.0625), t = 0.1;
  EXPECT_NEAR(r.fundamental[0].second(0, 0), std::exp(-0.25 * t) * (std::cos(wd * t) + 0.25 / wd * std::sin(wd * t)), 1e-10);
}

}  // namespace
}  // namespace eomgen::test
