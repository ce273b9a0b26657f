// `eomgen linear` against closed forms written here: the two-mass chain's
// frequencies, mass-normalized modes, Rayleigh damping ratios and Φ(t) from the
// modal solution; the double pendulum's frequencies and mode-shape ratios from its
// frequency equation; the space rendezvous' Jordan structure and Φ(t) against the
// Clohessy–Wiltshire solution. Transfer functions from their minimal realization: the
// upright cart pendulum, a quarter car at three time scales, an output the input cannot move;
// an output's C on its own scale (a capacitance across gaps from 1e-12 to 1e6 m).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include <fmt/format.h>

#include "parse/json_reader.hpp"
#include "support/small_models.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {


// Φ(t) from the JSON, row-major
std::vector<std::vector<double>> matrix_at(const JsonValue& json, std::size_t index) {
  std::vector<std::vector<double>> out;
  for (const JsonValue& row : json.find("fundamental_matrix")->items[index].find("matrix")->items) {
    out.emplace_back();
    for (const JsonValue& x : row.items) out.back().push_back(x.value);
  }
  return out;
}

TEST(LinearCommand, TwoMassChainModesAndFundamentalMatrix) {
  // m = 1, k = 100, alpha = 0.1, beta = 0.001: ω = 10, √300; modes (1, ±1)/√2
  JsonValue json = run_json("linear '" + model_path("two_mass_chain") + "' --at x1=0 --at x2=0 --times 0.25,1.5");
  const auto& modes = json.find("modes")->items;
  ASSERT_EQ(modes.size(), 2u);
  const double alpha = 0.1, beta = 0.001, w[2] = {10, std::sqrt(300.0)}, sign[2] = {1, -1};
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(at(modes[i], "frequency_rad_s"), w[i], 1e-12 * w[i]);
    EXPECT_NEAR(at(modes[i], "period_s"), 2 * M_PI / w[i], 1e-12);
    EXPECT_NEAR(at(modes[i], "damping_ratio"), alpha / (2 * w[i]) + beta * w[i] / 2, 1e-12);
    EXPECT_NEAR(at(*modes[i].find("shape"), "x1"), 1 / std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(at(*modes[i].find("shape"), "x2"), sign[i] / std::sqrt(2.0), 1e-12);
  }
  EXPECT_EQ(json.find("damping")->find("kind")->text, "proportional");
  EXPECT_LT(at(json, "orthonormality_error"), 1e-12);
  EXPECT_LT(at(json, "rayleigh_quotient_error"), 1e-12);
  // x1 held: the second mass alone on k2 + k3 = 200, ω = √200, between 10 and √300
  const JsonValue& held = json.find("interlacing")->items.at(0);
  EXPECT_EQ(held.find("fixed")->text, "x1");
  EXPECT_NEAR(held.find("frequencies_rad_s")->items.at(0).value, std::sqrt(200.0), 1e-10);
  EXPECT_TRUE(held.find("interlaces")->truth);
  // Φ(t) by modes: each q_i'' + 2ζω q_i' + ω² q_i = 0 solved in closed form, then x = V q
  for (std::size_t k = 0; k < 2; ++k) {
    double t = k == 0 ? 0.25 : 1.5;
    auto Phi = matrix_at(json, k);
    double exact[4][4] = {};
    for (int i = 0; i < 2; ++i) {
      double z = alpha / (2 * w[i]) + beta * w[i] / 2, wd = w[i] * std::sqrt(1 - z * z), e = std::exp(-z * w[i] * t);
      double c = std::cos(wd * t), s = std::sin(wd * t);
      // q(t) = e(c q0 + (v0 + zω q0)/wd s), v(t) = e((−ω²/wd) s q0 + (c − zω/wd s) v0)
      double qq = e * (c + z * w[i] / wd * s), qv = e * s / wd, vq = -e * w[i] * w[i] / wd * s, vv = e * (c - z * w[i] / wd * s);
      double V[2] = {1 / std::sqrt(2.0), sign[i] / std::sqrt(2.0)};
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) {
          double P = V[a] * V[b];  // V diag(...) Vᵀ with M = I
          exact[a][b] += P * qq, exact[a][2 + b] += P * qv, exact[2 + a][b] += P * vq, exact[2 + a][2 + b] += P * vv;
        }
    }
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) EXPECT_NEAR(Phi[a][b], exact[a][b], 1e-12 * 100) << "Phi(" << t << ")[" << a << "][" << b << "]";
  }
}

