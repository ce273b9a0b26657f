// `eomgen scene` against an independent reference: the pendulum's scenes, whose chosen
// trajectory (chosen.csv) is compared with φ'' = −(g/l) sin φ integrated here by RK4 at a
// step of 1e-4 s; the small swing picks the linear model, the large one must not; the
// choice is the same in two runs; a scene no candidate can meet exits 3 naming the closest;
// scene and variant mistakes are located.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <optional>

#include "support/small_models.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

// the states at the given times of x' = f(t, x) from x(0) = x0, by RK4 at the step h
template <std::size_t N, class F>
std::vector<std::array<double, N>> rk4_at(const F& f, std::array<double, N> x, double h, const std::vector<double>& times) {
  using State = std::array<double, N>;
  auto axpy = [](const State& y, double a, const State& d) {
    State z;
    for (std::size_t i = 0; i < N; ++i) z[i] = y[i] + a * d[i];
    return z;
  };
  double t = 0;
  std::vector<State> out;
  for (double target : times) {
    while (t < target - 1e-12) {
      double step = std::min(h, target - t);
      State k1 = f(t, x), k2 = f(t + step / 2, axpy(x, step / 2, k1)), k3 = f(t + step / 2, axpy(x, step / 2, k2)),
            k4 = f(t + step, axpy(x, step, k3));
      for (std::size_t i = 0; i < N; ++i) x[i] += step / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
      t += step;
    }
    out.push_back(x);
  }
  return out;
}

// φ(t) of the undamped pendulum (g = 9.81, l = 1) from φ(0) = phi0 at rest, at the given times
std::vector<double> pendulum_by_rk4(double phi0, const std::vector<double>& times) {
  using State = std::array<double, 2>;
  auto f = [](double, const State& x) { return State{x[1], -9.81 * std::sin(x[0])}; };
  std::vector<double> out;
  for (const State& x : rk4_at(f, State{phi0, 0}, 1e-4, times)) out.push_back(x[0]);
  return out;
}

struct Choice {
  std::string model, integrator, setting;
  double error = NAN;
};

Choice run_scene(const std::string& path, const std::string& scene, const std::string& dir) {
  JsonValue json = run_json("scene '" + path + "' " + scene + " -o '" + dir + "'");
  const JsonValue* chosen = json.find("chosen");
  if (!chosen || !chosen->find("model")) return {};
  return {chosen->find("model")->text, chosen->find("integrator")->text, chosen->find("setting")->text, at(*chosen, "error")};
}

// the chosen run's φ against the independent reference, relative to the reference's range
double chosen_error(const std::string& dir, double phi0) {
  auto rows = read_numeric_csv(dir + "/chosen.csv");
  std::vector<double> times;
  for (const auto& row : rows) times.push_back(row[0]);
  std::vector<double> reference = pendulum_by_rk4(phi0, times);
  auto [low, high] = std::minmax_element(reference.begin(), reference.end());
  double error = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) error = std::max(error, std::abs(rows[i][1] - reference[i]));
  return error / (*high - *low);
}

TEST(SceneCommand, SmallSwingPicksTheLinearModelAndMeetsTheAccuracy) {
  std::string dir = temporary_directory() + "/small";
  Choice c = run_scene(model_path("pendulum"), "small_swing", dir);
  EXPECT_EQ(c.model, "linear");
  double error = chosen_error(dir, 0.05);
  EXPECT_LE(error, 1e-2) << "the scene's accuracy";
  EXPECT_NEAR(error, c.error, 1e-4) << "the error eomgen measured against its own reference";
  for (const char* file : {"/report.md", "/candidates.csv", "/chosen.csv", "/pendulum_linear.hpp", "/error_vs_work.png"})
    EXPECT_GT(read_file(dir + file).size(), 100u) << file;
  Choice again = run_scene(model_path("pendulum"), "small_swing", dir + "2");
  EXPECT_EQ(again.model + again.integrator + again.setting, c.model + c.integrator + c.setting) << "the choice is stable";
}

