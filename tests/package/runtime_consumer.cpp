// A program that uses eomgen::runtime from an install tree on a generated header: the large
// swing of the pendulum (phi0 = 1.2) integrated by CVODE for one period, which returns it to
// phi0 at rest; the period from the closed form T = 4 K(sin(phi0/2)) sqrt(l/g), K by the
// arithmetic-geometric mean. Then the linearization at the bottom, eigenvalues ±i sqrt(g/l),
// and the energy, the model's first integral.
#include <cmath>
#include <complex>
#include <cstdio>

#include <eomgen/runtime.hpp>

#include "swing.hpp"

EOMGEN_MODEL_FUNCTION(swing_model, swing)

namespace {

// K(k) = π / (2 AGM(1, sqrt(1 − k²)))
double complete_elliptic_k(double k) {
  double a = 1, b = std::sqrt(1 - k * k);
  for (int i = 0; i < 40; ++i) {
    double next = (a + b) / 2;
    b = std::sqrt(a * b), a = next;
  }
  return M_PI / (2 * a);
}

bool check(const char* what, double value, double expected, double tolerance) {
  bool ok = std::fabs(value - expected) <= tolerance;
  std::printf("%s: %.15g (expected %.15g) %s\n", what, value, expected, ok ? "ok" : "WRONG");
  return ok;
}

}  // namespace

int main() {
  namespace rt = eomgen::runtime;
  const eomgen_model_abi& model = *swing_model();
  rt::Problem problem = rt::default_problem(model);
  std::vector<double> x0 = rt::default_state(model);
  const double m = 1.5, l = 0.8, g = 9.81, phi0 = 1.2;
  double period = 4 * complete_elliptic_k(std::sin(phi0 / 2)) * std::sqrt(l / g);

  rt::SimulationSettings settings;
  settings.integrator = "cvode-bdf";
  settings.rtol = 1e-11, settings.atol = 1e-13;
  settings.t_end = period, settings.dt_out = period / 4;
  rt::SimulationResult run = rt::simulate(problem, x0, settings);
  if (run.failed) {
    std::printf("the run failed: %s\n", run.failure.c_str());
    return 1;
  }
  const std::vector<double>& end = run.trajectory.states.back();
  bool ok = check("phi after one period", end[0], phi0, 1e-8);
  ok = check("der(phi) after one period", end[1], 0.0, 1e-8) && ok;

  rt::StabilityReport at_rest = rt::analyse_stability(problem, {0.0, 0.0});
  ok = check("eigenvalue at the bottom, imaginary part", std::fabs(at_rest.eigenvalues.front().imag()), std::sqrt(g / l), 1e-9) && ok;
  ok = check("eigenvalue at the bottom, real part", at_rest.eigenvalues.front().real(), 0.0, 1e-9) && ok;

  std::vector<double> integrals = rt::first_integrals_at(problem, 0.0, x0);
  ok = check("energy at the start", integrals.empty() ? NAN : integrals[0], -m * g * l * std::cos(phi0), 1e-12) && ok;
  std::printf("eomgen::runtime: %s\n", ok ? "the swing agrees with the closed forms" : "MISMATCH");
  return ok ? 0 : 1;
}
