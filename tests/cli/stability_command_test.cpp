// `eomgen stability` and `eomgen sweep` on the command line: the documented
// JSON keys, equilibria given and searched for, mistakes, and the map's files.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <tuple>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "parse/json_reader.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

using Output = CommandOutput;
Output eomgen(const std::string& arguments) { return run_eomgen(arguments); }

TEST(StabilityCommand, JsonHasTheDocumentedKeys) {
  Output r = eomgen("stability '" + model_path("pendulum") + "' --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* key : {"\"equilibrium\"", "\"A\"", "\"B\"", "\"M\"", "\"D\"", "\"G\"", "\"K\"", "\"N\"", "\"eigenvalues\"",
                          "\"verdict\": \"marginally_stable\"", "\"stability_degree\"", "\"modes\"",
                          "\"characteristic_polynomial\"", "\"hurwitz\"", "\"theorems\"", "\"conditions\""})
    EXPECT_NE(r.out.find(key), std::string::npos) << key << "\n" << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << "one JSON object on one line";
}

// a body thrown under gravity has no equilibrium: said with why, not as a search that failed
TEST(StabilityCommand, AFallingBodyHasNoEquilibriumAndIsToldWhy) {
  Output r = eomgen("stability '" + model_path("tumbling_body") + "'");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("error: no equilibrium exists: at rest, der(z) changes at the rate -9.81 in every configuration tried"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("hint: a floating base falls unless something holds it"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("no equilibrium found"), std::string::npos) << r.err;
}

// A floating humanoid falls too, but its joints swing as it does, so no velocity's rate is one
// number; its base's vertical row of M q'' = f, the momentum balance, is: f = −(Σ m) g at rest in
// every configuration, the masses summed from its file here
TEST(StabilityCommand, AFallingHumanoidHasNoEquilibriumByItsMomentumBalance) {
  std::string model = std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/models/floating_humanoid.toml";
  std::string text = read_file(model);
  double mass = 0;
  std::regex body_mass(R"re(\nmass\s*=\s*"?([0-9.eE+-]+))re");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), body_mass); it != std::sregex_iterator(); ++it)
    mass += std::stod((*it)[1]);
  ASSERT_GT(mass, 0);
  for (double g : {9.81, 9.81e6}) {
    Output r = eomgen(fmt::format("stability '{}' --set g={:g}", model, g));
    EXPECT_EQ(r.status, 2) << r.err;
    std::smatch m;
    std::regex told(R"(no equilibrium exists: at rest, the generalized force of the row of der\(z\) is ([-0-9.e+]+) in every )"
                    R"(configuration tried)");
    ASSERT_TRUE(std::regex_search(r.err, m, told)) << r.err;
    EXPECT_NEAR(std::stod(m[1]) / (-mass * g), 1, 1e-6) << "six digits printed";
  }
}

// vanishing Hurwitz conditions mean "at best marginal", never "holds"
TEST(StabilityCommand, SymbolicConditionsThatVanishDecideNothing) {
  Output undamped = eomgen("stability '" + model_path("two_mass_spring_damper") + "' --set d1=0 --set d2=0 --symbolic k1");
  ASSERT_EQ(undamped.status, 0) << undamped.err;
  EXPECT_NE(undamped.out.find("at best marginal: the coefficient of lambda^3"), std::string::npos) << undamped.out;
  EXPECT_EQ(undamped.out.find("every Hurwitz condition holds"), std::string::npos) << undamped.out;
  Output json = eomgen("stability '" + model_path("two_mass_spring_damper") +
                       "' --set d1=0 --set d2=0 --symbolic k1 --format json");
  EXPECT_NE(json.out.find("\"vanishing_conditions\": [\"the coefficient of lambda^3\""), std::string::npos) << json.out;
  Output damped = eomgen("stability '" + model_path("two_mass_spring_damper") + "' --symbolic k1");
  EXPECT_EQ(damped.out.find("at best marginal"), std::string::npos) << damped.out;
}

// a parameter that only sets the initial state was evaluated there: no condition is in it
TEST(StabilityCommand, SymbolicParameterAbsentFromThePolynomialIsRefused) {
  std::string model = temporary_directory() + "/launched.toml";
  std::string text = read_file(model_path("two_mass_spring_damper"));
  text.replace(text.find("d2 = 0.2"), 8, "d2 = 0.2\nv0 = 0.3");
  text.replace(text.find("x2 = 0.0"), 8, "x2 = { initial = 0.0, rate = \"v0\" }");
  std::ofstream(model) << text;
  Output r = eomgen("stability '" + model + "' --symbolic v0");
  EXPECT_EQ(r.status, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("--symbolic v0: v0 appears neither in the characteristic polynomial"), std::string::npos) << r.err;
}

// smaller findings of the verdict review, each said plainly
TEST(StabilityCommand, ConstantsNegativeMassesAndBadPeriodsAreSaidPlainly) {
  Output upright = eomgen("stability '" + model_path("pendulum") + "' --at phi=Pi --format json");
  ASSERT_EQ(upright.status, 0) << upright.err;
  EXPECT_NE(upright.out.find("\"verdict\": \"unstable\""), std::string::npos) << upright.out;
  Output quarter = eomgen("stability '" + model_path("pendulum") + "' --at 'phi=3*Pi/4+'");
  EXPECT_EQ(quarter.status, 2);
  EXPECT_NE(quarter.err.find("expected NAME=NUMBER or a constant expression"), std::string::npos) << quarter.err;
  Output negative = eomgen("stability '" + model_path("pendulum") + "' --set m=-1");
  EXPECT_EQ(negative.status, 3) << "a state unfit for analysis";
  EXPECT_NE(negative.err.find("not positive definite"), std::string::npos) << negative.err;
  EXPECT_EQ(negative.err.find("singular"), std::string::npos) << negative.err;
  Output period = eomgen("stability '" + model_path("mathieu") + "' --period -1");
  EXPECT_EQ(period.status, 2);
  EXPECT_NE(period.err.find("'-1' is not a positive number"), std::string::npos) << period.err;
  EXPECT_LT(period.err.size(), 200u) << "no largest double in full: " << period.err;
}

TEST(StabilityCommand, AStateThatIsNotAnEquilibriumIsRefused) {
  Output r = eomgen("stability '" + model_path("pendulum") + "' --at phi=0.3");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("is not an equilibrium"), std::string::npos) << r.err;
  Output upright = eomgen("stability '" + model_path("pendulum") + "' --at phi=3.141592653589793");
  EXPECT_EQ(upright.status, 0) << upright.err;
  EXPECT_NE(upright.out.find("verdict: unstable"), std::string::npos) << upright.out;
}