// A lightly damped mass on a spring (linear: every amplitude is the same motion, scaled), its swing
// from x0 = A for A from 1e-12 to 1e12 m: the same model, integrator and setting are chosen, and
// within the scene's accuracy against x0 e^(-ζωt) (cos ω_d t + ζω/ω_d sin ω_d t). With
// absolute tolerances of rtol/100 m in every unit, the small swings had needed tighter settings
// (a 5e-10 rad swing of the pendulum rtol 1e-9 where 0.05 rad took 1e-5), and at 1e-12 m none
// met the accuracy.
TEST(SceneCommand, ALinearSwingsChoiceDoesNotDependOnItsAmplitude) {
  const double m = 1, k = 4, d = 0.2, omega = 2, zeta = d / (2 * std::sqrt(k * m)), damped = omega * std::sqrt(1 - zeta * zeta);
  std::optional<Choice> first;
  for (double A : {1e-12, 1e-6, 1.0, 1e6, 1e12}) {
    std::string text = particle_on_a_line_model("swing", "m = 1.0\nk = 4.0\nd = 0.2\n",
                                                "potential = \"k*x^2/2\"\ndissipation = \"d*der(x)^2/2\"\n", A) +
                       fmt::format("[scenes.swing]\nt_end = 10.0\ndt_out = 0.05\ninitial = {{ x = {:.17g} }}\noutputs = [\"x\"]\n"
                                   "accuracy = 1e-3\n", A);
    std::string dir = temporary_directory() + "/swing";
    Choice c = run_scene(write_model("swing", text), "swing", dir);
    ASSERT_FALSE(c.model.empty()) << "A = " << A;
    if (!first) first = c;
    EXPECT_EQ(c.model + " " + c.integrator + " " + c.setting, first->model + " " + first->integrator + " " + first->setting)
        << "A = " << A;
    double worst = 0;
    for (const auto& row : read_numeric_csv(dir + "/chosen.csv")) {
      double t = row[0], x = A * std::exp(-zeta * omega * t) * (std::cos(damped * t) + zeta * omega / damped * std::sin(damped * t));
      worst = std::max(worst, std::abs(row[1] - x));
    }
    EXPECT_LE(worst, 1e-3 * 2 * A) << "A = " << A << ": the scene's accuracy of its range (under 2 A)";
  }
}

TEST(SceneCommand, LargeSwingDoesNotPickTheLinearModel) {
  std::string dir = temporary_directory() + "/large";
  Choice c = run_scene(model_path("pendulum"), "large_swing", dir);
  EXPECT_NE(c.model, "linear");
  EXPECT_NE(c.model, "variant:small_angle");
  EXPECT_LE(chosen_error(dir, 2.0), 1e-2);
}

// φ1(t) of the double pendulum (l1 = l2 = 1, m1 = 1, g = 9.81) from φ1(0) = phi1 at rest, φ2(0) = 0, by RK4 at 1e-4 s,
// from the textbook form of its equations (independent of eomgen's derivation)
std::vector<double> double_pendulum_by_rk4(double phi1, double m2, const std::vector<double>& times) {
  const double g = 9.81, m1 = 1;
  using State = std::array<double, 4>;  // φ1, φ2, φ1', φ2'
  auto f = [&](double, const State& x) {
    double d = x[0] - x[1], den = 2 * m1 + m2 - m2 * std::cos(2 * d);
    double a1 = (-g * (2 * m1 + m2) * std::sin(x[0]) - m2 * g * std::sin(x[0] - 2 * x[1]) -
                 2 * std::sin(d) * m2 * (x[3] * x[3] + x[2] * x[2] * std::cos(d))) / den;
    double a2 = 2 * std::sin(d) * (x[2] * x[2] * (m1 + m2) + g * (m1 + m2) * std::cos(x[0]) + x[3] * x[3] * m2 * std::cos(d)) / den;
    return State{x[2], x[3], a1, a2};
  };
  std::vector<double> out;
  for (const State& x : rk4_at(f, State{phi1, 0, 0, 0}, 1e-4, times)) out.push_back(x[0]);
  return out;
}

