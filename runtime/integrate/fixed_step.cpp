/// @file Fixed-step integrators: the classical fourth-order Runge–Kutta method,
/// Störmer–Verlet (leapfrog, kick–drift–kick) on x = [q; v] or, for Hamilton's
/// equations with a separable H = T(p) + V(q), on x = [q; p], and the implicit
/// two-stage Gauss–Legendre method (integrate/gauss_legendre.cpp). Verlet is
/// symplectic when the acceleration depends on q alone (conservative forces,
/// constant mass matrix), and symmetric and of second order in general.
#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "integrate/gauss_legendre.hpp"
#include "integrate/stepper.hpp"

namespace eomgen::runtime {
namespace {

enum class Method { rk4, verlet, canonical_verlet, gauss_legendre };

const char* title(Method m) {
  switch (m) {
    case Method::rk4: return "RK4";
    case Method::verlet: return "Störmer–Verlet";
    case Method::canonical_verlet: return "Störmer–Verlet in canonical variables";
    case Method::gauss_legendre: return "Gauss–Legendre";
  }
  return "";
}

class FixedStep : public Stepper {
 public:
  FixedStep(RightHandSide& f, const std::vector<double>& x0, const SimulationSettings& s, Method method)
      : f_(f), x_(x0), t_(s.t_start), h_(s.step > 0 ? s.step : s.dt_out / 10), method_(method), gauss_(x0.size()) {
    started_ = std::chrono::steady_clock::now();
  }

  bool advance(double t_out, std::vector<double>& x) override {
    while (t_ < t_out) {
      // land exactly on the output time; a step within roundoff of it is merged
      double h = std::min(h_, t_out - t_);
      if (within_roundoff(t_out - (t_ + h), t_out)) h = t_out - t_;
      bool projected = true;
      if (!take_step(h) ||
          !(projected = !f_.projection || f_.projection->project(t_ + h, x_.data()))) {
        x = x_;
        failure_time = t_;
        flag = -1;
        reason = fmt::format("{} stopped: {}", title(method_),
                             !projected ? "the projection onto the constraints failed (Newton's method did not converge)"
                             : method_ == Method::gauss_legendre && !f_.saw_non_finite()
                                 ? "Newton's method on the stage equations did not converge (try a smaller --step)"
                                 : "the right-hand side is not finite");
        return false;
      }
      t_ = within_roundoff(t_out - (t_ + h), t_out) ? t_out : t_ + h;
      ++steps_;
    }
    x = x_;
    return true;
  }

  // a remainder to the output time that is roundoff of the times or the step, not time: against
  // one second, a system on a time scale of 1e-12 s had its steps of 1e-14 s merged into the
  // output interval's 1e-13 s, ten steps into one, and rk4 came out 1e4 times less accurate
  bool within_roundoff(double remaining, double t_out) const {
    return remaining < 1e-12 * std::max({std::abs(t_out), std::abs(t_), h_});
  }

  SolverStatistics statistics() const override {
    SolverStatistics s;
    s.steps = steps_;
    s.rhs_evaluations = f_.evaluations();
    s.jacobian_evaluations = gauss_.jacobian_evaluations();
    s.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    return s;
  }

 private:
  bool take_step(double h) {
    switch (method_) {
      case Method::rk4: return rk4_step(h);
      case Method::verlet: return verlet_step(h);
      case Method::canonical_verlet: return canonical_verlet_step(h);
      case Method::gauss_legendre: return gauss_.step(f_, t_, h, x_);
    }
    return false;
  }

  bool rk4_step(double h) {
    std::size_t n = x_.size();
    std::vector<double> k1(n), k2(n), k3(n), k4(n), y(n);
    auto stage = [&](const std::vector<double>& k, double scale) {
      for (std::size_t i = 0; i < n; ++i) y[i] = x_[i] + scale * k[i];
    };
    if (f_(t_, x_.data(), k1.data())) return false;
    stage(k1, h / 2);
    if (f_(t_ + h / 2, y.data(), k2.data())) return false;
    stage(k2, h / 2);
    if (f_(t_ + h / 2, y.data(), k3.data())) return false;
    stage(k3, h);
    if (f_(t_ + h, y.data(), k4.data())) return false;
    for (std::size_t i = 0; i < n; ++i) x_[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    return true;
  }

  // kick (h/2, explicit) – drift (h) – kick (h/2, implicit): v½ = v + h/2 a(q, v),
  // q' = q + h v½, v' = v½ + h/2 a(q', v'). With a = a(q) this is Störmer–Verlet; when
  // the accelerations depend on the velocities (a mass matrix M(q) brings q'² terms)
  // the last kick is solved by fixed-point iteration, which keeps the method symmetric
  // and of second order (an explicit last kick at v½ would be of first order only)
  bool verlet_step(double h) {
    std::size_t n = x_.size(), half = n / 2;
    std::vector<double> xdot(n), v_half(half);
    if (f_(t_, x_.data(), xdot.data())) return false;
    for (std::size_t i = 0; i < half; ++i) v_half[i] = x_[half + i] + h / 2 * xdot[half + i];
    for (std::size_t i = 0; i < half; ++i) x_[i] += h * v_half[i];
    for (std::size_t i = 0; i < half; ++i) x_[half + i] = v_half[i];
    for (int iteration = 0; iteration < 8; ++iteration) {
      if (f_(t_ + h, x_.data(), xdot.data())) return false;
      double change = 0, size = 0;
      for (std::size_t i = 0; i < half; ++i) {
        double v = v_half[i] + h / 2 * xdot[half + i];
        change = std::max(change, std::abs(v - x_[half + i]));
        size = std::max(size, std::abs(v));
        x_[half + i] = v;
      }
      if (change <= 1e-15 * std::max(size, 1e-300)) break;
    }
    return true;
  }

  // x = [q; p] with q' = ∂H/∂p(p) and p' = −∂H/∂q(q, t): kick p by h/2, drift q by h with
  // q'(p½), kick p by h/2 at the new q. Explicit and symplectic for a separable H.
  bool canonical_verlet_step(double h) {
    std::size_t n = x_.size(), half = n / 2;
    std::vector<double> xdot(n);
    if (f_(t_, x_.data(), xdot.data())) return false;
    for (std::size_t i = 0; i < half; ++i) x_[half + i] += h / 2 * xdot[half + i];
    if (f_(t_ + h / 2, x_.data(), xdot.data())) return false;
    for (std::size_t i = 0; i < half; ++i) x_[i] += h * xdot[i];
    if (f_(t_ + h, x_.data(), xdot.data())) return false;
    for (std::size_t i = 0; i < half; ++i) x_[half + i] += h / 2 * xdot[half + i];
    return true;
  }

  RightHandSide& f_;
  std::vector<double> x_;
  double t_, h_;
  Method method_;
  GaussLegendreStep gauss_;
  long steps_ = 0;
  std::chrono::steady_clock::time_point started_;
};

}  // namespace

std::unique_ptr<Stepper> make_fixed_step(RightHandSide& f, const std::vector<double>& x0, const SimulationSettings& s) {
  Method method = s.integrator == "gauss-legendre" ? Method::gauss_legendre
                  : s.integrator != "verlet"       ? Method::rk4
                  : std::string(f.problem().model->method) == "hamilton" ? Method::canonical_verlet
                                                                         : Method::verlet;
  return std::make_unique<FixedStep>(f, x0, s, method);
}

}  // namespace eomgen::runtime
