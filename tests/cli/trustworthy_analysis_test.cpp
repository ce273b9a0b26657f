// Results eomgen prints must be right or say that they cannot be decided (issue
// "trustworthy analysis"): each test reproduces one wrong or misleading result
// of an earlier version on a small model written here, and checks the answer
// against the closed form or the refusal with its reason.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <regex>

#include <fmt/format.h>

#include "support/small_models.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

std::string fmt_number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

const char* const twenty_radian_oscillator = R"toml(
[model]
name = "oscillator"
title = "one mass on a spring: omega = sqrt(k/m) = 20 rad/s"
[parameters]
m = 1.0
k = 400.0
[coordinates]
x = { initial = 0.1, rate = 0.0 }
[[particles]]
name = "mass"
mass = "m"
position = ["x", "0", "0"]
[energy]
potential = "k*x^2/2"
)toml";

TEST(StabilityVerdicts, AMovingNonCyclicCoordinateIsNotAnEquilibrium) {
  CommandOutput r = run_eomgen("stability '" + model_path("pendulum") + "' --at phi=0 --at 'der(phi)=1'");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.err.find("der(phi) = 1 moves a coordinate that is not cyclic"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
  // a cyclic coordinate may turn at constant speed: the free body spinning about its minor axis
  CommandOutput spin = run_eomgen("stability '" + model_path("free_rigid_body") + "' --at 'der(alpha)=2'");
  EXPECT_EQ(spin.status, 0) << spin.err;
  EXPECT_NE(spin.out.find("verdict: marginally_stable"), std::string::npos) << spin.out;
}

TEST(StabilityVerdicts, ASingularMassMatrixIsFoundBeforeAnyVerdict) {
  std::string model = write_model("idle_coordinate", R"toml(
[model]
name = "idle_coordinate"
title = "y appears nowhere"
[parameters]
m = 1.0
k = 4.0
[coordinates]
x = 0.0
y = 0.0
[[particles]]
name = "mass"
mass = "m"
position = ["x", "0", "0"]
[energy]
potential = "k*x^2/2"
)toml");
  CommandOutput r = run_eomgen("stability '" + model + "'");
  EXPECT_EQ(r.status, 3);
  EXPECT_EQ(r.out.find("verdict"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("the mass matrix is singular"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("rank 1 of 2"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no inertia resists der(y)"), std::string::npos) << r.err;
}

const char* const sinc_pendulum = R"toml(
[model]
name = "sinc_pendulum"
title = "a position that divides by the coordinate"
[parameters]
m = 1.0
l = 1.0
g = 9.81
[coordinates]
phi = 0.0
[[particles]]
name = "bob"
mass = "m"
position = ["l*sin(phi)/phi", "-l*cos(phi)", "0"]
[gravity]
acceleration = ["0", "-g", "0"]
)toml";

TEST(StabilityVerdicts, NonFiniteValuesAreNamedAsSuch) {
  std::string model = write_model("sinc_pendulum", sinc_pendulum);
  CommandOutput r = run_eomgen("stability '" + model + "'");
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.err.find("M[0][0], f[0] (the equation of der(phi)), T are not finite at t = 0, phi = 0, der(phi) = 0"),
            std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("nan"), std::string::npos) << r.err;
  CommandOutput s = run_eomgen("simulate '" + model + "'");
  EXPECT_EQ(s.status, 3);
  EXPECT_NE(s.err.find("are not finite (a division by zero"), std::string::npos) << s.err;
  EXPECT_EQ(s.err.find("singular"), std::string::npos) << s.err;
}

TEST(InitialValues, ExpressionsAreEvaluatedAfterTheOverrides) {
  // the static deflection l0 + m g / k: with k = 80 the spring starts in equilibrium
  std::string model = write_model("hanging_spring", R"toml(
[model]
name = "hanging_spring"
title = "mass on a vertical spring, starting at its static deflection"
[parameters]
m = 1.0
k = 40.0
g = 9.81
l0 = 0.5
[coordinates]
r = { initial = "l0 + m*g/k", rate = 0.0 }
[[particles]]
name = "bob"
mass = "m"
position = ["0", "-r", "0"]
[gravity]
acceleration = ["0", "-g", "0"]
[energy]
potential = "k*(r - l0)^2/2"
)toml");
  std::string csv = temporary_directory() + "/run.csv";
  CommandOutput r = run_eomgen("simulate '" + model + "' --set k=80 --t-end 1 -o '" + csv + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  auto rows = read_numeric_csv(csv);
  ASSERT_FALSE(rows.empty());
  double deflection = 0.5 + 9.81 / 80;
  EXPECT_NEAR(rows.front()[1], deflection, 1e-15);
  EXPECT_NEAR(rows.back()[1], deflection, 1e-12) << "a mass at its static deflection stays there";
}

// n masses in a row between springs k and dampers c, the first tied to the wall
std::string damped_chain(int n) {
  std::string text = "[model]\nname = \"damped_chain\"\ntitle = \"masses, springs and dampers in a row\"\n"
                     "[parameters]\nm = 1.0\nk = 100.0\nc = 0.5\n[coordinates]\n";
  std::string potential, dissipation;
  for (int i = 1; i <= n; ++i) {
    text += "x" + std::to_string(i) + " = " + std::to_string(0.01 * i) + "\n";
    std::string q = "x" + std::to_string(i), previous = "x" + std::to_string(i - 1);
    potential += (i > 1 ? " + k*(" + q + " - " + previous + ")^2/2" : "k*x1^2/2");
    dissipation += (i > 1 ? " + c*(der(" + q + ") - der(" + previous + "))^2/2" : "c*der(x1)^2/2");
  }
  for (int i = 1; i <= n; ++i)
    text += "[[particles]]\nname = \"p" + std::to_string(i) + "\"\nmass = \"m\"\nposition = [\"x" + std::to_string(i) +
            "\", \"0\", \"0\"]\n";
  return text + "[energy]\npotential = \"" + potential + "\"\ndissipation = \"" + dissipation + "\"\n";
}

std::vector<double> numbers_after(const std::string& text, const std::string& key) {
  std::vector<double> out;
  std::size_t at = text.find(key);
  if (at == std::string::npos) return out;
  std::size_t end = text.find(']', at + key.size());
  std::string list = text.substr(at + key.size(), end - at - key.size());
  for (std::size_t i = 0; i < list.size();) {
    std::size_t comma = list.find(',', i);
    std::string item = list.substr(i, comma == std::string::npos ? std::string::npos : comma - i);
    out.push_back(item.find("null") != std::string::npos ? NAN : std::stod(item));
    if (comma == std::string::npos) break;
    i = comma + 1;
  }
  return out;
}

TEST(StabilityOutput, ModesAreSortedAndBothFrequenciesAreGiven) {
  // the two-mass chain: undamped frequencies sqrt((3 -+ sqrt 5)/2 k/m) = 6.18 and 16.18 rad/s
  std::string model = write_model("two_masses", damped_chain(2));
  CommandOutput r = run_eomgen("stability '" + model + "' --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  std::vector<double> undamped;
  std::regex mode(R"("frequency": ([-0-9.e+]+), "undamped_frequency": ([-0-9.e+]+), "damping_ratio": ([-0-9.e+]+))");
  for (std::sregex_iterator i(r.out.begin(), r.out.end(), mode), end; i != end; ++i) {
    double damped = std::stod((*i)[1]), natural = std::stod((*i)[2]), zeta = std::stod((*i)[3]);
    EXPECT_NEAR(damped, natural * std::sqrt(1 - zeta * zeta), 1e-9 * natural);
    undamped.push_back(natural);
  }
  ASSERT_EQ(undamped.size(), 2u) << r.out;
  EXPECT_NEAR(undamped[0], std::sqrt((3 - std::sqrt(5.0)) / 2 * 100), 1e-9);
  EXPECT_NEAR(undamped[1], std::sqrt((3 + std::sqrt(5.0)) / 2 * 100), 1e-9);
  CommandOutput text = run_eomgen("stability '" + model + "'");
  EXPECT_NE(text.out.find("undamped frequency 6.18034 rad/s, damped frequency"), std::string::npos) << text.out;
}

TEST(StabilityOutput, NoMinusZeroAndNoRoundingNoiseOnTheAxis) {
  for (const char* name : {"pendulum", "double_pendulum"}) {
    CommandOutput r = run_eomgen("stability '" + model_path(name) + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_FALSE(std::regex_search(r.out, std::regex(R"((^|[ \[(])-0([ ,\]\n]|$))"))) << r.out;
    EXPECT_FALSE(std::regex_search(r.out, std::regex(R"(e-1[4-9] [+-] )"))) << "noise in a real part:\n" << r.out;
    EXPECT_NE(r.out.find("Hurwitz determinants"), std::string::npos);
  }
}

TEST(StabilityOutput, HurwitzOfAHighOrderPolynomialIsScaledOrDeclared) {
  // order 20: unscaled, the determinants were about 1e134 and their signs noise
  std::string model = write_model("chain10", damped_chain(10));
  CommandOutput r = run_eomgen("stability '" + model + "' --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\"verdict\": \"asymptotically_stable\""), std::string::npos);
  std::vector<double> minors = numbers_after(r.out, "\"hurwitz\": [");
  ASSERT_EQ(minors.size(), 20u) << r.out;
  bool ill = r.out.find("\"hurwitz_ill_conditioned\": true") != std::string::npos;
  for (double h : minors) {
    if (std::isnan(h)) {
      EXPECT_TRUE(ill) << "a lost minor without the declaration";
    } else {
      EXPECT_TRUE(h > 0 && h < 1e12) << h << " in a stable system's balanced Hurwitz determinants";
    }
  }
  CommandOutput text = run_eomgen("stability '" + model + "'");
  EXPECT_EQ(ill, text.out.find("the verdict rests on the eigenvalues") != std::string::npos) << text.out;
  // a well-conditioned order: the two-mass chain's four minors are all there and positive
  CommandOutput small = run_eomgen("stability '" + write_model("chain2", damped_chain(2)) + "' --format json");
  EXPECT_NE(small.out.find("\"hurwitz_ill_conditioned\": false"), std::string::npos) << small.out;
  for (double h : numbers_after(small.out, "\"hurwitz\": [")) EXPECT_GT(h, 0);
}

TEST(StabilityOutput, UndampedPointsAreNotCountedAsAsymptoticallyStable) {
  CommandOutput r = run_eomgen("sweep '" + model_path("double_pendulum") +
                               "' --param m1=0.5:2:6 --param l2=0.5:2:6 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\"asymptotically_stable\": 0"), std::string::npos) << r.out;
  CommandOutput damped = run_eomgen("sweep '" + model_path("pendulum") + "' --set d=0.1 --param m=0.5:2:6 "
                                    "--param l=0.5:2:6 --format json");
  EXPECT_NE(damped.out.find("\"asymptotically_stable\": 36"), std::string::npos) << damped.out;
}

TEST(StabilityOutput, SymbolicConditionsThatAlwaysHoldSaySo) {
  CommandOutput r = run_eomgen("stability '" + model_path("pendulum") + "' --set d=0.1 --symbolic m,l");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("none: every Hurwitz condition holds for all positive values of m, l"), std::string::npos) << r.out;
}

TEST(FixedSteps, AStepBeyondTheStabilityLimitIsNamedAndNeverExitsZero) {
  // ω = sqrt(k/m) = 20 rad/s: RK4 is stable up to h = 2√2/20 = 0.1414 s, Verlet up to 2/20 = 0.1 s
  std::string model = write_model("oscillator", twenty_radian_oscillator);
  struct Case {
    const char* integrator;
    double step;
    bool stable;
  };
  for (Case c : {Case{"rk4", 0.2, false}, Case{"rk4", 0.14, true}, Case{"verlet", 0.11, false}, Case{"verlet", 0.095, true}})
    for (double t_end : {10.0, 100.0}) {
      std::string step = std::to_string(c.step);
      CommandOutput r = run_eomgen("simulate '" + model + "' --integrator " + c.integrator + " --step " + step +
                                   " --dt-out " + step + " --t-end " + std::to_string(t_end));
      SCOPED_TRACE(std::string(c.integrator) + " h = " + step + " to " + std::to_string(t_end));
      EXPECT_EQ(r.err.find("escapes to infinity"), std::string::npos) << r.err;
      if (c.stable) {
        EXPECT_EQ(r.status, 0) << r.err;
        EXPECT_EQ(r.err.find("stability limit"), std::string::npos) << r.err;
        continue;
      }
      EXPECT_EQ(r.status, 3) << r.out << r.err;
      EXPECT_NE(r.err.find(std::string("is beyond its stability limit at t = 0: h·|λ| = ") +
                           (c.step == 0.2 ? "4 " : "2.2 ")), std::string::npos) << r.err;
      EXPECT_NE(r.err.find(std::string("stable up to ") + (std::string(c.integrator) == "rk4" ? "2.83" : "2") +
                           " on the imaginary axis"), std::string::npos) << r.err;
      EXPECT_NE(r.err.find(std::string("largest stable step here is ") + (std::string(c.integrator) == "rk4" ? "0.141" : "0.1")),
                std::string::npos) << r.err;
      EXPECT_NE(r.err.find("not the mechanics"), std::string::npos) << r.err;
    }
}

TEST(FixedSteps, AStepLongerThanTheOutputIntervalIsSaid) {
  CommandOutput r = run_eomgen("simulate '" + write_model("oscillator", twenty_radian_oscillator) +
                               "' --integrator rk4 --step 0.2 --t-end 1");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("the step 0.2 s is longer than the output interval 0.01 s"), std::string::npos) << r.err;
}

TEST(DefaultIntegrator, ChosenFromTheModelAndSaid) {
  std::string oscillator_model = write_model("oscillator", twenty_radian_oscillator);
  CommandOutput smooth = run_eomgen("simulate '" + oscillator_model + "' --t-end 10 --format json");
  ASSERT_EQ(smooth.status, 0) << smooth.err;
  EXPECT_NE(smooth.err.find("integrator arkode-dp5: the model is not stiff"), std::string::npos) << smooth.err;
  EXPECT_NE(smooth.out.find("\"integrator\": \"arkode-dp5\""), std::string::npos) << smooth.out;
  CommandOutput stiff = run_eomgen("simulate '" + model_path("stiff_chain") + "' --t-end 1");
  EXPECT_NE(stiff.err.find("integrator cvode-bdf: the model is stiff"), std::string::npos) << stiff.err;
  CommandOutput constrained = run_eomgen("simulate '" + model_path("slider_crank") + "' --t-end 1");
  EXPECT_NE(constrained.err.find("integrator cvode-bdf: the model has constraints"), std::string::npos) << constrained.err;
  // the reason for the choice: at the same tolerances the conservative oscillator keeps its
  // energy better with the explicit method than with BDF
  auto drift = [](const std::string& json) {
    std::smatch m;
    std::regex_search(json, m, std::regex(R"("relative_energy_drift": ([0-9.e+-]+))"));
    return m.empty() ? NAN : std::stod(m[1]);
  };
  CommandOutput bdf = run_eomgen("simulate '" + oscillator_model + "' --t-end 10 --integrator cvode-bdf --format json");
  EXPECT_LT(drift(smooth.out), drift(bdf.out) / 10) << smooth.out << "\n" << bdf.out;
}

TEST(ConstrainedInitialState, TheUsersVelocitiesWinWhereTheConstraintsAllow) {
  // the rod pendulum at (x0, y0): x der(x) + y der(y) = 0 determines one velocity from the other
  std::string csv = temporary_directory() + "/rod.csv";
  CommandOutput r = run_eomgen("simulate '" + model_path("pendulum_cartesian") + "' --initial 'der(y)=-2' --t-end 0.1 -o '" +
                               csv + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("do not allow"), std::string::npos) << r.err;
  auto rows = read_numeric_csv(csv);
  ASSERT_FALSE(rows.empty());
  double x = rows[0][1], y = rows[0][2];
  EXPECT_EQ(rows[0][4], -2.0) << "der(y) as given";
  EXPECT_NEAR(rows[0][3], -y * -2.0 / x, 1e-12) << "der(x) from the constraint";
  // both given: they cannot both stand; the change is said with its size
  CommandOutput both = run_eomgen("simulate '" + model_path("pendulum_cartesian") +
                                  "' --initial 'der(y)=-2' --initial 'der(x)=1' --t-end 0.1");
  ASSERT_EQ(both.status, 0) << both.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(both.err, m, std::regex(R"(changed der\(y\) from -2 to ([-0-9.e]+) \(by ([-+0-9.e]+)\))")))
      << both.err;
  EXPECT_NEAR(std::stod(m[1]), -x * 1.0 / y, 1e-8);
}

// Baumgarte's gains are rates in 1/s: simulate says where they are far from the system's rate (the
// rod pendulum at time scales T of 1e12 and 1e-12 s), and not where they are near it or not used
TEST(BaumgarteGains, AreSaidToBeFarFromTheSystemsRateWhereTheyAre) {
  auto run = [](double T, const std::string& options) {
    return run_eomgen(fmt::format("simulate '{}' --set g={:.17g} --t-end {:g} --dt-out {:g} {}", model_path("pendulum_cartesian"),
                                  9.81 / (T * T), 10 * T, T / 10, options));
  };
  const std::string faster = "times the system's rate: a constraint error decays that much faster than the motion";
  const std::string slower = "times the system's rate: a constraint error is corrected that much more slowly";
  for (double T : {1e12, 1e-12}) {
    CommandOutput far = run(T, "");
    ASSERT_EQ(far.status, 0) << far.err;
    EXPECT_NE(far.err.find(T > 1 ? faster : slower), std::string::npos) << "T = " << T << "\n" << far.err;
    EXPECT_NE(far.err.find("(alpha 10, beta 10 1/s, the model's)"), std::string::npos) << far.err;
    for (const std::string& kept : {std::string("--stabilization projection"),
                                    fmt::format("--baumgarte-alpha {:g} --baumgarte-beta {:g}", 3 / T, 3 / T)}) {
      CommandOutput near = run(T, kept);
      ASSERT_EQ(near.status, 0) << near.err;
      EXPECT_EQ(near.err.find("Baumgarte's gains"), std::string::npos) << "T = " << T << ", " << kept << "\n" << near.err;
    }
  }
  CommandOutput usual = run(1.0, "");
  EXPECT_EQ(usual.err.find("Baumgarte's gains"), std::string::npos) << usual.err;
}

std::string verdict_of(const CommandOutput& r) {
  std::smatch m;
  return std::regex_search(r.out, m, std::regex(R"re("verdict": "([a-z_]+)")re")) ? std::string(m[1]) : "none: " + r.err;
}

TEST(Floquet, MathieuStabilityChartAtQOne) {
  // characteristic values at q = 1 (Abramowitz & Stegun, Table 20.1): a0 = -0.4551386,
  // b1 = -0.1102488, a1 = 1.8591081, b2 = 3.9170248, a2 = 4.3713010; unstable in (b1, a1)
  // and (b2, a2), stable between a0 and b1 and between a1 and b2
  struct Point {
    double a;
    const char* verdict;
  };
  for (Point p : {Point{-0.2, "marginally_stable"}, Point{-0.1102488 - 0.005, "marginally_stable"},
                  Point{-0.1102488 + 0.005, "unstable"}, Point{1.0, "unstable"}, Point{1.8591081 - 0.005, "unstable"},
                  Point{1.8591081 + 0.005, "marginally_stable"}, Point{2.5, "marginally_stable"},
                  Point{3.9170248 - 0.005, "marginally_stable"}, Point{3.9170248 + 0.005, "unstable"},
                  Point{4.3713010 - 0.005, "unstable"}, Point{4.3713010 + 0.005, "marginally_stable"}}) {
    CommandOutput r = run_eomgen("stability '" + model_path("mathieu") + "' --set q=1 --set a=" + fmt_number(p.a) +
                                 " --format json");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(verdict_of(r), p.verdict) << "a = " << p.a << "\n" << r.out;
    EXPECT_NE(r.out.find("\"analysis\": \"floquet\""), std::string::npos);
  }
}

TEST(Floquet, KapitzaPendulumUprightAboveTheCriterion) {
  // a² w² > 2 g l: with a = 0.1 m, l = 1 m the upright pendulum is stable above w = 44.29 rad/s
  // (the exact boundary, from Mathieu's a0(q), lies within 0.3 % of it)
  double critical = std::sqrt(2 * 9.81 * 1.0) / 0.1;
  std::string upright = " --at phi=3.141592653589793 --format json";
  CommandOutput slow = run_eomgen("stability '" + model_path("kapitza_pendulum") + "' --set w=" +
                                  fmt_number(0.95 * critical) + upright);
  CommandOutput fast = run_eomgen("stability '" + model_path("kapitza_pendulum") + "' --set w=" +
                                  fmt_number(1.05 * critical) + upright);
  EXPECT_EQ(verdict_of(slow), "unstable") << slow.out;
  EXPECT_EQ(verdict_of(fast), "marginally_stable") << fast.out;
  // at the model's w = 60 rad/s: the period 2 pi / w is found, and no theorem of frozen t is quoted
  CommandOutput text = run_eomgen("stability '" + model_path("kapitza_pendulum") + "' --at phi=3.141592653589793");
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("Floquet analysis over the period T = " + fmt_number(2 * M_PI / 60).substr(0, 10)), std::string::npos)
      << text.out;
  EXPECT_EQ(text.out.find("Lagrange-Dirichlet"), std::string::npos) << text.out;
}