TEST(SceneCommand, ALightSecondBobIsDroppedForAQuestionAboutTheFirstAngle) {
  std::string dir = temporary_directory() + "/first_angle";
  Choice c = run_scene(model_path("double_pendulum"), "first_angle", dir);
  EXPECT_EQ(c.model, "variant:light_bob");
  auto rows = read_numeric_csv(dir + "/chosen.csv");
  std::vector<double> times;
  for (const auto& row : rows) times.push_back(row[0]);
  std::vector<double> reference = double_pendulum_by_rk4(1.0, 0.001, times);
  auto [low, high] = std::minmax_element(reference.begin(), reference.end());
  double error = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) error = std::max(error, std::abs(rows[i][1] - reference[i]));
  EXPECT_LE(error / (*high - *low), 1e-2) << "the scene's accuracy, against the full model computed here";
  // the variant alone: m2 neglected leaves phi2 undetermined, so it is dropped with the tip outputs
  CommandOutput variant = run_eomgen("derive '" + model_path("double_pendulum") + "' --variant light_bob");
  EXPECT_EQ(variant.status, 0) << variant.err;
  EXPECT_NE(variant.out.find("coordinates: phi1\n"), std::string::npos) << variant.out;
  EXPECT_NE(variant.out.find("f[0] = -g*l1*m1*sin(phi1) + tau"), std::string::npos) << variant.out;
}

// x1, x2 of the stiff chain (m = k = 1, K = 1e8, c = 2e4, x1(0) = 0.1) by RK4 at 2e-5 s, below the
// explicit stability limit of its fast decay (about 2.8 / 3.4e4 s)
std::vector<std::array<double, 2>> stiff_chain_by_rk4(const std::vector<double>& times) {
  const double k = 1, K = 1e8, c = 2e4;
  using State = std::array<double, 6>;
  auto f = [&](double, const State& x) {
    double stretch = x[2] - x[1], rate = x[5] - x[4];
    return State{x[3], x[4], x[5], -k * x[0] + k * (x[1] - x[0]),
                 -k * (x[1] - x[0]) + (k + K) * stretch + c * rate, -(k + K) * stretch - c * rate};
  };
  std::vector<std::array<double, 2>> out;
  for (const State& x : rk4_at(f, State{0.1, 0, 0, 0, 0, 0}, 2e-5, times)) out.push_back({x[0], x[1]});
  return out;
}

TEST(SceneCommand, TheStiffLinkMadeRigidAnswersTheSlowSwing) {
  std::string dir = temporary_directory() + "/slow_swing";
  Choice c = run_scene(model_path("stiff_chain"), "slow_swing", dir);
  EXPECT_EQ(c.model, "variant:rigid_link");
  auto rows = read_numeric_csv(dir + "/chosen.csv");
  std::vector<double> times;
  for (const auto& row : rows) times.push_back(row[0]);
  auto reference = stiff_chain_by_rk4(times);
  for (int k = 0; k < 2; ++k) {
    double low = INFINITY, high = -INFINITY, error = 0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      low = std::min(low, reference[i][k]), high = std::max(high, reference[i][k]);
      error = std::max(error, std::abs(rows[i][1 + k] - reference[i][k]));
    }
    EXPECT_LE(error / (high - low), 1e-2) << "x" << k + 1 << " against the stiff chain integrated here";
  }
  CommandOutput rigid = run_eomgen("derive '" + model_path("stiff_chain") + "' --variant rigid_link");
  EXPECT_NE(rigid.out.find("coordinates: x1, x2\n"), std::string::npos) << rigid.out;
  EXPECT_NE(rigid.out.find("M[1][1] = 2*m"), std::string::npos) << "masses 2 and 3 move as one\n" << rigid.out;
}

// the car's parameters (models/car_braking.toml) and the scenes' braking force, built up over 0.15 s
struct Car {
  double m = 1500, Iyy = 2400, a = 1.2, b = 1.5, h = 0.55, kf = 40000, kr = 44000, cf = 4000, cr = 4400, cw = 0.4;
  double force(double t) const { return -0.8 * m * 9.81 * (1 - std::exp(-t / 0.15)); }
};