TEST(LinearCommand, PrincipalCoordinatesDecoupleTheChain) {
  // q = Φ η: η_i'' + (α + β ω_i²) η_i' + ω_i² η_i = φ_iᵀ (0, 1) F (Hiller §6.3)
  JsonValue json = run_json("linear '" + model_path("two_mass_chain") + "' --at x1=0 --at x2=0");
  const JsonValue& p = *json.find("principal_coordinates");
  EXPECT_EQ(p.find("kind")->text, "modal");
  const auto& equations = p.find("equations")->items;
  ASSERT_EQ(equations.size(), 2u);
  EXPECT_EQ(equations[0].text, "der(der(eta1)) + 0.2*der(eta1) + 100*eta1 = (0.707107) F");
  EXPECT_EQ(equations[1].text, "der(der(eta2)) + 0.4*der(eta2) + 300*eta2 = (-0.707107) F");
  const auto& Phi = p.find("matrix")->items;
  EXPECT_NEAR(Phi[1].items[1].value, -1 / std::sqrt(2.0), 1e-12);
  // the rendezvous' Jordan block at 0 keeps its chain coupled: η3' = η4, η4' = 0 (the drift along the track)
  JsonValue cw = run_json("linear '" + model_path("space_rendezvous") + "' --at x=0");
  const JsonValue& jordan = *cw.find("principal_coordinates");
  EXPECT_EQ(jordan.find("kind")->text, "jordan");
  const auto& chained = jordan.find("equations")->items;
  ASSERT_EQ(chained.size(), 6u);
  EXPECT_EQ(chained[2].text, "der(eta3) = (0)*eta3 + eta4 + 0");
  EXPECT_EQ(chained[3].text, "der(eta4) = (0)*eta4 + 0");
}

TEST(LinearCommand, DoublePendulumFrequenciesFromTheFrequencyEquation) {
  // m1 l1 l2 ω⁴ − (m1 + m2) g (l1 + l2) ω² + (m1 + m2) g² = 0 (absolute angles, as the model's)
  const std::string set = " --set m1=1.5 --set m2=0.7 --set l1=0.9 --set l2=0.6 --set g=9.81";
  JsonValue json = run_json("linear '" + model_path("double_pendulum") + "' --at phi1=0 --at phi2=0" + set);
  const double m1 = 1.5, m2 = 0.7, l1 = 0.9, l2 = 0.6, g = 9.81;
  double a = m1 * l1 * l2, b = -(m1 + m2) * g * (l1 + l2), c = (m1 + m2) * g * g;
  double roots[2] = {(-b - std::sqrt(b * b - 4 * a * c)) / (2 * a), (-b + std::sqrt(b * b - 4 * a * c)) / (2 * a)};
  const auto& modes = json.find("modes")->items;
  ASSERT_EQ(modes.size(), 2u);
  for (int i = 0; i < 2; ++i) {
    double w2 = roots[i];
    EXPECT_NEAR(std::pow(at(modes[i], "frequency_rad_s"), 2), w2, 1e-12 * w2);
    // phi2/phi1 = (m1 + m2)(g − ω² l1)/(ω² m2 l2)
    const JsonValue& shape = *modes[i].find("shape");
    EXPECT_NEAR(at(shape, "phi2") / at(shape, "phi1"), (m1 + m2) * (g - w2 * l1) / (w2 * m2 * l2), 1e-10);
  }
  for (const JsonValue& e : json.find("eigenvalues")->items) EXPECT_EQ(at(e, "re"), 0) << "conservative: on the axis";
}

// det(λ² M + λ D + K) / det M of the tuned absorber, m1 m2 λ⁴ + d (m1 + m2) λ³ + (m1 k2 + m2 k1 + m2 k2) λ²
// + d k1 λ + k1 k2 over m1 m2, with its time scaled by s (k s², d s). The coefficients had come from
// the eigenvalues of the unbalanced A: at s = 1e6 (entries from 1 to 1e14) they were 0.5 % off.
TEST(LinearCommand, TheCharacteristicPolynomialIsExactAtEveryTimeScale) {
  const double m1 = 10, m2 = 1, k1 = 1000, k2 = 82.6446, d = 2;
  for (double s : {1e-12, 1e-6, 1.0, 1e6, 1e12}) {
    std::string set = fmt::format(" --set k1={:.17g} --set k2={:.17g} --set d={:.17g}", k1 * s * s, k2 * s * s, d * s);
    JsonValue json = run_json("linear '" + model_path("damped_two_mass_oscillator") + "' --at x1=0 --at x2=0" + set);
    const auto& c = json.find("characteristic_polynomial")->items;
    ASSERT_EQ(c.size(), 5u);
    double exact[5] = {1, d * (m1 + m2) / (m1 * m2), (m1 * k2 + m2 * k1 + m2 * k2) / (m1 * m2), d * k1 / (m1 * m2),
                       k1 * k2 / (m1 * m2)};
    for (int i = 0; i < 5; ++i)
      EXPECT_NEAR(c[std::size_t(i)].value / std::pow(s, i), exact[i], 1e-9 * exact[i]) << "s = " << s << ", λ^" << 4 - i;
  }
}

