// Models whose coordinates are angles beside lengths, at lengths of 1e-12 m to 1e12 m: the verdicts
// and the equilibria found are the same at every scale. Each angle counts in radians and each length
// in the configuration's size (derive/angle_coordinates.hpp, integrate/coordinate_sizes.hpp); with
// one size for both, a spring pendulum of 1e12 m at 0.5 rad had passed for an equilibrium (its
// torque against its stiffness times 1e12 m), one of 1e-12 m too, and a slider-crank of 1e-13 m
// could not be started (its angles' columns of the constraint Jacobian, r = 1e-13 m, taken for zero).
#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>

#include "parse/json_reader.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

// a bob of 1 kg on a spring of rest length L, stiffness 100/T² N/m, under g = 9.81 L/T²: it hangs at
// r = L (1 + 0.0981), and swings at √(k/m) = 10/T along the spring and √(g/r) across it
std::string spring_pendulum(double L, double T) {
  return write_model(fmt::format("spring_pendulum_{:g}_{:g}", L, T), fmt::format(R"toml([model]
name = "spring_pendulum"
[parameters]
m = 1.0
k = {:.17g}
l0 = {:.17g}
g = {:.17g}
[coordinates]
r = {{ initial = {:.17g}, rate = 0.0 }}
theta = {{ initial = 0.3, rate = 0.0 }}
[[particles]]
name = "bob"
mass = "m"
position = ["r*sin(theta)", "-r*cos(theta)", "0"]
[gravity]
acceleration = ["0", "-g", "0"]
[energy]
potential = "k*(r - l0)^2/2"
)toml",
                                                                                 100 / (T * T), L, 9.81 * L / (T * T), 1.1 * L));
}

TEST(AnglesBesideLengths, ASpringPendulumsEquilibriumAndVerdictAreTheSameAtEveryScale) {
  for (auto [L, T] : {std::pair{1e-12, 1.0}, {1.0, 1.0}, {1e12, 1.0}, {1e12, 1e-12}, {1e-12, 1e12}}) {
    std::string where = fmt::format("L = {:g} m, T = {:g} s", L, T), model = spring_pendulum(L, T);
    CommandOutput swung = run_eomgen(fmt::format("stability '{}' --at theta=0.5 --at r={:.17g}", model, 1.1 * L));
    EXPECT_EQ(swung.status, 2) << where << "\n" << swung.out;
    EXPECT_NE(swung.err.find("is not an equilibrium"), std::string::npos) << where << "\n" << swung.err;
    JsonValue json = run_json(fmt::format("stability '{}'", model));
    const JsonValue& equilibrium = *json.find("equilibrium");
    EXPECT_NEAR(at(equilibrium, "r") / L, 1.0981, 1e-12) << where;
    EXPECT_NEAR(at(equilibrium, "theta"), 0, 1e-12) << where;
    EXPECT_EQ(json.find("verdict")->text, "marginally_stable") << where;
    std::vector<double> rates;
    for (const JsonValue& e : json.find("eigenvalues")->items) rates.push_back(std::abs(e.items.at(1).value) * T);
    std::sort(rates.begin(), rates.end());
    ASSERT_EQ(rates.size(), 4u) << where;
    EXPECT_NEAR(rates[0] / std::sqrt(9.81 / 1.0981), 1, 1e-9) << where;
    EXPECT_NEAR(rates[3] / 10, 1, 1e-9) << where;
    EXPECT_EQ(json.find("critical_case")->find("nonlinear_verdict")->text, "stable") << where;
  }
}

// models/slider_crank.toml with its lengths, g and slider position scaled by L (the time scale kept)
std::string slider_crank_of_size(double L) {
  std::string text = edited(read_file(model_path("slider_crank")),
                            {{"r  = 0.1 ", fmt::format("r  = {:.17g} ", 0.1 * L)},
                             {"l  = 0.3 ", fmt::format("l  = {:.17g} ", 0.3 * L)},
                             {"g  = 9.81", fmt::format("g  = {:.17g}", 9.81 * L)},
                             {"initial = 0.375,", fmt::format("initial = {:.17g},", 0.375 * L)}});
  return write_model(fmt::format("slider_crank_{:g}", L), text);
}

// The crank's angle and the slider's position move alike at every length: the same φ(1 s) and
// x(1 s)/L, the constraints met, the equilibrium with the crank upright at the same eigenvalues, and
// a crank at 0.5 rad on its loop refused
TEST(AnglesBesideLengths, ASliderCrankMovesAndBalancesAlikeAtEveryLength) {
  std::vector<double> phi, x;
  for (double L : {1.0, 1e-12, 1e12}) {
    std::string where = fmt::format("L = {:g} m", L), model = slider_crank_of_size(L);
    std::string dir = temporary_directory();
    CommandOutput run = run_eomgen(fmt::format("simulate '{}' --t-end 1 --rtol 1e-10 -o '{}/run.csv'", model, dir));
    ASSERT_EQ(run.status, 0) << where << "\n" << run.err;
    std::vector<std::vector<double>> rows = read_numeric_csv(dir + "/run.csv");  // t, phi, beta, x, …
    ASSERT_FALSE(rows.empty()) << where;
    phi.push_back(rows.back().at(1)), x.push_back(rows.back().at(3) / L);
    JsonValue json = run_json(fmt::format("stability '{}'", model));
    const JsonValue& equilibrium = *json.find("equilibrium");
    EXPECT_NEAR(at(equilibrium, "phi"), M_PI / 2, 1e-9) << where;
    EXPECT_NEAR(at(equilibrium, "x") / L, std::sqrt(0.3 * 0.3 - 0.1 * 0.1), 1e-9) << where;
    EXPECT_EQ(json.find("verdict")->text, "unstable") << where;
    double beta = std::asin(-0.1 * std::sin(0.5) / 0.3), at_beta = 0.1 * std::cos(0.5) + 0.3 * std::cos(beta);
    CommandOutput on_loop =
        run_eomgen(fmt::format("stability '{}' --at phi=0.5 --at beta={:.17g} --at x={:.17g}", model, beta, at_beta * L));
    EXPECT_EQ(on_loop.status, 2) << where << "\n" << on_loop.out;
    EXPECT_NE(on_loop.err.find("is not an equilibrium"), std::string::npos) << where << "\n" << on_loop.err;
  }
  for (std::size_t k = 1; k < phi.size(); ++k) {
    EXPECT_NEAR(phi[k] / phi[0], 1, 1e-7) << k;
    EXPECT_NEAR(x[k] / x[0], 1, 1e-7) << k;
  }
}

}  // namespace
}  // namespace eomgen::test
