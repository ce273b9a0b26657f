// Property-based test of the sweep's crossings and stable intervals: random families
// M q'' + D(p) q' + K q = 0 whose answers are known by construction. In modal coordinates
// mode k has ω_k and damping ratio ζ_k(p) = c_k (p − p_k), so its pair crosses the imaginary
// axis at p = p_k exactly, into the right half-plane where c_k < 0; the system is
// asymptotically stable between the largest p_k with c_k > 0 and the smallest with c_k < 0.
// The modes are hidden by a random congruence with an integer matrix T (M = Tᵀ T, K = Tᵀ Ω² T,
// D = Tᵀ 2ζΩ T keep the eigenvalues) and the system is scaled in time by s (1e-12 … 1e12) and in
// the unit of its coordinates by u (1e-6 … 1e6). Each family is a model of its own, given to
// the runtime through the model ABI the compiled headers fill in. The seed is fixed;
// EOMGEN_RANDOM_SYSTEMS=N runs N/10 families instead of 200.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <deque>
#include <random>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "analyse/eigenvalue_sweep.hpp"

namespace eomgen::test {
namespace {

using Matrix = Eigen::Matrix<double, -1, -1, Eigen::RowMajor>;

struct Family {
  Matrix M, K, D0, E;  // D(p) = D0 + p E
  std::vector<double> omega, slope, crossing;  // ω_k s, c_k, p_k
};

// the model ABI's functions are plain C functions: they read the family in hand (the sweep runs
// on the calling thread)
const Family* family = nullptr;

Matrix damping_at(const double* p) { return family->D0 + p[0] * family->E; }

Eigen::Map<const Eigen::VectorXd> positions(const double* x) { return {x, family->M.rows()}; }
Eigen::Map<const Eigen::VectorXd> velocities(const double* x) { return {x + family->M.rows(), family->M.rows()}; }

void forcing(double, const double* x, const double*, const double* p, double* out) {
  Eigen::Map<Eigen::VectorXd>(out, family->M.rows()) = -damping_at(p) * velocities(x) - family->K * positions(x);
}

void rhs(double t, const double* x, const double* u, const double* p, double* out) {
  Eigen::Index n = family->M.rows();
  Eigen::VectorXd f(n);
  forcing(t, x, u, p, f.data());
  Eigen::Map<Eigen::VectorXd>(out, n) = velocities(x);
  Eigen::Map<Eigen::VectorXd>(out + n, n) = family->M.ldlt().solve(f);
}

void jacobian_state(double, const double*, const double*, const double* p, double* out) {
  Eigen::Index n = family->M.rows();
  Matrix J = Matrix::Zero(2 * n, 2 * n);
  J.block(0, n, n, n).setIdentity();
  J.block(n, 0, n, n) = -family->M.ldlt().solve(family->K);
  J.block(n, n, n, n) = -family->M.ldlt().solve(damping_at(p));
  Eigen::Map<Matrix>(out, 2 * n, 2 * n) = J;
}

void nothing(double, const double*, const double*, const double*, double*) {}

void mass_matrix(double, const double*, const double*, double* out) {
  Eigen::Map<Matrix>(out, family->M.rows(), family->M.cols()) = family->M;
}

double kinetic_energy(double, const double* x, const double*) { return 0.5 * velocities(x).dot(family->M * velocities(x)); }
double potential_energy(double, const double* x, const double*) { return 0.5 * positions(x).dot(family->K * positions(x)); }

void linearization(double, const double*, const double*, const double* p, double* P, double* Q, double*) {
  Eigen::Index n = family->M.rows();
  Eigen::Map<Matrix>(P, n, n) = damping_at(p);
  Eigen::Map<Matrix>(Q, n, n) = family->K;
}

// the names and defaults of an n-coordinate model q1 … qn with one parameter p
struct SyntheticModel {
  std::deque<std::string> texts;
  std::vector<const char*> coordinates, states, velocity_definitions, parameters{"p"};
  std::vector<double> default_parameters{0.0}, default_state;
  std::unique_ptr<bool[]> cyclic, angle;
  eomgen_model_abi abi{};