TEST(LinearCommand, RendezvousJordanStructureAndTheClohessyWiltshireSolution) {
  const double n = 0.0011;
  JsonValue json = run_json("linear '" + model_path("space_rendezvous") + "' --at x=0 --times 600,3000");
  int found = 0;
  for (const JsonValue& e : json.find("eigenvalues")->items) {
    double re = at(e, "re"), im = at(e, "im");
    EXPECT_EQ(re, 0);
    EXPECT_EQ(at(e, "algebraic_multiplicity"), 2);
    const auto& blocks = e.find("jordan_blocks")->items;
    if (im == 0) {
      EXPECT_EQ(at(e, "geometric_multiplicity"), 1) << "the along-track drift";
      ASSERT_EQ(blocks.size(), 1u);
      EXPECT_EQ(blocks[0].value, 2);
    } else {
      EXPECT_NEAR(std::abs(im), n, 1e-12);
      EXPECT_EQ(at(e, "geometric_multiplicity"), 2) << "semisimple";
    }
    ++found;
  }
  EXPECT_EQ(found, 3);
  EXPECT_FALSE(json.find("structure_uncertain")->truth);
  EXPECT_EQ(json.find("jordan_decided")->text, "exact") << "n = 0.0011 is rational: A is exact";
  for (std::size_t k = 0; k < 2; ++k) {
    double t = k == 0 ? 600 : 3000, c = std::cos(n * t), s = std::sin(n * t);
    // state [x, y, z, x', y', z']
    double cw[6][6] = {{4 - 3 * c, 0, 0, s / n, 2 * (1 - c) / n, 0},
                       {6 * (s - n * t), 1, 0, 2 * (c - 1) / n, (4 * s - 3 * n * t) / n, 0},
                       {0, 0, c, 0, 0, s / n},
                       {3 * n * s, 0, 0, c, 2 * s, 0},
                       {6 * n * (c - 1), 0, 0, -2 * s, 4 * c - 3, 0},
                       {0, 0, -n * s, 0, 0, c}};
    auto Phi = matrix_at(json, k);
    double largest = 0;
    for (auto& row : cw)
      for (double v : row) largest = std::max(largest, std::abs(v));
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b) EXPECT_NEAR(Phi[a][b], cw[a][b], 1e-10 * largest) << "t = " << t << " [" << a << "][" << b << "]";
  }
}

TEST(LinearCommand, CartPendulumIsControllableWithTheClosedFormTransferFunction) {
  // hanging, force F on the cart: X/F = (l s² + g) / (s² (mc l s² + (mc + m) g))
  const double mc = 1.3, m = 0.4, l = 0.6, g = 9.81;
  JsonValue json = run_json("linear '" + model_path("cart_pendulum") + "' --at x=0 --at theta=0 --set mc=1.3 --set m=0.4 "
                            "--set l=0.6 --transfer F:x");
  EXPECT_TRUE(json.find("controllable")->truth);
  EXPECT_EQ(at(*json.find("kalman_ranks"), "controllability"), 4);
  const JsonValue& g_json = json.find("transfer_functions")->items.at(0);
  EXPECT_NEAR(at(g_json, "gain"), 1 / mc, 1e-12);
  std::vector<double> pole_frequencies, zero_frequencies;
  for (const JsonValue& p : g_json.find("poles")->items) pole_frequencies.push_back(std::abs(p.items[1].value));
  for (const JsonValue& z : g_json.find("zeros")->items) zero_frequencies.push_back(std::abs(z.items[1].value));
  std::sort(pole_frequencies.begin(), pole_frequencies.end());
  ASSERT_EQ(pole_frequencies.size(), 4u);
  EXPECT_NEAR(pole_frequencies[0], 0, 1e-7) << "the double pole at 0 (a Jordan block: split by about sqrt(eps))";
  EXPECT_NEAR(pole_frequencies[3], std::sqrt((mc + m) * g / (mc * l)), 1e-12);
  ASSERT_EQ(zero_frequencies.size(), 2u);
  for (double z : zero_frequencies) EXPECT_NEAR(z, std::sqrt(g / l), 1e-10);
}