// A mass m on a spring of 1 N/m hangs m g / k below z = 0, for m from 1e-12 to 1 kg: z = 0 is
// refused as its equilibrium and the search finds z = −m g / k. A tolerance with a floor of one
// metre had taken z = 0 for the equilibrium of 1e-12 kg (9.81e-12 m away); the forces it holds,
// m g at the model's default z = 0, now set the scale.
TEST(StabilityCommand, ALightHangingMassIsNotAtRestWhereItHangsFrom) {
  std::string model = write_model("light_hanging_mass", R"toml([model]
name = "light_hanging_mass"
[parameters]
m = 1.0
k = 1.0
g = 9.81
[coordinates]
z = { initial = 0.0, rate = 0.0 }
[[particles]]
name = "mass"
mass = "m"
position = ["0", "0", "z"]
[gravity]
acceleration = ["0", "0", "-g"]
[energy]
potential = "k*z^2/2"
)toml");
  for (double m : {1e-12, 1e-9, 1e-6, 1e-3, 1.0}) {
    std::string set = fmt::format(" --set m={:.17g}", m);
    Output at_zero = eomgen("stability '" + model + "' --at z=0" + set);
    EXPECT_EQ(at_zero.status, 2) << "m = " << m << ": " << at_zero.out;
    EXPECT_NE(at_zero.err.find("is not an equilibrium"), std::string::npos) << at_zero.err;
    JsonValue found = run_json("stability '" + model + "'" + set);
    const JsonValue* equilibrium = found.find("equilibrium");
    ASSERT_TRUE(equilibrium) << "m = " << m;
    EXPECT_NEAR(at(*equilibrium, "z"), -m * 9.81, 1e-9 * m * 9.81) << "m = " << m;
  }
}

TEST(StabilityCommand, SteadyMotionOfTheGovernorWithSymbolicConditions) {
  Output r = eomgen("stability '" + model_path("watt_governor") + "' --symbolic b,J");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("verdict: asymptotically_stable"), std::string::npos) << r.out;
  // the values of the condition are checked against Vyshnegradsky in stability_conditions_test;
  // here: it is printed, as an inequality in both kept parameters
  std::smatch condition;
  EXPECT_TRUE(std::regex_search(r.out, condition, std::regex(R"(\n    [^\n]*\bJ\*b\b[^\n]* > 0\n)"))) << r.out;
  Output bad = eomgen("stability '" + model_path("watt_governor") + "' --symbolic damping");
  EXPECT_EQ(bad.status, 2);
}