// the car by RK4 at 1e-4 s from Newton's and Euler's laws written here: m x'' = F − cw x'², and the
// body's heave and pitch on its springs and dampers (forces at the axles, the brake's moment −h F)
std::vector<std::array<double, 3>> car_by_rk4(const std::vector<double>& times) {
  Car c;
  using State = std::array<double, 6>;  // x, z, θ, x', z', θ'
  auto f = [&](double t, const State& s) {
    double front = c.kf * (s[1] - c.a * std::sin(s[2])) + c.cf * (s[4] - c.a * std::cos(s[2]) * s[5]);
    double rear = c.kr * (s[1] + c.b * std::sin(s[2])) + c.cr * (s[4] + c.b * std::cos(s[2]) * s[5]);
    double F = c.force(t);
    return State{s[3], s[4], s[5], (F - c.cw * s[3] * s[3]) / c.m, -(front + rear) / c.m,
                 (c.a * std::cos(s[2]) * front - c.b * std::cos(s[2]) * rear - c.h * F) / c.Iyy};
  };
  std::vector<std::array<double, 3>> out;
  for (const State& x : rk4_at(f, State{0, 0, 0, 20, 0, 0}, 1e-4, times))
    out.push_back({x[0], x[2], x[1] - c.a * std::sin(x[2])});  // x, θ, front travel
  return out;
}

// the largest error of column `column` of chosen.csv against reference[.][k], relative to the reference's range
double relative_error(const std::vector<std::vector<double>>& rows, std::size_t column,
                      const std::vector<std::array<double, 3>>& reference, std::size_t k) {
  double low = INFINITY, high = -INFINITY, error = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    low = std::min(low, reference[i][k]), high = std::max(high, reference[i][k]);
    error = std::max(error, std::abs(rows[i][column] - reference[i][k]));
  }
  return error / (high - low);
}

TEST(SceneCommand, TheStoppingDistanceIsAPointMassQuestion) {
  std::string dir = temporary_directory() + "/stopping";
  Choice c = run_scene(model_path("car_braking"), "stopping", dir);
  EXPECT_EQ(c.model, "reduced") << "heave and pitch dropped: they do not act back on x";
  std::string header;
  auto rows = read_numeric_csv(dir + "/chosen.csv", &header);
  ASSERT_EQ(header, "t,x,der(x)");
  std::vector<double> times;
  for (const auto& row : rows) times.push_back(row[0]);
  EXPECT_LE(relative_error(rows, 1, car_by_rk4(times), 0), 1e-3) << "the scene's accuracy on x";
  std::string report = read_file(dir + "/report.md");
  EXPECT_NE(report.find("dropped, as they do not feed back into the outputs: z, theta"), std::string::npos) << report;
}

TEST(SceneCommand, TheNoseDiveIsTheLinearBodyInTheModesTheStopExcites) {
  std::string dir = temporary_directory() + "/nose_dive";
  Choice c = run_scene(model_path("car_braking"), "nose_dive", dir);
  EXPECT_EQ(c.model, "reduced:modal") << "heave and pitch, linear, without the rigid-body motion along the road";
  auto rows = read_numeric_csv(dir + "/chosen.csv");
  std::vector<double> times;
  for (const auto& row : rows) times.push_back(row[0]);
  auto reference = car_by_rk4(times);
  EXPECT_LE(relative_error(rows, 1, reference, 1), 1e-2) << "theta";
  EXPECT_LE(relative_error(rows, 2, reference, 2), 1e-2) << "front_travel";
  std::string report = read_file(dir + "/report.md");
  EXPECT_NE(report.find("the linear model in 2 of its 3 modes"), std::string::npos) << report;
  std::string chosen = read_file(dir + "/car_braking_linear_modal.hpp");
  EXPECT_NE(chosen.find("inline constexpr std::array<const char*, num_coordinates> coordinate_names{{\"eta2\", \"eta3\"}}"),
            std::string::npos);
}

std::string pendulum_with(const std::string& extra) {
  std::string path = temporary_directory() + "/pendulum.toml";
  std::ofstream(path) << read_file(model_path("pendulum")) << extra;
  return path;
}

TEST(SceneCommand, AnUnreachableAccuracyExitsThreeNamingTheClosest) {
  std::string path = pendulum_with("\n[scenes.impossible]\nt_end = 2.0\ninitial = { phi = 1.0 }\naccuracy = 1e-15\n");
  CommandOutput r = run_eomgen("scene '" + path + "' impossible");
  EXPECT_EQ(r.status, 3) << r.err;
  // the full model and the pruned one (the same but for the damping term, zero here) come closest
  std::size_t closest = r.out.find("no candidate reaches the accuracy; closest: ");
  ASSERT_NE(closest, std::string::npos) << r.out;
  std::string named = r.out.substr(closest + 44, 12);
  EXPECT_TRUE(named.rfind("full model", 0) == 0 || named.rfind("pruned model", 0) == 0) << r.out;
}