  explicit SyntheticModel(std::size_t n) : default_state(2 * n, 0.0), cyclic(new bool[n]()), angle(new bool[n]()) {
    for (std::size_t i = 0; i < n; ++i) coordinates.push_back(texts.emplace_back(fmt::format("q{}", i + 1)).c_str());
    states = coordinates;
    for (std::size_t i = 0; i < n; ++i) {
      velocity_definitions.push_back(texts.emplace_back(fmt::format("der(q{})", i + 1)).c_str());
      states.push_back(velocity_definitions.back());
    }
    abi.abi_version = EOMGEN_MODEL_ABI_VERSION;
    abi.name = "random_family";
    abi.build_key = "";
    abi.num_coordinates = abi.num_velocities = n;
    abi.num_states = 2 * n;
    abi.num_parameters = 1;
    abi.parameter_names = parameters.data();
    abi.coordinate_names = coordinates.data();
    abi.state_names = states.data();
    abi.velocity_definitions = velocity_definitions.data();
    abi.default_parameters = default_parameters.data();
    abi.default_state = default_state.data();
    abi.is_cyclic = cyclic.get();
    abi.is_angle = angle.get();
    abi.rhs = rhs, abi.jacobian_state = jacobian_state, abi.jacobian_input = nothing, abi.forcing = forcing;
    abi.outputs = nothing;
    abi.mass_matrix = mass_matrix;
    abi.kinetic_energy = kinetic_energy, abi.potential_energy = potential_energy;
    abi.linearization = linearization;
    abi.method = "lagrange2";
  }
};

// n modes with crossings at least 0.25 apart and away from the sweep's grid (spacing 0.1)
Family random_family(std::mt19937_64& rng, std::size_t n, double s, double u) {
  std::uniform_real_distribution<double> unit(0, 1);
  Family f;
  while (f.crossing.size() < n) {
    double p = -1.8 + 3.6 * unit(rng);
    double off_grid = std::abs(p * 10 - std::round(p * 10));
    bool apart = std::all_of(f.crossing.begin(), f.crossing.end(), [&](double q) { return std::abs(p - q) > 0.25; });
    if (off_grid > 0.1 && apart) f.crossing.push_back(p);
  }
  for (std::size_t k = 0; k < n; ++k) {
    f.omega.push_back(s * (0.5 + 1.5 * unit(rng)));
    f.slope.push_back((unit(rng) < 0.5 ? -1 : 1) * (0.3 + 1.2 * unit(rng)));
  }
  Matrix T;
  std::uniform_int_distribution<int> entry(-3, 3);
  do {
    T = Matrix::NullaryExpr(Eigen::Index(n), Eigen::Index(n), [&] { return double(entry(rng)); });
  } while (std::abs(T.determinant()) < 0.5);
  Eigen::VectorXd omega = Eigen::Map<Eigen::VectorXd>(f.omega.data(), Eigen::Index(n));
  Eigen::VectorXd c = Eigen::Map<Eigen::VectorXd>(f.slope.data(), Eigen::Index(n));
  Eigen::VectorXd p = Eigen::Map<Eigen::VectorXd>(f.crossing.data(), Eigen::Index(n));
  double units = u * u;
  f.M = units * T.transpose() * T;
  f.K = units * T.transpose() * omega.array().square().matrix().asDiagonal() * T;
  // 2 ζ_k ω_k = 2 c_k (p − p_k) ω_k = p·(2 c_k ω_k) − 2 c_k p_k ω_k
  f.E = units * T.transpose() * (2 * c.array() * omega.array()).matrix().asDiagonal() * T;
  f.D0 = units * T.transpose() * (-2 * c.array() * p.array() * omega.array()).matrix().asDiagonal() * T;
  return f;
}

long family_count() {
  const char* n = std::getenv("EOMGEN_RANDOM_SYSTEMS");
  return n ? std::max(1L, std::atol(n) / 10) : 200;
}

TEST(RandomSweeps, CrossingsAndStableIntervalsAtEveryScale) {
  std::mt19937_64 rng(20261126);
  std::uniform_real_distribution<double> exponent(-1, 1);
  std::uniform_int_distribution<std::size_t> size(1, 4);
  std::atomic<bool> stop{false};
  long count = family_count(), wrong = 0;
  for (long trial = 0; trial < count && wrong < 5; ++trial) {
    double s = std::pow(10.0, 12 * exponent(rng)), u = std::pow(10.0, 6 * exponent(rng));
    std::size_t n = size(rng);
    Family f = random_family(rng, n, s, u);
    family = &f;
    SyntheticModel model(n);
    runtime::Problem problem{&model.abi, {0.0}, {}};
    runtime::StartState rest = [n](const std::vector<double>&) { return std::optional<std::vector<double>>(std::vector<double>(2 * n, 0.0)); };
    runtime::EigenvalueSweep sweep =
        runtime::sweep_eigenvalues(problem, rest, true, runtime::SweepAxis{0, -2, 2, 41}, 1e-10, 1, [](long, long) {}, stop);
    std::string at = fmt::format("family {} (n = {}, s = {:.3g}, u = {:.3g})", trial, n, s, u);
    // the crossings, in the order of the parameter, each where its mode's damping vanishes
    std::vector<std::size_t> order(n);
    for (std::size_t k = 0; k < n; ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return f.crossing[a] < f.crossing[b]; });
    bool right = sweep.crossings.size() == n;
    EXPECT_EQ(sweep.crossings.size(), n) << at;
    for (std::size_t i = 0; right && i < n; ++i) {
      std::size_t k = order[i];
      const runtime::AxisCrossing& c = sweep.crossings[i];
      bool here = std::abs(c.parameter - f.crossing[k]) <= 2 * sweep.resolution + 1e-12 && c.destabilizing == (f.slope[k] < 0) &&
                  std::abs(c.eigenvalue.imag() / f.omega[k] - 1) < 1e-6;
      EXPECT_TRUE(here) << at << ": crossing " << i << " at " << c.parameter << " (expected " << f.crossing[k] << "), Im "
                        << c.eigenvalue.imag() << " (expected " << f.omega[k] << "), destabilizing " << c.destabilizing;
      right = right && here;
    }
    // stable between the last mode that gains damping and the first that loses it
    double low = -2, high = 2;
    bool open_low = true, open_high = true;
    for (std::size_t k = 0; k < n; ++k) {
      if (f.slope[k] > 0 && f.crossing[k] > low) low = f.crossing[k], open_low = false;
      if (f.slope[k] < 0 && f.crossing[k] < high) high = f.crossing[k], open_high = false;
    }
    if (low < high) {
      bool one = sweep.stable.size() == 1;
      EXPECT_TRUE(one) << at << ": one stable interval (" << low << ", " << high << ")";
      if (one) {
        const runtime::StableInterval& i = sweep.stable[0];
        bool ends = std::abs(i.low - low) <= 2 * sweep.resolution + 1e-12 && std::abs(i.high - high) <= 2 * sweep.resolution + 1e-12 &&
                    i.open_low == open_low && i.open_high == open_high;
        EXPECT_TRUE(ends) << at << ": stable for " << i.low << " .. " << i.high << ", expected " << low << " .. " << high;
        right = right && ends;
      }
      right = right && one;
    } else {
      EXPECT_TRUE(sweep.stable.empty()) << at << ": stable nowhere";
      right = right && sweep.stable.empty();
    }
    for (int g = 0; g < 41; ++g) {
      double p = sweep.axis.value(g);
      bool inside = (open_low ? p >= low : p > low) && (open_high ? p <= high : p < high);
      std::string expected = inside ? "asymptotically_stable" : "unstable";
      if (sweep.verdicts[std::size_t(g)] != expected) {
        ADD_FAILURE() << at << ": at p = " << p << " the verdict is " << sweep.verdicts[std::size_t(g)] << ", expected " << expected;
        right = false;
      }
    }
    wrong += !right;
  }
  family = nullptr;
  EXPECT_EQ(wrong, 0) << "families with a wrong answer (the run stops after five)";
}

}  // namespace
}  // namespace eomgen::test