// the upright cart pendulum from F to the angle: the cart's double pole at 0 is not seen in the
// angle and cancels; φ/F = 1/(mc l s² − (mc + m) g), so G(0) = −1/((mc + m) g)
TEST(LinearCommand, UprightCartPendulumTransferFunctionIsMinimal) {
  const double mc = 1.3, m = 0.4, l = 0.6, g = 9.81;
  JsonValue json = run_json("linear '" + model_path("cart_pendulum") + "' --at x=0 --at theta=3.141592653589793 "
                            "--set mc=1.3 --set m=0.4 --set l=0.6 --transfer F:theta");
  const JsonValue& tf = json.find("transfer_functions")->items.at(0);
  EXPECT_EQ(tf.find("zeros")->items.size(), 0u);
  ASSERT_EQ(tf.find("poles")->items.size(), 2u);
  for (const JsonValue& p : tf.find("poles")->items)
    EXPECT_NEAR(std::abs(p.items[0].value), std::sqrt((mc + m) * g / (mc * l)), 1e-10);
  EXPECT_NEAR(at(tf, "gain"), 1 / (mc * l), 1e-12);
  EXPECT_NEAR(at(tf, "dc_gain"), -1 / ((mc + m) * g), 1e-12);
  EXPECT_EQ(at(tf, "cancelled_modes"), 2);
}

// road height to body height of a quarter car: G(s) = kt (cs s + ks)/Δ(s), one zero at −ks/cs,
// G(0) = 1 (no spurious zeros near infinity from the pencil's rounding)
TEST(LinearCommand, QuarterCarHasOneZeroAndUnitStaticGain) {
  const double ms = 250, mu = 35, ks = 16000, cs = 1000, kt = 160000;
  std::string path = temporary_directory() + "/quarter_car.toml";
  std::ofstream(path) << "[model]\nname = \"quarter_car\"\ntitle = \"Quarter car on a road\"\n\n"
                         "[parameters]\nms = 250.0\nmu = 35.0\nks = 16000.0\ncs = 1000.0\nkt = 160000.0\n\n"
                         "[coordinates]\nzs = 0.0\nzu = 0.0\n\n[inputs]\nroad = 0.0\n\n"
                         "[[particles]]\nname = \"body\"\nmass = \"ms\"\nposition = [\"0\", \"0\", \"zs\"]\n\n"
                         "[[particles]]\nname = \"wheel\"\nmass = \"mu\"\nposition = [\"0\", \"0\", \"zu\"]\n\n"
                         "[energy]\npotential = \"ks*(zs - zu)^2/2 + kt*zu^2/2\"\n"
                         "dissipation = \"cs*(der(zs) - der(zu))^2/2\"\n\n"
                         "[[forces]]\ngeneralized = { zu = \"kt*road\" }\n\n[outputs]\nbody = \"zs\"\n";
  JsonValue json = run_json("linear '" + path + "' --at zs=0 --at zu=0 --transfer road:body");
  const JsonValue& tf = json.find("transfer_functions")->items.at(0);
  ASSERT_EQ(tf.find("zeros")->items.size(), 1u);
  EXPECT_NEAR(tf.find("zeros")->items[0].items[0].value, -ks / cs, 1e-9 * ks / cs);
  EXPECT_NEAR(tf.find("zeros")->items[0].items[1].value, 0, 1e-9 * ks / cs);
  EXPECT_EQ(tf.find("poles")->items.size(), 4u);
  EXPECT_NEAR(at(tf, "gain"), kt * cs / (ms * mu), 1e-9 * kt * cs / (ms * mu));
  EXPECT_NEAR(at(tf, "dc_gain"), 1, 1e-9);
  // the same at scales of time from 1e-6 to 1e6: the zero scales, the gain in s² too
  for (double s : {1e-6, 1e6}) {
    JsonValue scaled = run_json(fmt::format("linear '{}' --at zs=0 --at zu=0 --transfer road:body --set ks={:.17g} "
                                            "--set cs={:.17g} --set kt={:.17g}", path, ks * s * s, cs * s, kt * s * s));
    const JsonValue& g = scaled.find("transfer_functions")->items.at(0);
    ASSERT_EQ(g.find("zeros")->items.size(), 1u) << "s = " << s;
    EXPECT_NEAR(g.find("zeros")->items[0].items[0].value / s, -ks / cs, 1e-8 * ks / cs) << "s = " << s;
    EXPECT_NEAR(at(g, "dc_gain"), 1, 1e-8) << "s = " << s;
  }
}