TEST(SceneCommand, MistakesInScenesAndVariantsAreLocated) {
  // the file's structure first (parse), then the names (model), as for the rest of the file
  CommandOutput negative = run_eomgen("derive '" + pendulum_with("\n[scenes.typo]\nt_end = -1.0\n") + "'");
  EXPECT_EQ(negative.status, 2);
  EXPECT_NE(negative.err.find("scenes.typo.t_end: t_end must be positive"), std::string::npos) << negative.err;
  std::string path = pendulum_with("\n[scenes.typo]\noutputs = [\"ph\"]\ninputs = { tau = \"t\" }\n"
                                   "[variants.bad]\nneglect = [\"mm\"]\nsmall_angle = { phi = \"cubic\" }\n");
  CommandOutput r = run_eomgen("derive '" + path + "'");
  EXPECT_EQ(r.status, 2);
  for (const char* message : {"'ph' is not an output, a coordinate or a velocity", "did you mean 'phi'",
                              "'tau' is not an input", "'mm' is not a parameter", "unknown small-angle form 'cubic'"})
    EXPECT_NE(r.err.find(message), std::string::npos) << message << "\n" << r.err;
  CommandOutput tie = run_eomgen("derive '" + model_path("stiff_chain") + "' --variant rigid_link");
  ASSERT_EQ(tie.status, 0) << tie.err;
  std::string chain = temporary_directory() + "/chain.toml";
  std::ofstream(chain) << read_file(model_path("stiff_chain")) << "[variants.loop]\ntie = { x2 = \"x2 + x1\", x4 = \"x1\" }\n";
  CommandOutput ties = run_eomgen("derive '" + chain + "'");
  EXPECT_EQ(ties.status, 2);
  for (const char* message : {"x2 is tied to an expression of itself", "'x4' is not a coordinate"})
    EXPECT_NE(ties.err.find(message), std::string::npos) << message << "\n" << ties.err;
  CommandOutput unknown = run_eomgen("simulate '" + model_path("pendulum") + "' --scene small_swig");
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.err.find("the model has no scenes 'small_swig'"), std::string::npos) << unknown.err;
}

TEST(SceneCommand, VariantsAndScenesDeriveAndSimulate) {
  CommandOutput variant = run_eomgen("derive '" + model_path("pendulum") + "' --variant small_angle");
  EXPECT_EQ(variant.status, 0) << variant.err;
  EXPECT_NE(variant.out.find("model: pendulum_small_angle"), std::string::npos);
  EXPECT_NE(variant.out.find("f[0] = -d*der(phi) - g*l*m*phi - l^2*m*phi*der(phi)^2"), std::string::npos)
      << "sin(phi) -> phi, cos(phi) -> 1 - phi^2/2 in the position, then Lagrange's equations\n" << variant.out;
  std::string csv = temporary_directory() + "/scene.csv";
  CommandOutput scene = run_eomgen("simulate '" + model_path("pendulum") + "' --scene large_swing -o '" + csv + "'");
  EXPECT_EQ(scene.status, 0) << scene.err;
  auto rows = read_numeric_csv(csv);
  ASSERT_EQ(rows.size(), 201u) << "t_end 10 at dt_out 0.05";
  EXPECT_EQ(rows[0][1], 2.0) << "the scene's initial angle";
  EXPECT_NEAR(rows.back()[1], pendulum_by_rk4(2.0, {10.0})[0], 1e-6);
  std::string dir = temporary_directory() + "/chosen";
  CommandOutput generated = run_eomgen("generate '" + model_path("pendulum") + "' --scene small_swing -o '" + dir + "'");
  EXPECT_EQ(generated.status, 0) << generated.err;
  EXPECT_NE(read_file(dir + "/pendulum_linear.hpp").find("namespace eomgen::models::pendulum_linear"), std::string::npos) << generated.err;
}

}  // namespace
}  // namespace eomgen::test
