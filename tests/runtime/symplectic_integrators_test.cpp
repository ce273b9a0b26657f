// The integrators in canonical variables (Hiller §3.8; Hairer, Lubich, Wanner §VI, §IX):
// the two-stage Gauss–Legendre method keeps the energy error of the pendulum in
// Hamilton's variables bounded over 1000 periods while RK4 with the same step drifts;
// it is of order 4; Störmer–Verlet on a separable H keeps the Jacobi integral of the
// bead on the rotating hoop bounded, at order 2; a coupled H is refused for Verlet.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "generated/header_registry.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

// the relative error |I(t) − I(0)| / |I(0)| of a CSV column over the rows
std::vector<double> relative_errors(const std::string& csv, const std::string& column) {
  std::string header;
  auto rows = read_numeric_csv(csv, &header);
  std::size_t index = 0;
  for (std::size_t start = 0, k = 0;; ++k) {
    std::size_t comma = header.find(',', start);
    if (header.substr(start, comma - start) == column) { index = k; break; }
    if (comma == std::string::npos) { ADD_FAILURE() << column << " not in " << header; return {}; }
    start = comma + 1;
  }
  std::vector<double> errors;
  for (const auto& row : rows) errors.push_back(std::abs(row[index] - rows[0][index]) / std::abs(rows[0][index]));
  return errors;
}

double largest(const std::vector<double>& v, std::size_t from, std::size_t to) {
  return *std::max_element(v.begin() + static_cast<long>(from), v.begin() + static_cast<long>(to));
}