// an output that the input cannot move: G ≡ 0, no poles or zeros listed
TEST(LinearCommand, AnOutputTheInputCannotMoveHasAZeroTransferFunction) {
  JsonValue json = run_json("linear '" + model_path("cart_pendulum") + "' --at x=0 --at theta=0 --transfer F:bob_height");
  const JsonValue& tf = json.find("transfer_functions")->items.at(0);
  EXPECT_TRUE(tf.find("constant")->truth);
  EXPECT_EQ(tf.find("zeros")->items.size(), 0u);
  EXPECT_EQ(tf.find("poles")->items.size(), 0u);
  EXPECT_EQ(at(tf, "gain"), 0);
}

// the Mathieu equation's coefficients depend on time: no constant A to analyse
TEST(LinearCommand, EquationsThatDependOnTimeAreRefused) {
  CommandOutput r = run_eomgen("linear '" + model_path("mathieu") + "'");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.err.find("the equations depend explicitly on time"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("Floquet"), std::string::npos) << r.err;
}

TEST(LinearCommand, AModeTheInputCannotReachIsNamed) {
  // two uncoupled oscillators, the force on the first only: the second mode is unreachable
  std::string dir = temporary_directory(), path = dir + "/two_oscillators.toml";
  std::ofstream(path) << "[model]\nname = \"two_oscillators\"\ntitle = \"Two uncoupled oscillators\"\n\n"
                         "[parameters]\nk1 = 4.0\nk2 = 9.0\n\n[coordinates]\na = 0.0\nb = 0.0\n\n[inputs]\nF = 0.0\n\n"
                         "[[particles]]\nname = \"first\"\nmass = \"1\"\nposition = [\"a\", \"0\", \"0\"]\n\n"
                         "[[particles]]\nname = \"second\"\nmass = \"1\"\nposition = [\"b\", \"0\", \"0\"]\n\n"
                         "[energy]\npotential = \"k1*a^2/2 + k2*b^2/2\"\n\n[[forces]]\ngeneralized = { a = \"F\" }\n";
  JsonValue json = run_json("linear '" + path + "' --at a=0 --at b=0 --outputs a");
  EXPECT_FALSE(json.find("controllable")->truth);
  EXPECT_FALSE(json.find("observable")->truth) << "b is not seen in a either";
  EXPECT_EQ(at(*json.find("kalman_ranks"), "controllability"), 2);
  int unreachable = 0;
  for (const JsonValue& mode : json.find("mode_reach")->items) {
    bool second = std::abs(std::abs(at(mode, "im")) - 3) < 1e-9;
    EXPECT_EQ(mode.find("controllable")->truth, !second) << at(mode, "im");
    if (!second) continue;
    ++unreachable;
    std::vector<std::string> states;
    for (const JsonValue& s : mode.find("unreachable_states")->items) states.push_back(s.text);
    EXPECT_EQ(states, (std::vector<std::string>{"b", "der(b)"}));
  }
  EXPECT_EQ(unreachable, 2) << "the pair ±3i";
  CommandOutput text = run_eomgen("linear '" + path + "' --at a=0 --at b=0");
  EXPECT_NE(text.out.find("the mode 0 + 3i cannot be reached by the inputs (PBH); it lives in b, der(b)"), std::string::npos)
      << text.out;
}