TEST(SweepCommand, WritesTheMapAndItsChart) {
  std::string dir = temporary_directory();
  Output r = eomgen("sweep '" + model_path("watt_governor") + "' --param b=0.05:1.2:20 --param J=0.05:3:20 --symbolic -o '" +
                    dir + "/map.csv' --plot '" + dir + "/map.png' --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\"points\": 400"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"computed\": 400"), std::string::npos) << r.out;
  std::ifstream csv(dir + "/map.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "b,J,stability_degree,symbolic_margin");
  int rows = 0;
  for (std::string line; std::getline(csv, line);) ++rows;
  EXPECT_EQ(rows, 400);
  EXPECT_GT(std::filesystem::file_size(dir + "/map.png"), 10000u);
  EXPECT_EQ(eomgen("sweep '" + model_path("watt_governor") + "' --param b=1:0:20 --param J=0.05:3:20").status, 2);
}

TEST(StabilityCommand, ConstrainedModelsAreRefusedWhereTheAnalysisDoesNotApply) {
  Output linear = eomgen("linear '" + model_path("slider_crank") + "'");
  EXPECT_EQ(linear.status, 2);
  EXPECT_NE(linear.err.find("Lagrange I model"), std::string::npos) << linear.err;
  Output lagrange1 = eomgen("stability '" + model_path("pendulum_cartesian") + "' --at x=0 --at y=-1 --symbolic g");
  EXPECT_EQ(lagrange1.status, 2);
  EXPECT_NE(lagrange1.err.find("symbolic conditions need them"), std::string::npos) << lagrange1.err;
  Output symbolic = eomgen("sweep '" + model_path("rolling_disk") + "' --param R=0.05:0.2:3 --param m=0.5:2:3 "
                           "--at theta=1.5707963267948966 --at 'der(phi)=6' --symbolic");
  EXPECT_EQ(symbolic.status, 2) << symbolic.err;
  EXPECT_NE(symbolic.err.find("Appell models are analysed numerically"), std::string::npos) << symbolic.err;
}

// A ball joint's quaternion keeps the frames' quantities as intermediates: no symbolic conditions
// (the attempt ran for minutes past --max-seconds before this refusal), the numeric analysis as
// usual. The spatial double pendulum's frames read as joints: it is derived written out in q for them.
TEST(StabilityCommand, BallJointsHaveNoSymbolicConditions) {
  std::string top = model_path("ball_joint_top");
  Output symbolic = eomgen("stability '" + top + "' --symbolic g");
  EXPECT_EQ(symbolic.status, 2) << symbolic.err;
  EXPECT_NE(symbolic.err.find("those of ball and free joints hold the frames' quantities"), std::string::npos) << symbolic.err;
  EXPECT_NE(symbolic.err.find("hint: leave out --symbolic"), std::string::npos) << symbolic.err;
  Output sweep = eomgen("sweep '" + top + "' --param g=1:10:3 --param m=0.5:1:3 --symbolic");
  EXPECT_EQ(sweep.status, 2) << sweep.err;
  EXPECT_NE(sweep.err.find("ball and free joints"), std::string::npos) << sweep.err;
  Output written_out = eomgen("stability '" + model_path("spatial_double_pendulum") + "' --symbolic g");
  EXPECT_EQ(written_out.status, 0) << written_out.err;
  EXPECT_NE(written_out.out.find("stability conditions in g"), std::string::npos) << written_out.out;
}

// The pendulum in Cartesian coordinates (Lagrange I, x² + y² = l²) on its constraint manifold:
// hanging, λ = ±i·√(g/l) (a centre); upright, λ = ±√(g/l) (a saddle); y and der(y) are tied to x
TEST(StabilityCommand, LagrangeOneIsAnalysedOnTheConstraintManifold) {
  double root = std::sqrt(9.81 / 1.0);
  for (double y : {-1.0, 1.0}) {
    JsonValue r = run_json("stability '" + model_path("pendulum_cartesian") + "' --at x=0 --at y=" + std::to_string(y));
    std::vector<std::string> state;
    for (const JsonValue& name : r.find("state")->items) state.push_back(name.text);
    EXPECT_EQ(state, (std::vector<std::string>{"x", "der(x)"}));
    const auto& eigenvalues = r.find("eigenvalues")->items;
    ASSERT_EQ(eigenvalues.size(), 2u);
    for (const JsonValue& l : eigenvalues) {
      ASSERT_EQ(l.items.size(), 2u) << "[re, im]";
      EXPECT_NEAR(std::abs(l.items[0].value), y < 0 ? 0.0 : root, 1e-12) << "y = " << y;
      EXPECT_NEAR(std::abs(l.items[1].value), y < 0 ? root : 0.0, 1e-12) << "y = " << y;
    }
    EXPECT_EQ(r.find("verdict")->text, y < 0 ? "marginally_stable" : "unstable");
  }
}

