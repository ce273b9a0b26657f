// `eomgen stability` searching for the equilibrium or steady motion it analyses, and checking one
// given: where Newton's method from the model's initial values ends at a singularity of the
// coordinates, wanders, or meets a saturated force; on a constraint loop and a constraint manifold;
// with --at holding some states. Each at time scales from 1e-12 to 1e12 s where the search's
// tolerances could depend on them. Models in a first-order form (Appell, Hamilton) are searched in
// first_order_search_test.cpp, in the same suite.
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

// A mass m on a spring of 1 N/m hangs m g / k below z = 0, for m from 1e-12 to 1 kg: z = 0 is
// refused as its equilibrium and the search finds z = −m g / k. A tolerance with a floor of one
// metre had taken z = 0 for the equilibrium of 1e-12 kg (9.81e-12 m away); the forces it holds,
// m g at the model's default z = 0, now set the scale.
TEST(EquilibriumSearch, ALightHangingMassIsNotAtRestWhereItHangsFrom) {
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
    CommandOutput at_zero = run_eomgen("stability '" + model + "' --at z=0" + set);
    EXPECT_EQ(at_zero.status, 2) << "m = " << m << ": " << at_zero.out;
    EXPECT_NE(at_zero.err.find("is not an equilibrium"), std::string::npos) << at_zero.err;
    JsonValue found = run_json("stability '" + model + "'" + set);
    const JsonValue* equilibrium = found.find("equilibrium");
    ASSERT_TRUE(equilibrium) << "m = " << m;
    EXPECT_NEAR(at(*equilibrium, "z"), -m * 9.81, 1e-9 * m * 9.81) << "m = " << m;
  }
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
TEST(EquilibriumSearch, ASearchThatEndsAtASingularityOfTheCoordinatesTakesTheSteadyMotionThere) {
  for (double s : {1e-12, 1e-6, 1e-3, 1.0, 1e3, 1e6, 1e12}) {
    std::string model = spherical_pendulum_on_time_scale(s);
    CommandOutput r = run_eomgen("stability '" + model + "'");
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

// 21 hinges about oblique axes under gravity, started at angles of up to 0.2 rad: Newton's method from
// there goes round for 100 steps, and the path on which the start's forces are scaled down folds back
// (the tree snaps through). Where it comes to rest with damping added is an equilibrium, which the
// model simulated from it keeps, and asymptotically stable (the model has damping on every joint),
// which a disturbed start that the model brings back shows.
TEST(EquilibriumSearch, ATreeWhoseNewtonSearchWandersIsFoundWhereItComesToRest) {
  std::string model = std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/models/branched_tree.toml";
  CommandOutput r = run_eomgen("stability '" + model + "' --format json");
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
    CommandOutput run = run_eomgen("simulate '" + model + "'" + given + " --t-end " + std::to_string(t_end) + " --rtol 1e-10 -o '" +
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
// and tau_max in 1/T², kd in 1/T). Written for Appell or Hamilton, its pseudo-velocity or momentum
// is damped instead, and it comes to rest at the same φ; those forms had found no equilibrium.
TEST(EquilibriumSearch, ASaturatedServoIsFoundWhereItComesToRestAtEveryTimeScale) {
  const double kp = 20, m = 1.5, g = 9.81, s = 0.25, u = 0.5;
  double phi = 0.4;  // kp (u − φ) = m g s sin φ, by Newton's method
  for (int k = 0; k < 50; ++k) phi -= (kp * (u - phi) - m * g * s * std::sin(phi)) / (-kp - m * g * s * std::cos(phi));
  for (const std::string method : {"lagrange2", "appell", "hamilton"}) {
    std::string model = write_model("servo_pendulum_" + method, edited(read_file(model_path("servo_pendulum")),
                                                                        {{"[model]\n", "[model]\nmethod = \"" + method + "\"\n"}}));
    for (double T : {1e-12, 1.0, 1e12}) {
      std::string set = fmt::format(" --set u={} --set m={} --set s={} --set g={:.17g} --set kp={:.17g} --set kd={:.17g} "
                                    "--set tau_max={:.17g}", u, m, s, g / (T * T), kp / (T * T), 2.0 / T, 6.0 / (T * T));
      CommandOutput r = run_eomgen("stability '" + model + "'" + set + " --format json");
      ASSERT_EQ(r.status, 0) << method << ": " << r.err;
      EXPECT_NE(r.err.find("comes to rest"), std::string::npos) << r.err;
      Diagnostics diagnostics;
      std::optional<JsonValue> json = parse_json(r.out, "stability", diagnostics);
      ASSERT_TRUE(json) << r.out;
      EXPECT_NEAR(at(*json->find("equilibrium"), "phi"), phi, 1e-12) << method << ", T = " << T;
      EXPECT_EQ(json->find("verdict")->text, "asymptotically_stable") << method << ", T = " << T;
    }
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
TEST(EquilibriumSearch, ALagrangeOneEquilibriumIsSearchedAndCheckedOnItsConstraintsAtEveryScale) {
  for (auto [T, L] : {std::pair{1e-12, 1.0}, {1.0, 1.0}, {1e12, 1.0}, {1.0, 1e-12}, {1.0, 1e12}, {1e12, 1e12}}) {
    std::string where = fmt::format("T = {:g} s, L = {:g} m", T, L);
    std::string model = fmt::format("stability '{}' --set g={:.17g}", cartesian_pendulum_of_length(L), 9.81 * L / (T * T));
    CommandOutput released = run_eomgen(model + fmt::format(" --at x={:.17g} --at y={:.17g}", L * std::sin(0.5), -L * std::cos(0.5)));
    EXPECT_EQ(released.status, 2) << where;
    EXPECT_NE(released.err.find("is not an equilibrium: the largest residual of the equations of motion"), std::string::npos)
        << where << "\n" << released.err;
    CommandOutput off_the_rod = run_eomgen(model + fmt::format(" --at x=0 --at y={:.17g}", -1.1 * L));
    EXPECT_EQ(off_the_rod.status, 2) << where;
    EXPECT_NE(off_the_rod.err.find("does not meet the constraints: rod = "), std::string::npos)
        << where << "\n" << off_the_rod.err;
    EXPECT_EQ(run_eomgen(model + fmt::format(" --at x=0 --at y={:.17g}", -L)).status, 0) << where;
    CommandOutput searched = run_eomgen(model + " --format json");
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

// The four-bar's equilibrium found on its loop, checked against its potential written out here:
// V's gradient is normal to the loop there (no component along the loop's one tangent). Its links'
// lengths and g are set here; the masses (0.3, 0.6, 0.5) and the coupler's centre 0.01 off its
// axis are numbers in the file.
TEST(EquilibriumSearch, AFourBarsEquilibriumIsWhereItsPotentialIsStationaryOnItsLoop) {
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

// --at that names some states holds them and solves for the rest where the rest as given do not
// balance: a spherical pendulum held at θ0 turns at φ'² = g/(l cos θ0) (from the model's φ' = 2 s,
// at time scales s from 1e-12 to 1e12), and a pendulum on a cart held at x = 5 hangs upside down
// at θ = π, the nearest balance to its initial 3.0. Before, each was "not an equilibrium". A double
// pendulum held at φ1 = 0.5 has none, and says that the search with φ2 free found none either.
TEST(EquilibriumSearch, AnAtThatNamesSomeStatesSolvesForTheRest) {
  for (double s : {1e-12, 1e-6, 1.0, 1e6, 1e12}) {
    std::string model = spherical_pendulum_on_time_scale(s);
    for (double theta : {0.3, 0.8, 1.2}) {
      std::string given = fmt::format(" --at theta={}", theta);
      CommandOutput r = run_eomgen("stability '" + model + "'" + given);
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
  CommandOutput none = run_eomgen("stability '" + model_path("double_pendulum") + "' --at phi1=0.5");
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.err.find("is not an equilibrium"), std::string::npos) << none.err;
  EXPECT_NE(none.err.find("with the named values held, Newton on phi2 found none either"), std::string::npos) << none.err;
}

}  // namespace
}  // namespace eomgen::test