// the response CSV of `linear --response ...`
std::vector<std::vector<double>> response(const std::string& options) {
  std::string csv = temporary_directory() + "/response.csv";
  CommandOutput r = run_eomgen("linear '" + model_path("two_mass_chain") + "' --at x1=0 --at x2=0 " + options + " -o '" + csv + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  return read_numeric_csv(csv);
}

TEST(LinearCommand, StepResponseOfTheChainByModes) {
  // unit step in F on the second mass: q_i = f_i/ω_i² (1 − e^{−ζωt}(cos ω_d t + ζω/ω_d sin ω_d t)), f = Φᵀ(0, 1)
  auto rows = response("--response step:F --t-end 3 --dt-out 0.1");
  ASSERT_EQ(rows.size(), 31u);
  const double alpha = 0.1, beta = 0.001, w[2] = {10, std::sqrt(300.0)}, sign[2] = {1, -1};
  for (const auto& row : rows) {
    double t = row[0], x[2] = {0, 0};
    for (int i = 0; i < 2; ++i) {
      double z = alpha / (2 * w[i]) + beta * w[i] / 2, wd = w[i] * std::sqrt(1 - z * z);
      double f = sign[i] / std::sqrt(2.0);
      double q = f / (w[i] * w[i]) * (1 - std::exp(-z * w[i] * t) * (std::cos(wd * t) + z * w[i] / wd * std::sin(wd * t)));
      x[0] += q / std::sqrt(2.0), x[1] += sign[i] * q / std::sqrt(2.0);
    }
    EXPECT_NEAR(row[1], x[0], 1e-13) << "x1 at t = " << t;
    EXPECT_NEAR(row[2], x[1], 1e-13) << "x2 at t = " << t;
  }
}

// The defaults, rows 0.01 s apart up to 10 s, against the tuned absorber on time scales s: at
// 1e6 its rows skip 1e4 periods, at 1e-6 its 10 s show nothing of a mode of 1e5 s; each says
// so, with the interval or the end that would show the motion, and nothing is said once given.
TEST(LinearCommand, AResponseWarnsWhereItsDefaultTimesMissTheMotion) {
  const double k1 = 1000, k2 = 82.6446, d = 2;
  auto run = [&](double s, const std::string& times) {
    std::string set = fmt::format(" --set k1={:.17g} --set k2={:.17g} --set d={:.17g}", k1 * s * s, k2 * s * s, d * s);
    std::string csv = temporary_directory() + "/response.csv";
    return run_eomgen("linear '" + model_path("damped_two_mass_oscillator") + "' --at x1=0 --at x2=0 --response step:F -o '" +
                      csv + "'" + set + times);
  };
  CommandOutput fast = run(1e6, ""), slow = run(1e-6, ""), unit = run(1, "");
  for (const CommandOutput* r : {&fast, &slow, &unit}) ASSERT_EQ(r->status, 0) << r->err;
  EXPECT_NE(fast.err.find("longer than half the period of the fastest mode"), std::string::npos) << fast.err;
  EXPECT_EQ(fast.err.find("the response ends"), std::string::npos) << fast.err;
  EXPECT_NE(slow.err.find("the response ends at t = 10 s"), std::string::npos) << slow.err;
  EXPECT_EQ(slow.err.find("longer than half"), std::string::npos) << slow.err;
  EXPECT_EQ(unit.err.find("warning"), std::string::npos) << unit.err;
  EXPECT_EQ(run(1e6, " --dt-out 1e-8 --t-end 1e-5").err.find("warning"), std::string::npos);
  EXPECT_EQ(run(1e-6, " --t-end 1e6 --dt-out 1e3").err.find("warning"), std::string::npos);
}

TEST(LinearCommand, FreeImpulseAndHarmonicResponses) {
  // free: x(t) = Φ(t) x0, the first column of Φ scaled; impulse: Φ(t) B, the fourth column
  JsonValue json = run_json("linear '" + model_path("two_mass_chain") + "' --at x1=0 --at x2=0 --times 0.7");
  auto Phi = matrix_at(json, 0);
  auto free = response("--response initial --initial x1=0.01 --t-end 0.7 --dt-out 0.7");
  auto impulse = response("--response impulse:F --t-end 0.7 --dt-out 0.7");
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(free.back()[1 + i], 0.01 * Phi[i][0], 1e-14);
    EXPECT_NEAR(impulse.back()[1 + i], Phi[i][3], 1e-12);
  }
  // sin(5t) against the simulation of the same (linear) model with a tight tolerance
  auto harmonic = response("--response harmonic:F:5 --t-end 4 --dt-out 0.5");
  std::string csv = temporary_directory() + "/simulated.csv";
  CommandOutput sim = run_eomgen("simulate '" + model_path("two_mass_chain") + "' --initial x1=0 --input 'F=sin(5*t)' "
                                 "--t-end 4 --dt-out 0.5 --integrator cvode-bdf --rtol 1e-12 --atol 1e-15 -o '" + csv + "'");
  ASSERT_EQ(sim.status, 0) << sim.err;
  auto simulated = read_numeric_csv(csv);
  ASSERT_EQ(harmonic.size(), simulated.size());
  for (std::size_t k = 0; k < harmonic.size(); ++k)
    for (int i = 1; i <= 4; ++i) EXPECT_NEAR(harmonic[k][i], simulated[k][i], 1e-9) << "t = " << harmonic[k][0];
}