TEST(StabilityCommand, RollingDiskFromTheCommandLine) {
  Output fast = eomgen("stability '" + model_path("rolling_disk") + "' --at theta=1.5707963267948966 --at 'der(phi)=8'");
  Output slow = eomgen("stability '" + model_path("rolling_disk") + "' --at theta=1.5707963267948966 --at 'der(phi)=4'");
  ASSERT_EQ(fast.status, 0) << fast.err;
  EXPECT_NE(fast.out.find("verdict: marginally_stable"), std::string::npos) << fast.out;
  EXPECT_NE(slow.out.find("verdict: unstable"), std::string::npos) << slow.out;
}

// models/spherical_pendulum.toml on time scale s: g by s², the initial turning rate by s
std::string spherical_pendulum_on_time_scale(double s) {
  std::string text = read_file(model_path("spherical_pendulum"));
  for (auto [line, scaled] : {std::pair<std::string, std::string>{"g = 9.81", fmt::format("g = {:.17g}", 9.81 * s * s)},
                              {"rate = 2.0", fmt::format("rate = {:.17g}", 2 * s)}}) {
    EXPECT_NE(text.find(line), std::string::npos) << line;
    if (text.find(line) != std::string::npos) text.replace(text.find(line), line.size(), scaled);
  }
  return write_model("spherical_pendulum", text);
}

// A spherical pendulum released at θ = 0.8 turning at φ' = 2 s (time scale s): no conical motion
// turns that fast or that slowly (φ'² = g/(l cos θ)). Newton from there slid to θ = 0, where the
// azimuth is undefined and any φ' balances ("the mass matrix is singular", nothing analysed), or
// found nothing at s = 1e-12 and 1e12. Now, where it does, the search takes the steady motion at
// θ = 0.8 instead and says so: at every time scale from 1e-12 to 1e12 a conical motion near
// θ = 0.8 is found and is stable. The heavy top's steady precession (Hiller §3.9):
// m g s = Ω (C ω3 − A' Ω cos θ), A' = A + m s² about the pivot, ω3 = φ' + Ω cos θ, found near its
// initial θ = 0.3 at the same θ at time scales T of 1e-6, 1 and 1e6 (g over T², its spin over T: the
// search steps the rates in their own scale), and at θ = 0.3 where --at holds it there.
TEST(StabilityCommand, ASearchThatEndsAtASingularityOfTheCoordinatesTakesTheSteadyMotionThere) {
  for (double s : {1e-12, 1e-6, 1e-3, 1.0, 1e3, 1e6, 1e12}) {
    std::string model = spherical_pendulum_on_time_scale(s);
    Output r = eomgen("stability '" + model + "'");
    ASSERT_EQ(r.status, 0) << "s = " << s << ": " << r.err;
    EXPECT_NE(r.out.find("nonlinear verdict: stable"), std::string::npos) << r.out;
    JsonValue json = run_json("stability '" + model + "'");
    const JsonValue& equilibrium = *json.find("equilibrium");
    double theta = at(equilibrium, "theta"), conical = s * std::sqrt(9.81 / std::cos(theta));
    EXPECT_NEAR(theta, 0.8, 1e-3) << "s = " << s;
    EXPECT_NEAR(at(equilibrium, "der(phi)") / conical, 1, 1e-9) << "s = " << s;
    if (s == 1) {  // the shipped model as it is: the search ends at θ = 0, and says what it did then
      EXPECT_NE(r.err.find("where the mass matrix is singular (so are the coordinates there); this is the steady motion"),
                std::string::npos) << r.err;
    }
  }
  double unscaled_theta = NAN;
  for (double T : {1.0, 1e-6, 1e6}) {
    std::string top = write_model("heavy_symmetric_top", edited(read_file(model_path("heavy_symmetric_top")),
                                                                {{"rate = 100.0", fmt::format("rate = {:.17g}", 100 / T)}}));
    const double m = 0.5, s = 0.05, A = 0.0004 + m * s * s, C = 0.0006, g = 9.81 / (T * T);
    for (std::string held : {"", "--at theta=0.3"}) {
      JsonValue json = run_json(fmt::format("stability '{}' --set g={:.17g} {}", top, g, held));
      const JsonValue& steady = *json.find("equilibrium");
      double theta = at(steady, "theta"), precession = at(steady, "der(psi)");
      double spin = at(steady, "der(phi)") + precession * std::cos(theta);
      EXPECT_NEAR(precession * (C * spin - A * precession * std::cos(theta)), m * g * s, 1e-9 * m * g * s) << "T = " << T;
      if (!held.empty()) {
        EXPECT_EQ(theta, 0.3) << "T = " << T;
        continue;
      }
      EXPECT_NEAR(theta, 0.3, 1e-2) << "T = " << T;
      if (T == 1.0) unscaled_theta = theta;
      EXPECT_NEAR(theta, unscaled_theta, 1e-9) << "T = " << T;
    }
  }
}

