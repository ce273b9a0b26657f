#include "analyse/step_stability.hpp"

#include <cmath>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "analyse/first_order_form.hpp"
#include "analyse/system_scales.hpp"

namespace eomgen::runtime {

namespace {

// the largest r with r·direction inside the region, by bisection (the regions of both
// methods meet every ray from the origin in one interval)
double limit_along(const std::string& integrator, std::complex<double> direction) {
  double inside = 0, outside = 8;
  for (int k = 0; k < 60; ++k) {
    double mid = (inside + outside) / 2;
    (inside_stability_region(integrator, mid * direction) ? inside : outside) = mid;
  }
  return inside;
}

}  // namespace

bool inside_stability_region(const std::string& integrator, std::complex<double> z) {
  if (integrator == "verlet") return std::abs(z) < 2;  // h ω < 2 for the oscillation ω = |λ|
  std::complex<double> r = 1.0 + z + z * z / 2.0 + z * z * z / 6.0 + z * z * z * z / 24.0;
  return std::abs(r) <= 1 + 1e-12;
}

StepStability check_step(const Problem& p, const std::string& integrator, double h, double t, const std::vector<double>& x) {
  Eigen::MatrixXd J = state_jacobian(p, t, x);
  StepStability s;
  s.largest_stable_step = INFINITY;
  if (integrator == "gauss-legendre" || !J.allFinite()) return s;  // A-stable: no limit for Re λ ≤ 0
  double worst = 0;
  for (std::complex<double> lambda : balanced_eigenvalues(J)) {
    double size = std::abs(lambda);
    if (size == 0 || lambda.real() > 1e-9 * size) continue;  // a mode that grows by itself
    if (lambda.real() > 0) lambda.real(0);  // on the axis within rounding
    double limit = limit_along(integrator, lambda / size);
    s.largest_stable_step = std::min(s.largest_stable_step, limit / size);
    double excess = h * size / limit;
    if (excess > worst) {
      worst = excess;
      s.eigenvalue = lambda, s.h_lambda = h * size, s.limit = limit;
    }
  }
  s.beyond = worst > 1;
  return s;
}

std::string step_stability_warning(const std::string& integrator, double h, const StepStability& s, double t) {
  std::complex<double> l = s.eigenvalue;
  std::string mode = std::abs(l.imag()) > 0 ? fmt::format("{:.4g} ± {:.4g}i", l.real() + 0.0, std::abs(l.imag()))
                                            : fmt::format("{:.4g}", l.real());
  return fmt::format("the step h = {:g} s of {} is beyond its stability limit at t = {:g}: h·|λ| = {:.3g} for the mode "
                     "λ = {} 1/s, where the method is stable up to {:.3g}{}; the numerical solution grows although the "
                     "motion does not. The largest stable step here is {:.3g} s (use --step, or an adaptive integrator)",
                     h, integrator, t, s.h_lambda, mode, s.limit,
                     std::abs(l.real()) <= 1e-9 * std::abs(l) ? " on the imaginary axis" : " in its direction",
                     s.largest_stable_step);
}

}  // namespace eomgen::runtime