TEST(LinearCommand, ModeShapeAndBodeCharts) {
  std::string dir = temporary_directory();
  CommandOutput r = run_eomgen("linear '" + model_path("cart_pendulum") + "' --at x=0 --at theta=0 --bode F:x --plot '" + dir +
                               "/cart.png'");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* chart : {"/cart_modes.png", "/cart_shapes.png", "/cart_bode_F_x.png"})
    EXPECT_GT(read_file(dir + chart).size(), 1000u) << chart << "\n" << r.err;
  CommandOutput alone = run_eomgen("linear '" + model_path("cart_pendulum") + "' --at x=0 --at theta=0 --bode F:x");
  EXPECT_EQ(alone.status, 2);
  EXPECT_NE(alone.err.find("--bode needs --plot"), std::string::npos) << alone.err;
}

TEST(LinearCommand, InputsAsFunctionsOfTime) {
  // a unit step at t = 2 is the step response delayed by 2; 0.5*impulse(0) halves the impulse response
  auto step = response("--response step:F --t-end 3 --dt-out 0.5");
  auto delayed = response("--input 'F=step(2)' --t-end 5 --dt-out 0.5");
  ASSERT_EQ(delayed.size(), 11u);
  for (std::size_t k = 0; k < delayed.size(); ++k)
    for (int i = 1; i <= 4; ++i)
      EXPECT_NEAR(delayed[k][i], k < 4 ? 0.0 : step[k - 4][i], 1e-15) << "t = " << delayed[k][0];
  auto impulse = response("--response impulse:F --t-end 1 --dt-out 0.5");
  auto half = response("--input 'F=0.5*impulse(0)' --t-end 1 --dt-out 0.5");
  for (std::size_t k = 0; k < half.size(); ++k)
    for (int i = 1; i <= 4; ++i) EXPECT_NEAR(half[k][i], 0.5 * impulse[k][i], 1e-15);
  // 2 cos(5t) against the simulation of the same linear model
  auto cosine = response("--input 'F=2*cos(5*t)' --t-end 3 --dt-out 0.5");
  std::string csv = temporary_directory() + "/simulated.csv";
  CommandOutput sim = run_eomgen("simulate '" + model_path("two_mass_chain") + "' --initial x1=0 --input 'F=2*cos(5*t)' "
                                 "--t-end 3 --dt-out 0.5 --integrator cvode-bdf --rtol 1e-12 --atol 1e-15 -o '" + csv + "'");
  ASSERT_EQ(sim.status, 0) << sim.err;
  auto simulated = read_numeric_csv(csv);
  for (std::size_t k = 0; k < cosine.size(); ++k)
    for (int i = 1; i <= 4; ++i) EXPECT_NEAR(cosine[k][i], simulated[k][i], 1e-9) << "t = " << cosine[k][0];
  CommandOutput wrong = run_eomgen("linear '" + model_path("two_mass_chain") + "' --at x1=0 --at x2=0 --input 'F=t^2'");
  EXPECT_EQ(wrong.status, 2);
  EXPECT_NE(wrong.err.find("expected A*step(T0), A*impulse(T0), A*sin(W*t) or A*cos(W*t)"), std::string::npos) << wrong.err;
}

// models/car_braking.toml at rest on time scales T from 1e-12 to 1e12 s (small_models.hpp): its
// D is cf/kf T K = cr/kr T K exactly, and the fit says so, α = 0 rather than the 1.5e-15 that
// least squares leaves in rounding.
TEST(LinearCommand, RayleighDampingHasNoCoefficientFromRounding) {
  const BrakingCar car;
  ASSERT_EQ(car.cf / car.kf, car.cr / car.kr);
  for (double T : {1e-12, 1e-6, 1.0, 1e6, 1e12}) {
    JsonValue r = run_json(fmt::format("linear '{}' {}", model_path("car_braking"), car.on_time_scale(T)));
    ASSERT_NE(r.find("damping"), nullptr) << "T = " << T;
    const JsonValue& damping = *r.find("damping");
    EXPECT_EQ(damping.find("kind")->text, "proportional") << "T = " << T;
    EXPECT_EQ(at(damping, "rayleigh_alpha"), 0) << "T = " << T;
    EXPECT_NEAR(at(damping, "rayleigh_beta") / (car.cf / car.kf * T), 1, 1e-12) << "T = " << T;
  }
}