// --at that names some states holds them and solves for the rest where the rest as given do not
// balance: a spherical pendulum held at θ0 turns at φ'² = g/(l cos θ0) (from the model's φ' = 2 s,
// at time scales s from 1e-12 to 1e12), and a pendulum on a cart held at x = 5 hangs upside down
// at θ = π, the nearest balance to its initial 3.0. Before, each was "not an equilibrium". A double
// pendulum held at φ1 = 0.5 has none, and says that the search with φ2 free found none either.
// 21 hinges about oblique axes under gravity, started at angles of up to 0.2 rad: Newton's method from
// there goes round for 100 steps, and the path on which the start's forces are scaled down folds back
// (the tree snaps through). Where it comes to rest with damping added is an equilibrium, which the
// model simulated from it keeps, and asymptotically stable (the model has damping on every joint),
// which a disturbed start that the model brings back shows.
TEST(StabilityCommand, ATreeWhoseNewtonSearchWandersIsFoundWhereItComesToRest) {
  std::string model = std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/models/branched_tree.toml";
  Output r = eomgen("stability '" + model + "' --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("is where the model, released at its initial state with damping added, comes to rest"),
            std::string::npos) << r.err;
  Diagnostics diagnostics;
  std::optional<JsonValue> json = parse_json(r.out, "stability", diagnostics);
  ASSERT_TRUE(json) << r.out;
  EXPECT_EQ(json->find("verdict")->text, "asymptotically_stable");
  std::string at, disturbed;
  for (const auto& [name, value] : json->find("equilibrium")->members) {
    at += fmt::format(" --initial '{}={:.17g}'", name, value.value);
    disturbed += fmt::format(" --initial '{}={:.17g}'", name, value.value + (name == "q1" ? 0.05 : 0.0));
  }
  std::string scratch = temporary_directory();
  for (const auto& [given, t_end, within] : {std::tuple{at, 2.0, 1e-9}, std::tuple{disturbed, 200.0, 1e-4}}) {
    Output run = eomgen("simulate '" + model + "'" + given + " --t-end " + std::to_string(t_end) + " --rtol 1e-10 -o '" +
                        scratch + "/rest.csv'");
    ASSERT_EQ(run.status, 0) << run.err;
    std::vector<std::vector<double>> rows = read_numeric_csv(scratch + "/rest.csv");
    double largest = 0;
    for (std::size_t i = 0; i < 21; ++i)
      largest = std::max(largest, std::abs(rows.back()[1 + i] - json->find("equilibrium")->members[i].second.value));
    EXPECT_LT(largest, within) << "t_end " << t_end;
  }
}