TEST(Floquet, TimeDependenceThatIsNotPeriodicIsRefused) {
  std::string model = write_model("decaying_spring", R"toml(
[model]
name = "decaying_spring"
title = "a stiffness that decays in time"
[parameters]
k = 4.0
[coordinates]
x = 0.0
[[particles]]
name = "p"
mass = "1"
position = ["x", "0", "0"]
[energy]
potential = "k*exp(-t)*x^2/2"
)toml");
  CommandOutput r = run_eomgen("stability '" + model + "'");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("depend explicitly on time, and not periodically"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
  CommandOutput forced = run_eomgen("stability '" + model + "' --period 1");
  EXPECT_EQ(forced.status, 2);
  EXPECT_NE(forced.err.find("not periodic with this period"), std::string::npos) << forced.err;
  CommandOutput sweep = run_eomgen("sweep '" + model_path("mathieu") + "' --param a=0:1:3 --param q=0:1:3");
  EXPECT_EQ(sweep.status, 2);
  EXPECT_NE(sweep.err.find("depend on time"), std::string::npos) << sweep.err;
}



double final_position(const std::string& csv) {
  auto rows = read_numeric_csv(csv);
  return rows.empty() ? NAN : rows.back()[1];
}

TEST(Inputs, AFunctionOfTimeDrivesTheModel) {
  // m x'' = F0 sin(w t) from rest: x(t) = F0 / (m w²) (w t − sin w t)
  std::string model = write_model("pushed_mass", pushed_mass_model), csv = temporary_directory() + "/run.csv";
  CommandOutput r = run_eomgen("simulate '" + model + "' --input 'F=3*sin(2*t)/m*m' --t-end 2 --rtol 1e-11 --atol 1e-13 -o '" +
                               csv + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(final_position(csv), 3.0 / (2.0 * 4.0) * (4.0 - std::sin(4.0)), 1e-9);
  CommandOutput broken = run_eomgen("simulate '" + model + "' --input 'F=sin(2*t'");
  EXPECT_EQ(broken.status, 2);
  EXPECT_NE(broken.err.find("--input:1:"), std::string::npos) << broken.err;
}

TEST(Inputs, ATableIsInterpolatedLinearly) {
  // F rises linearly from 0 to 1 over the first second, then stays: m = 2, x(2) = (1/6 + 1/2 + 1/2)/m
  std::string dir = temporary_directory();
  std::ofstream(dir + "/u.csv") << "t,F\n0,0\n1,1\n5,1\n";
  std::string model = write_model("pushed_mass", pushed_mass_model), csv = dir + "/run.csv";
  CommandOutput r = run_eomgen("simulate '" + model + "' --input-file '" + dir + "/u.csv' --t-end 2 --rtol 1e-11 "
                               "--atol 1e-13 -o '" + csv + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(final_position(csv), (1.0 / 6 + 0.5 + 0.5) / 2, 1e-9);
  std::ofstream(dir + "/short.csv") << "t,F\n0,0\n1,1\n";
  CommandOutput held = run_eomgen("simulate '" + model + "' --input-file '" + dir + "/short.csv' --t-end 2");
  EXPECT_EQ(held.status, 0);
  EXPECT_NE(held.err.find("ends at t = 1, before --t-end 2: its last values are held"), std::string::npos) << held.err;
}

TEST(Charts, OutputsAndAnXYChart) {
  std::string dir = temporary_directory();
  CommandOutput r = run_eomgen("simulate '" + model_path("double_pendulum") + "' --t-end 2 --plot '" + dir +
                               "/dp.png' --plot-xy tip_x,tip_y");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* chart : {"/dp.png", "/dp_energy.png", "/dp_outputs.png", "/dp_xy.png"})
    EXPECT_GT(read_file(dir + chart).size(), 10000u) << chart;
  CommandOutput wrong = run_eomgen("simulate '" + model_path("double_pendulum") + "' --plot '" + dir +
                                   "/x.png' --plot-xy tip_x,tipy");
  EXPECT_EQ(wrong.status, 2);
  EXPECT_NE(wrong.err.find("did you mean 'tip_y'"), std::string::npos) << wrong.err;
  EXPECT_EQ(run_eomgen("simulate '" + model_path("double_pendulum") + "' --plot-xy tip_x,tip_y").status, 2)
      << "the x-y chart is named after --plot";
}

}  // namespace
}  // namespace eomgen::test