std::vector<double> run(const std::string& model, const std::string& options, const std::string& column) {
  std::string csv = temporary_directory() + "/run.csv";
  CommandOutput r = run_eomgen("simulate '" + model_path(model) + "' " + options + " -o '" + csv + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  return relative_errors(csv, column);
}

TEST(SymplecticIntegrators, GaussLegendreKeepsThePendulumsEnergyOverAThousandPeriods) {
  // amplitude 0.5 rad, period about 2.04 s: 2040 s are a thousand periods, 20 steps each
  const std::string options = "--step 0.1 --t-end 2040 --dt-out 1";
  std::vector<double> gauss = run("pendulum_hamilton", "--integrator gauss-legendre " + options, "energy");
  std::vector<double> rk4 = run("pendulum_hamilton", "--integrator rk4 " + options, "energy");
  ASSERT_EQ(gauss.size(), 2041u);
  ASSERT_EQ(rk4.size(), 2041u);
  std::size_t tenth = gauss.size() / 10, n = gauss.size();
  double gauss_early = largest(gauss, 0, tenth), gauss_late = largest(gauss, n - tenth, n);
  EXPECT_LT(gauss_late, 1e-6);
  EXPECT_LT(gauss_late, 1.01 * gauss_early) << "bounded: the last hundred periods are no worse than the first";
  double rk4_early = largest(rk4, 0, tenth), rk4_late = largest(rk4, n - tenth, n);
  EXPECT_GT(rk4_late, 5 * rk4_early) << "RK4 drifts, about linearly in time";
  EXPECT_GT(rk4_late, 1000 * gauss_late);
}

TEST(SymplecticIntegrators, GaussLegendreIsOfOrderFour) {
  // the state at t = 4 against a tight adaptive run; halving the step divides the error by 2⁴
  auto final_state = [](const std::string& options) {
    std::string csv = temporary_directory() + "/order.csv";
    CommandOutput r = run_eomgen("simulate '" + model_path("spherical_pendulum_hamilton") + "' --t-end 4 --dt-out 4 " +
                                 options + " -o '" + csv + "'");
    EXPECT_EQ(r.status, 0) << r.err;
    return read_numeric_csv(csv).back();
  };
  std::vector<double> exact = final_state("--integrator cvode-bdf --rtol 1e-13 --atol 1e-14");
  auto error = [&](double h) {
    std::vector<double> x = final_state("--integrator gauss-legendre --step " + std::to_string(h));
    double e = 0;
    for (std::size_t i = 1; i <= 4; ++i) e = std::max(e, std::abs(x[i] - exact[i]));
    return e;
  };
  double coarse = error(0.04), fine = error(0.02);
  double order = std::log2(coarse / fine);
  EXPECT_GT(order, 3.8) << coarse << " " << fine;
  EXPECT_LT(order, 4.2) << coarse << " " << fine;
}

TEST(SymplecticIntegrators, VerletInCanonicalVariablesKeepsTheJacobiIntegral) {
  const std::string column = "I[jacobi_integral]";
  std::vector<double> coarse = run("bead_on_rotating_hoop_hamilton", "--integrator verlet --step 0.02 --t-end 400 --dt-out 0.5", column);
  std::vector<double> fine = run("bead_on_rotating_hoop_hamilton", "--integrator verlet --step 0.01 --t-end 400 --dt-out 0.5", column);
  std::size_t tenth = coarse.size() / 10, n = coarse.size();
  EXPECT_LT(largest(coarse, n - tenth, n), 1.05 * largest(coarse, 0, tenth)) << "bounded over the run";
  double ratio = largest(coarse, 0, n) / largest(fine, 0, n);
  EXPECT_GT(ratio, 3.6) << "second order: half the step, a quarter of the error";
  EXPECT_LT(ratio, 4.4);
}

// The spherical pendulum, and the four-link pendulum whose header solves M(q) v = p: its H couples
// q and p through M(q), and it had been declared separable (its rates, the velocities v, name no
// coordinate), so that Störmer–Verlet ran on it
TEST(SymplecticIntegrators, VerletRefusesACoupledHamiltonian) {
  for (const char* name : {"spherical_pendulum_hamilton", "n_link_pendulum_4_hamilton"}) {
    CommandOutput r = run_eomgen("simulate '" + model_path(name) + "' --integrator verlet");
    EXPECT_EQ(r.status, 2) << name;
    EXPECT_NE(r.err.find("needs a separable H = T(p) + V(q)"), std::string::npos) << name << ": " << r.err;
    EXPECT_NE(r.err.find("use gauss-legendre"), std::string::npos) << r.err;
  }
}

// Separable, H = T(p) + V(q) with forces of q alone, is ∂q'/∂q = 0 and ∂p'/∂p = 0: every Hamilton
// model of models/ declares it exactly when its generated jacobian_state has those blocks zero at
// three states and parameters about its default ones
TEST(SymplecticIntegrators, EveryHamiltonianIsDeclaredSeparableExactlyWhenItIs) {
  int hamiltonians = 0;
  for (const GeneratedModel& model : generated_models()) {
    if (std::string(model.abi->method) != "hamilton") continue;
    ++hamiltonians;
    std::size_t n = model.num_coordinates, N = model.num_states;
    bool coupled = false;
    for (int k = 1; k <= 3; ++k) {
      std::vector<double> x = model.default_state, parameters = model.default_parameters, J(N * N);
      for (std::size_t i = 0; i < N; ++i) x[i] += 0.1 * k * (1 + double(i) / double(N));
      // a damping whose default is 0 couples p' to p all the same
      for (std::size_t i = 0; i < parameters.size(); ++i) parameters[i] += 0.1 * k * (1 + double(i) / double(parameters.size()));
      model.jacobian_state(0.0, x.data(), model.default_inputs.data(), parameters.data(), J.data());
      for (std::size_t i = 0; i < N; ++i)
        for (std::size_t j = 0; j < N; ++j)
          if ((i < n) == (j < n) && J[i * N + j] != 0) coupled = true;
    }
    EXPECT_EQ(model.abi->separable_hamiltonian, !coupled) << model.name;
  }
  EXPECT_GE(hamiltonians, 6);
}

}  // namespace
}  // namespace eomgen::test