// The servo pendulum started at 2 rad, where its servo saturates: its torque is constant there, and
// Newton's method from the start has no slope to follow. Released with damping added, it comes to
// rest where the servo's pull kp (u − φ) holds gravity's m g s sin φ, at every time scale T (g, kp
// and tau_max in 1/T², kd in 1/T).
TEST(StabilityCommand, ASaturatedServoIsFoundWhereItComesToRestAtEveryTimeScale) {
  const double kp = 20, m = 1.5, g = 9.81, s = 0.25, u = 0.5;
  double phi = 0.4;  // kp (u − φ) = m g s sin φ, by Newton's method
  for (int k = 0; k < 50; ++k) phi -= (kp * (u - phi) - m * g * s * std::sin(phi)) / (-kp - m * g * s * std::cos(phi));
  for (double T : {1e-12, 1.0, 1e12}) {
    std::string set = fmt::format(" --set u={} --set m={} --set s={} --set g={:.17g} --set kp={:.17g} --set kd={:.17g} "
                                  "--set tau_max={:.17g}", u, m, s, g / (T * T), kp / (T * T), 2.0 / T, 6.0 / (T * T));
    Output r = eomgen("stability '" + model_path("servo_pendulum") + "'" + set + " --format json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("comes to rest"), std::string::npos) << r.err;
    Diagnostics diagnostics;
    std::optional<JsonValue> json = parse_json(r.out, "stability", diagnostics);
    ASSERT_TRUE(json) << r.out;
    EXPECT_NEAR(at(*json->find("equilibrium"), "phi"), phi, 1e-12) << "T = " << T;
    EXPECT_EQ(json->find("verdict")->text, "asymptotically_stable") << "T = " << T;
  }
}

// A Lagrange I model at rest where it hangs, at time scales of 1e-12 and 1e12 s (g in 1/T²): the
// Cartesian pendulum's linearization on its rod is an oscillator of sqrt(g/l). Its velocities' columns
// (entries of 1) beside the positions' (9.81e24) had been taken for columns no rate depends on, then
// the positions' too, and the eigenvalue solver crashed (exit 139) on an empty A.
TEST(StabilityCommand, ALagrangeOneModelIsLinearizedOnItsConstraintsAtEveryTimeScale) {
  for (double T : {1e-12, 1.0, 1e12}) {
    Output r = eomgen(fmt::format("stability '{}' --set g={:.17g} --at x=0 --at y=-1 --format json",
                                  model_path("pendulum_cartesian"), 9.81 / (T * T)));
    ASSERT_EQ(r.status, 0) << "T = " << T << "\n" << r.err;
    Diagnostics diagnostics;
    std::optional<JsonValue> json = parse_json(r.out, "stability", diagnostics);
    ASSERT_TRUE(json) << r.out;
    EXPECT_EQ(json->find("verdict")->text, "marginally_stable") << "T = " << T;
    const JsonValue& eigenvalues = *json->find("eigenvalues");
    ASSERT_EQ(eigenvalues.items.size(), 2u) << "T = " << T << "\n" << r.out;
    for (const JsonValue& e : eigenvalues.items)
      EXPECT_NEAR(std::abs(e.items.at(1).value) * T / std::sqrt(9.81), 1, 1e-9) << "T = " << T << "\n" << r.out;
  }
}

// the Cartesian pendulum with a rod of length L released at 0.5 rad (its file's initial values
// scaled), written to a file of its own
std::string cartesian_pendulum_of_length(double L) {
  std::string text = edited(read_file(model_path("pendulum_cartesian")),
                            {{"l = 1.0", fmt::format("l = {:.17g}", L)},
                             {"initial = 0.479425538604203", fmt::format("initial = {:.17g}", L * std::sin(0.5))},
                             {"initial = -0.877582561890373", fmt::format("initial = {:.17g}", -L * std::cos(0.5))}});
  return write_file(fmt::format("pendulum_cartesian_{:g}.toml", L), text);
}

// Lagrange I: a configuration off equilibrium is refused by each rate against its own terms, not
// against the 1 of q' = v (at 1e12 s, q'' of 4e-24 had passed), one off the rod is refused as such,
// and the search from 0.5 rad finds the hanging pendulum, whose long runs keep the rod by projection
// alone (with Baumgarte's gains of 10/s against a period of 2e12 s, BDF gave up: "unstable")
TEST(StabilityCommand, ALagrangeOneEquilibriumIsSearchedAndCheckedOnItsConstraintsAtEveryScale) {
  for (auto [T, L] : {std::pair{1e-12, 1.0}, {1.0, 1.0}, {1e12, 1.0}, {1.0, 1e-12}, {1.0, 1e12}, {1e12, 1e12}}) {
    std::string where = fmt::format("T = {:g} s, L = {:g} m", T, L);
    std::string model = fmt::format("stability '{}' --set g={:.17g}", cartesian_pendulum_of_length(L), 9.81 * L / (T * T));
    Output released = eomgen(model + fmt::format(" --at x={:.17g} --at y={:.17g}", L * std::sin(0.5), -L * std::cos(0.5)));
    EXPECT_EQ(released.status, 2) << where;
    EXPECT_NE(released.err.find("is not an equilibrium: the largest residual of the equations of motion"), std::string::npos)
        << where << "\n" << released.err;
    Output off_the_rod = eomgen(model + fmt::format(" --at x=0 --at y={:.17g}", -1.1 * L));
    EXPECT_EQ(off_the_rod.status, 2) << where;
    EXPECT_NE(off_the_rod.err.find("does not meet the constraints: rod = "), std::string::npos)
        << where << "\n" << off_the_rod.err;
    EXPECT_EQ(eomgen(model + fmt::format(" --at x=0 --at y={:.17g}", -L)).status, 0) << where;
    Output searched = eomgen(model + " --format json");
    ASSERT_EQ(searched.status, 0) << where << "\n" << searched.err;
    Diagnostics diagnostics;
    std::optional<JsonValue> json = parse_json(searched.out, "stability", diagnostics);
    ASSERT_TRUE(json) << searched.out;
    const JsonValue& equilibrium = *json->find("equilibrium");
    EXPECT_NEAR(at(equilibrium, "x") / L, 0, 1e-12) << where;
    EXPECT_NEAR(at(equilibrium, "y") / L, -1, 1e-12) << where;
    EXPECT_EQ(json->find("verdict")->text, "marginally_stable") << where;
    for (const JsonValue& e : json->find("eigenvalues")->items)
      EXPECT_NEAR(std::abs(e.items.at(1).value) * T / std::sqrt(9.81), 1, 1e-9) << where;
    EXPECT_EQ(json->find("critical_case")->find("nonlinear_verdict")->text, "stable") << where << "\n" << searched.out;
  }
}

// Appell: the rolling disk tilted at rest falls, and is refused at every time scale T (at 1e12 s
// its rate of 1e-23 had passed against the 1 of q' = W s); upright and spinning, it rolls steadily
TEST(StabilityCommand, AnAppellSteadyMotionIsCheckedRateByRateAtEveryTimeScale) {
  for (double T : {1e-12, 1.0, 1e12}) {
    std::string model = fmt::format("stability '{}' --set g={:.17g}", model_path("rolling_disk"), 9.81 / (T * T));
    Output tilted = eomgen(model + " --at theta=1.4");
    EXPECT_EQ(tilted.status, 2) << "T = " << T << "\n" << tilted.out;
    EXPECT_NE(tilted.err.find("is not an equilibrium"), std::string::npos) << "T = " << T << "\n" << tilted.err;
    Output rolling = eomgen(model + fmt::format(" --at theta={:.17g} --at 'der(phi)={:.17g}'", M_PI / 2, 15 / T));
    EXPECT_EQ(rolling.status, 0) << "T = " << T << "\n" << rolling.err;
    EXPECT_NE(rolling.out.find("verdict: marginally_stable"), std::string::npos) << "T = " << T << "\n" << rolling.out;
  }
}

// The four-bar's equilibrium found on its loop, checked against its potential written out here:
// V's gradient is normal to the loop there (no component along the loop's one tangent). Its links'
// lengths and g are set here; the masses (0.3, 0.6, 0.5) and the coupler's centre 0.01 off its
// axis are numbers in the file.
TEST(StabilityCommand, AFourBarsEquilibriumIsWhereItsPotentialIsStationaryOnItsLoop) {
  const double a = 0.25, b = 0.55, c = 0.45, d = 0.5, g = 3.7;
  JsonValue json = run_json(fmt::format("stability '{}' --set a={} --set b={} --set c={} --set d={} --set g={}",
                                        model_path("four_bar_linkage"), a, b, c, d, g));
  const JsonValue& equilibrium = *json.find("equilibrium");
  double c1 = at(equilibrium, "crank"), c2 = at(equilibrium, "coupler"), c3 = at(equilibrium, "rocker"), c12 = c1 + c2;
  // the pin: a (cos c1, sin c1) + b (cos c12, sin c12) = (d, 0) + c (cos c3, sin c3)
  EXPECT_NEAR(a * std::cos(c1) + b * std::cos(c12) - d - c * std::cos(c3), 0, 1e-12);
  EXPECT_NEAR(a * std::sin(c1) + b * std::sin(c12) - c * std::sin(c3), 0, 1e-12);
  // the pin's two gradients in (crank, coupler, rocker); the loop's tangent is normal to both
  Eigen::Vector3d pin_x(-a * std::sin(c1) - b * std::sin(c12), -b * std::sin(c12), c * std::sin(c3));
  Eigen::Vector3d pin_y(a * std::cos(c1) + b * std::cos(c12), b * std::cos(c12), -c * std::cos(c3));
  Eigen::Vector3d tangent = pin_x.cross(pin_y).normalized();
  // V = g (0.3 a/2 sin c1 + 0.6 (a sin c1 + b/2 sin c12 + 0.01 cos c12) + 0.5 c/2 sin c3)
  double coupler = 0.6 * g * (b / 2 * std::cos(c12) - 0.01 * std::sin(c12));
  Eigen::Vector3d gradient(0.3 * g * a / 2 * std::cos(c1) + 0.6 * g * a * std::cos(c1) + coupler, coupler,
                           0.5 * g * c / 2 * std::cos(c3));
  EXPECT_NEAR(gradient.dot(tangent) / gradient.norm(), 0, 1e-9) << "crank " << c1 << ", coupler " << c2 << ", rocker " << c3;
  EXPECT_EQ(json.find("verdict")->text, "unstable");
}

TEST(StabilityCommand, AnAtThatNamesSomeStatesSolvesForTheRest) {
  for (double s : {1e-12, 1e-6, 1.0, 1e6, 1e12}) {
    std::string model = spherical_pendulum_on_time_scale(s);
    for (double theta : {0.3, 0.8, 1.2}) {
      std::string given = fmt::format(" --at theta={}", theta);
      Output r = eomgen("stability '" + model + "'" + given);
      ASSERT_EQ(r.status, 0) << "s = " << s << given << ": " << r.err;
      EXPECT_NE(r.err.find("with the named ones held, der(phi) = "), std::string::npos) << r.err;
      JsonValue json = run_json("stability '" + model + "'" + given);
      const JsonValue& equilibrium = *json.find("equilibrium");
      EXPECT_EQ(at(equilibrium, "theta"), theta);
      EXPECT_NEAR(at(equilibrium, "der(phi)") / (s * std::sqrt(9.81 / std::cos(theta))), 1, 1e-12) << "s = " << s << given;
    }
  }
  JsonValue cart_json = run_json("stability '" + model_path("cart_pendulum") + "' --at x=5");
  const JsonValue& cart = *cart_json.find("equilibrium");
  EXPECT_EQ(at(cart, "x"), 5.0);
  EXPECT_NEAR(at(cart, "theta"), M_PI, 1e-14);
  Output none = eomgen("stability '" + model_path("double_pendulum") + "' --at phi1=0.5");
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.err.find("is not an equilibrium"), std::string::npos) << none.err;
  EXPECT_NE(none.err.find("with the named values held, Newton on phi2 found none either"), std::string::npos) << none.err;
}