// The same car with its free position and speed in the state (x' = v, v' = 0 at rest: a double zero
// in one Jordan block) and its pitch's response to the braking force F: at T = 1e12 s the
// balancing had kept x' = 1 · v beside rates of 1e-12 1/s, so that every eigenvalue fell in one
// cluster ("algebraic 6, Jordan blocks [2, 1, 1, 1, 1]") and G(s) was called identically zero.
// F enters θ's equation as −h F, and heave and pitch are coupled, so by Cramer's rule
// G(s) = −h (m s² + (cf + cr) s + kf + kr) / det: its zeros are the heave's own roots and its gain
// (the s² over s⁴ coefficients) −h m / (m Iyy).
TEST(LinearCommand, AFreePositionBesideSlowModesKeepsTheirStructureAndTransferFunction) {
  const BrakingCar car;
  double damping = (car.cf + car.cr) / car.m, stiffness = (car.kf + car.kr) / car.m;
  double zero_re = -damping / 2, zero_im = std::sqrt(stiffness - damping * damping / 4);
  for (double T : {1e-12, 1e-6, 1.0, 1e6, 1e12}) {
    JsonValue r = run_json(fmt::format("linear '{}' --transfer F:theta {}", model_path("car_braking"), car.on_time_scale(T)));
    std::vector<std::vector<double>> blocks;
    for (const JsonValue& e : r.find("eigenvalues")->items) {
      blocks.emplace_back();
      for (const JsonValue& b : e.find("jordan_blocks")->items) blocks.back().push_back(b.value);
    }
    EXPECT_EQ(blocks, (std::vector<std::vector<double>>{{2}, {1}, {1}, {1}, {1}})) << "T = " << T;
    const JsonValue& G = r.find("transfer_functions")->items.at(0);
    EXPECT_EQ(G.find("constant")->kind, JsonValue::boolean) << "T = " << T;
    EXPECT_FALSE(G.find("constant")->truth) << "T = " << T;
    ASSERT_EQ(G.find("zeros")->items.size(), 2u) << "T = " << T;
    for (const JsonValue& z : G.find("zeros")->items) {
      EXPECT_NEAR(z.items.at(0).value * T / zero_re, 1, 1e-9) << "T = " << T;
      EXPECT_NEAR(std::abs(z.items.at(1).value) * T / zero_im, 1, 1e-9) << "T = " << T;
    }
    EXPECT_NEAR(at(G, "gain") / (-car.h / car.Iyy), 1, 1e-9) << "T = " << T;
  }
}

TEST(LinearCommand, TextNamesTheModesAndMistakesAreRefused) {
  CommandOutput r = run_eomgen("linear '" + model_path("two_mass_chain") + "' --at x1=0 --at x2=0");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("mode 1: ω = 10 rad/s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("damping: proportional (Rayleigh)"), std::string::npos) << r.out;
  CommandOutput bad = run_eomgen("linear '" + model_path("two_mass_chain") + "' --times 1,x");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("'x' is not a number"), std::string::npos) << bad.err;
  CommandOutput unknown = run_eomgen("linear '" + model_path("two_mass_chain") + "' --at x1=0 --at x2=0 --transfer G:x9");
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.err.find("G, x9: not an input, a state or an output"), std::string::npos) << unknown.err;
  CommandOutput response = run_eomgen("linear '" + model_path("two_mass_chain") + "' --at x1=0 --at x2=0 --response ramp:F");
  EXPECT_EQ(response.status, 2);
  EXPECT_NE(response.err.find("expected initial, impulse:INPUT, step:INPUT or harmonic:INPUT:OMEGA"), std::string::npos);
}

// C of an output that varies over its own scale: a plate's capacitance eA/(d − x) across gaps d from
// 1e-12 to 1e6 m, whose slope at x = 0 is eA/d²; a fixed step of 1e-6 crossed the micrometre gap
TEST(LinearCommand, AnOutputIsDifferentiatedOnItsOwnScale) {
  std::string model = write_model("mems_plate", R"toml(
[model]
name = "mems_plate"
title = "A plate on a spring across a gap"
[parameters]
m = 1e-9
k = 1.0
d = 1e-6
eA = 1e-15
[coordinates]
x = 0.0
[[particles]]
name = "plate"
mass = "m"
position = ["x", "0", "0"]
[energy]
potential = "k*x^2/2"
[outputs]
capacitance = "eA/(d - x)"
)toml");
  for (double d : {1e-12, 1e-6, 1.0, 1e6}) {
    JsonValue json = run_json(fmt::format("linear '{}' --set d={}", model, d));
    const JsonValue* C = json.find("C");
    ASSERT_TRUE(C) << "d = " << d;
    EXPECT_NEAR(C->items.at(0).items.at(0).value, 1e-15 / (d * d), 1e-8 * 1e-15 / (d * d)) << "d = " << d;
    EXPECT_EQ(C->items.at(0).items.at(1).value, 0.0) << "it does not depend on the velocity";
  }
}

}  // namespace
}  // namespace eomgen::test
