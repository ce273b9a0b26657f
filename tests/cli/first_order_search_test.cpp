// `eomgen stability` searching for the steady motion of a model in a first-order form (Appell's
// pseudo-velocities, Hamilton's momenta, a ball joint's angular velocities;
// runtime/analyse/first_order_equilibrium.hpp): where the model starts moving with no steady motion
// there, where the search meets a singularity of the coordinates, and the same systems written for
// Lagrange II, Appell and Hamilton finding the same state, each at time scales from 1e-12 to 1e12 s.
// The suite is EquilibriumSearch's, whose other tests are in equilibrium_search_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "parse/json_reader.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

// models/chaplygin_sleigh.toml starts turning (v = 0.2/T m/s, w = 2/T rad/s) and models/ball_joint_top.toml
// spinning (its ω (0.5, −1, 20)/T rad/s at g = 9.81/T²), T from 1e-12 to 1e12 s: Appell's equations
// hold the velocities as given, and with them the coordinates balance nothing. Without --at the
// analysis is at rest from the initial configuration, the equilibrium `--at w=0` (sleigh) and
// `--at wz=0` (top) name, and says so; it had ended in "no equilibrium found".
TEST(EquilibriumSearch, AModelMovingAtItsStartWithNoSteadyMotionThereIsAnalysedAtRest) {
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
      CommandOutput found = run_eomgen(fmt::format("stability '{}'{} --format json", model, given));
      ASSERT_EQ(found.status, 0) << model << ", T = " << T << ": " << found.err;
      EXPECT_NE(found.err.find(model == turning ? fmt::format("the initial velocities (v = {:.6g}, w = {:.6g}) make no steady motion",
                                                              0.2 / T, 2 / T)
                                                : std::string(") held, found none")),
                std::string::npos)
          << found.err;
      EXPECT_NE(found.err.find("with the velocities solved for too found no steady motion; this is the equilibrium at rest "
                               "from the initial configuration"),
                std::string::npos)
          << found.err;
      CommandOutput named = run_eomgen(fmt::format("stability '{}'{} --format json", model, at_rest));
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

// A singularity of the coordinates written for Hamilton: the header's p' = f has the identity for
// M, but q' = M⁻¹ p, and at θ = 1e-20 of a spherical pendulum T's Hessian in p is 1e40 times its
// size: the coordinates' M is singular there, and Hamilton's form is refused as Lagrange II's is.
// Searched at rest, the crane hook's θ = 0 (its load hanging, ψ undefined) had been called unstable
// in Hamilton's form (a push "grew" 1.4e13-fold through the singularity) and refused in Lagrange II.
TEST(EquilibriumSearch, AHamiltonModelAtASingularityOfItsCoordinatesIsRefusedAsItsLagrangeTwin) {
  for (const char* name : {"spherical_pendulum", "spherical_pendulum_hamilton"}) {
    bool hamilton = std::string(name).find("hamilton") != std::string::npos;
    CommandOutput r = run_eomgen(fmt::format("stability '{}' --at theta=1e-20 --at {}=0 --at {}=0", model_path(name),
                                             hamilton ? "p_theta" : "'der(theta)'", hamilton ? "p_phi" : "'der(phi)'"));
    EXPECT_EQ(r.status, 3) << name << ": " << r.out;
    EXPECT_NE(r.err.find("the mass matrix is singular at theta = 1e-20"), std::string::npos) << name << ": " << r.err;
  }
  std::string crane = read_file(model_path("crane_hook_tree"));
  for (const char* method : {"lagrange2", "hamilton"}) {
    std::string model = write_model(std::string("crane_hook_tree_") + method,
                                    edited(crane, {{"[model]\n", std::string("[model]\nmethod = \"") + method + "\"\n"}}));
    CommandOutput r = run_eomgen(fmt::format("stability '{}'", model));
    EXPECT_EQ(r.status, 3) << method << ": " << r.out;
    EXPECT_NE(r.err.find("no stability analysis at the equilibrium found: the mass matrix is singular at theta = "),
              std::string::npos) << method << ": " << r.err;
  }
}

// The heavy top written for Appell, its spin of 100 rad/s held: Newton's method from θ = 0.3 steps
// onto θ = 0, where its Euler angles are singular. The message had read "largest residual nan"; it
// now names the state and why its equations are not finite there. The search then solves for the
// velocities too and finds the steady precession that Lagrange II's search finds (it had stopped
// with "no equilibrium found").
TEST(EquilibriumSearch, ASearchThatStepsWhereItsEquationsAreNotFiniteSaysWhere) {
  std::string lagrange = read_file(model_path("heavy_symmetric_top"));
  std::string model = write_model("heavy_symmetric_top_appell", edited(lagrange, {{"[model]\n", "[model]\nmethod = \"appell\"\n"}}));
  CommandOutput r = run_eomgen(fmt::format("stability '{}'", model));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("its last step reached a state where the equations of motion are not finite: the mass matrix is "
                       "singular at"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("this is the steady motion nearest the initial state, its velocities solved for"), std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("nan"), std::string::npos) << r.err;
  JsonValue appell = run_json(fmt::format("stability '{}'", model));
  JsonValue lagrange_two = run_json(fmt::format("stability '{}'", model_path("heavy_symmetric_top")));
  const JsonValue &found = *appell.find("equilibrium"), &expected = *lagrange_two.find("equilibrium");
  for (const char* state : {"theta", "der(psi)", "der(phi)"})
    EXPECT_NEAR(at(found, state) / at(expected, state), 1, 1e-9) << state;
  EXPECT_EQ(appell.find("verdict")->text, lagrange_two.find("verdict")->text);
}

// models/watt_governor.toml written for `method` on time scale T (g, the torques κ and P over T², the
// arms' friction b and the engine's initial speed over T)
std::string governor(const std::string& method, double T) {
  std::string text = edited(read_file(model_path("watt_governor")),
                            {{"[model]\n", "[model]\nmethod = \"" + method + "\"\n"},
                             {"b     = 0.8", fmt::format("b = {:.17g}", 0.8 / T)},
                             {"kappa = 10.0", fmt::format("kappa = {:.17g}", 10 / (T * T))},
                             {"P     = 8.660254037844386", fmt::format("P = {:.17g}", 8.660254037844386 / (T * T))},
                             {"g     = 9.81", fmt::format("g = {:.17g}", 9.81 / (T * T))},
                             {"rate = 3.3658", fmt::format("rate = {:.17g}", 3.3658 / T)}});
  return write_model(fmt::format("watt_governor_{}_{:g}", method, T), text);
}

// Appell's and Hamilton's forms hold the initial velocities while Newton moves the coordinates, and
// then searched rest only. The Watt governor's engine speed is given to five digits (3.3658 rad/s,
// the steady speed is 3.36565…), so its arms balance at no angle, and both forms stopped with "no
// equilibrium found" where Lagrange II's search, which solves for the cyclic speed, finds the
// steady run. Now the velocities are solved for too, and at time scales from 1e-12 to 1e12 s both
// find it (Hiller §7.6): κ cos θ = P, n² φ'² l cos θ = g, in Hamilton's form p_φ = (J + 2 m n² l²
// sin² θ) φ', and call it asymptotically stable as Lagrange II does.
TEST(EquilibriumSearch, AppellsAndHamiltonsFormsFindAGovernorsSteadyRunAtEveryTimeScale) {
  const double m = 1, l = 0.25, n = 2, J = 0.5, kappa = 10, P = 8.660254037844386, g = 9.81;
  const double theta = std::acos(P / kappa), speed = std::sqrt(g / (n * n * l * std::cos(theta)));
  for (const std::string method : {"appell", "hamilton"}) {
    for (double T : {1e-12, 1e-6, 1.0, 1e6, 1e12}) {
      CommandOutput r = run_eomgen(fmt::format("stability '{}' --format json", governor(method, T)));
      ASSERT_EQ(r.status, 0) << method << ", T = " << T << ": " << r.err;
      EXPECT_NE(r.err.find("this is the steady motion nearest the initial state"), std::string::npos) << r.err;
      Diagnostics diagnostics;
      std::optional<JsonValue> json = parse_json(r.out, "stability", diagnostics);
      ASSERT_TRUE(json) << r.out;
      const JsonValue& steady = *json->find("equilibrium");
      EXPECT_NEAR(at(steady, "theta"), theta, 1e-12) << method << ", T = " << T;
      if (method == "appell") {
        EXPECT_NEAR(at(steady, "der(phi)") * T / speed, 1, 1e-12) << "T = " << T;
      } else {
        double momentum = (J + 2 * m * n * n * l * l * std::sin(theta) * std::sin(theta)) * speed / T;
        EXPECT_NEAR(at(steady, "p_phi") / momentum, 1, 1e-12) << "T = " << T;
      }
      EXPECT_EQ(json->find("verdict")->text, "asymptotically_stable") << method << ", T = " << T;
    }
  }
}

// models/free_rigid_body.toml (Cardan angles 0, rates α' = 1, γ' = 2 over T) written for each form:
// Lagrange II's search holds the non-cyclic rates at zero and finds the spin about the first axis,
// α' = 1/T, stable. Appell's and Hamilton's had held the velocities and then taken rest, unstable
// (a body at rest drifts); Newton on all three velocities from the start went to rest too. They now
// start from the velocities that make the non-cyclic coordinates stand still, the cyclic one
// moving as at the start (Hamilton: p_α = A α'), and find the same spin at every time scale.
TEST(EquilibriumSearch, AFreeBodyInEveryFormSpinsAsLagrangesSearchFindsIt) {
  const double A = 1;
  for (const std::string method : {"lagrange2", "appell", "hamilton"}) {
    for (double T : {1e-12, 1.0, 1e12}) {
      std::string model = write_model(fmt::format("free_rigid_body_{}_{:g}", method, T),
                                      edited(read_file(model_path("free_rigid_body")),
                                             {{"[model]\n", "[model]\nmethod = \"" + method + "\"\n"},
                                              {"rate = 1.0", fmt::format("rate = {:.17g}", 1 / T)},
                                              {"rate = 2.0", fmt::format("rate = {:.17g}", 2 / T)}}));
      JsonValue r = run_json(fmt::format("stability '{}'", model));
      const JsonValue& found = field(r, "equilibrium");
      EXPECT_EQ(at(found, "beta"), 0) << method << ", T = " << T;
      EXPECT_EQ(at(found, "gamma"), 0) << method << ", T = " << T;
      if (method == "hamilton") EXPECT_NEAR(at(found, "p_alpha") * T / A, 1, 1e-12) << "T = " << T;
      else EXPECT_NEAR(at(found, "der(alpha)") * T, 1, 1e-12) << method << ", T = " << T;
      EXPECT_EQ(field(r, "verdict").text, "marginally_stable") << method << ", T = " << T;
      EXPECT_EQ(field(field(r, "critical_case"), "nonlinear_verdict").text, "stable") << method << ", T = " << T;
    }
  }
}

// The spherical pendulum written for Appell, released at θ = 0.8 turning at φ' = 2 s (time scale s):
// Newton with φ' held slides to θ = 0 (singular), and so does the search with the velocities free.
// As in Lagrange II's search, the steady motion at θ = 0.8 is then taken, the velocities alone solved
// for: the conical motion φ'² = g/(l cos θ), stable. It had been refused at θ = 0 (singular).
TEST(EquilibriumSearch, AnAppellSearchThatEndsAtASingularityTakesTheSteadyMotionAtItsStart) {
  for (double s : {1e-12, 1.0, 1e12}) {
    std::string model = write_model("spherical_pendulum_appell",
                                    edited(read_file(model_path("spherical_pendulum")),
                                           {{"[model]\n", "[model]\nmethod = \"appell\"\n"},
                                            {"g = 9.81", fmt::format("g = {:.17g}", 9.81 * s * s)},
                                            {"rate = 2.0", fmt::format("rate = {:.17g}", 2 * s)}}));
    CommandOutput r = run_eomgen("stability '" + model + "'");
    ASSERT_EQ(r.status, 0) << "s = " << s << ": " << r.err;
    EXPECT_NE(r.err.find("this is the steady motion at the initial configuration, its velocities alone solved for"),
              std::string::npos) << r.err;
    EXPECT_NE(r.out.find("nonlinear verdict: stable"), std::string::npos) << r.out;
    JsonValue json = run_json("stability '" + model + "'");
    const JsonValue& equilibrium = *json.find("equilibrium");
    EXPECT_EQ(at(equilibrium, "theta"), 0.8) << "s = " << s;
    EXPECT_NEAR(at(equilibrium, "der(phi)") / (s * std::sqrt(9.81 / std::cos(0.8))), 1, 1e-12) << "s = " << s;
    EXPECT_EQ(at(equilibrium, "der(theta)"), 0) << "s = " << s;
  }
}

}  // namespace
}  // namespace eomgen::test