// models/chaplygin_sleigh.toml starts turning (v = 0.2/T m/s, w = 2/T rad/s) and models/ball_joint_top.toml
// spinning (its ω (0.5, −1, 20)/T rad/s at g = 9.81/T²), T from 1e-12 to 1e12 s: Appell's equations
// hold the velocities as given, and with them the coordinates balance nothing. Without --at the
// analysis is at rest from the initial configuration, the equilibrium `--at w=0` (sleigh) and
// `--at wz=0` (top) name, and says so; it had ended in "no equilibrium found".
TEST(StabilityCommand, AModelMovingAtItsStartWithNoSteadyMotionThereIsAnalysedAtRest) {
  std::string top = read_file(model_path("ball_joint_top")), sleigh = read_file(model_path("chaplygin_sleigh"));
  for (double T : {1e-12, 1.0, 1e12}) {
    std::string turning = write_model("turning_sleigh", edited(sleigh, {{"rate = 0.2 }", fmt::format("rate = {:.17g} }}", 0.2 / T)},
                                                                        {"rate = 2.0 }", fmt::format("rate = {:.17g} }}", 2 / T)}}));
    std::string spinning = write_model("spinning_top", edited(top, {{"initial_angular_velocity = [0.5, -1, 20]",
                                                                     fmt::format("initial_angular_velocity = [{:.17g}, {:.17g}, "
                                                                                 "{:.17g}]", 0.5 / T, -1 / T, 20 / T)}}));
    std::string g = fmt::format(" --set g={:.17g}", 9.81 / (T * T));
    for (const auto& [model, at_rest] : {std::pair{turning, std::string(" --at w=0")}, std::pair{spinning, " --at wz=0" + g}}) {
      std::string given = model == spinning ? g : "";
      Output found = eomgen(fmt::format("stability '{}'{} --format json", model, given));
      ASSERT_EQ(found.status, 0) << model << ", T = " << T << ": " << found.err;
      EXPECT_NE(found.err.find(model == turning ? fmt::format("(v = {:.6g}, w = {:.6g}) make no steady motion", 0.2 / T, 2 / T)
                                                : std::string("make no steady motion")),
                std::string::npos)
          << found.err;
      EXPECT_NE(found.err.find("this is the equilibrium at rest from the initial configuration"), std::string::npos);
      Output named = eomgen(fmt::format("stability '{}'{} --format json", model, at_rest));
      ASSERT_EQ(named.status, 0) << named.err;
      Diagnostics diagnostics;
      std::optional<JsonValue> by_search = parse_json(found.out, "stability", diagnostics);
      std::optional<JsonValue> by_name = parse_json(named.out, "stability", diagnostics);
      ASSERT_TRUE(by_search && by_name) << found.out << named.out;
      const JsonValue& searched = *by_search->find("equilibrium");
      ASSERT_EQ(searched.members.size(), by_name->find("equilibrium")->members.size());
      for (const auto& [state, value] : searched.members)
        EXPECT_NEAR(value.value, at(*by_name->find("equilibrium"), state), 1e-9) << model << ", T = " << T << ": " << state;
      EXPECT_EQ(by_search->find("verdict")->text, by_name->find("verdict")->text);
    }
  }
}

}  // namespace
}  // namespace eomgen::test
