/// @file Reference solutions: a generated header's rhs instantiated with a wide
/// scalar (__float128 through libquadmath when EOMGEN_WITH_QUADMATH is defined,
/// long double otherwise) and integrated by Gragg–Bulirsch–Stoer extrapolation
/// with fixed macro steps. Self-contained (the C++17 standard library and, with
/// quadmath, libquadmath): the compile cache writes it beside each driver.
///
/// Why extrapolation rather than an implicit Gauss–Legendre method: it is explicit,
/// so every step costs a fixed number of right-hand sides and no Newton iteration has
/// to converge in 113-bit arithmetic; with the step-number sequence 2, 4, …, 16 it is
/// of order 16, so a modest macro step already gives errors far below 1e-13 on smooth
/// problems, and halving the step shows the error of the coarser run directly.
#ifndef EOMGEN_REFERENCE_SOLUTION_HPP
#define EOMGEN_REFERENCE_SOLUTION_HPP

#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

#ifdef EOMGEN_WITH_QUADMATH
#include <quadmath.h>
#endif

namespace eomgen::reference {

#ifdef EOMGEN_WITH_QUADMATH
/// __float128 as a class, so that the generated code's unqualified sin, cos, … find
/// the quadmath functions by argument-dependent lookup.
class Wide {
 public:
  Wide() = default;
  template <class Number, class = std::enable_if_t<std::is_arithmetic_v<Number>>>
  explicit Wide(Number v) : v_(static_cast<__float128>(v)) {}
  static Wide of(__float128 v) {
    Wide w;
    w.v_ = v;
    return w;
  }
  __float128 raw() const { return v_; }
  double to_double() const { return static_cast<double>(v_); }
  friend Wide operator+(Wide a, Wide b) { return of(a.v_ + b.v_); }
  friend Wide operator-(Wide a, Wide b) { return of(a.v_ - b.v_); }
  friend Wide operator*(Wide a, Wide b) { return of(a.v_ * b.v_); }
  friend Wide operator/(Wide a, Wide b) { return of(a.v_ / b.v_); }
  friend Wide operator-(Wide a) { return of(-a.v_); }
  friend Wide sin(Wide a) { return of(sinq(a.v_)); }
  friend Wide cos(Wide a) { return of(cosq(a.v_)); }
  friend Wide tan(Wide a) { return of(tanq(a.v_)); }
  friend Wide asin(Wide a) { return of(asinq(a.v_)); }
  friend Wide acos(Wide a) { return of(acosq(a.v_)); }
  friend Wide atan(Wide a) { return of(atanq(a.v_)); }
  friend Wide atan2(Wide y, Wide x) { return of(atan2q(y.v_, x.v_)); }
  friend Wide sinh(Wide a) { return of(sinhq(a.v_)); }
  friend Wide cosh(Wide a) { return of(coshq(a.v_)); }
  friend Wide tanh(Wide a) { return of(tanhq(a.v_)); }
  friend Wide exp(Wide a) { return of(expq(a.v_)); }
  friend Wide log(Wide a) { return of(logq(a.v_)); }
  friend Wide sqrt(Wide a) { return of(sqrtq(a.v_)); }
  friend Wide pow(Wide a, Wide b) { return of(powq(a.v_, b.v_)); }
  friend Wide abs(Wide a) { return of(fabsq(a.v_)); }
  // for a model's clamp(x, lo, hi)
  friend bool operator<(Wide a, Wide b) { return a.v_ < b.v_; }
  friend bool operator>(Wide a, Wide b) { return a.v_ > b.v_; }

 private:
  __float128 v_ = 0;
};
inline double to_double(Wide w) { return w.to_double(); }
inline constexpr const char* wide_scalar_name = "__float128 (libquadmath, 113-bit mantissa)";
}  // namespace eomgen::reference

/// Wide's width, so that a generated header's constants that no small fraction states
/// (detail::constant) reach it to 113 bits instead of as doubles.
namespace std {
template <>
struct numeric_limits<eomgen::reference::Wide> {
  static constexpr bool is_specialized = true;
  static constexpr int digits = 113;
};
}  // namespace std

namespace eomgen::reference {
#else
using Wide = long double;
inline double to_double(Wide w) { return static_cast<double>(w); }
inline constexpr const char* wide_scalar_name = "long double";
#endif

/// x' = rhs(t, x) in the wide scalar; `rhs` writes xdot.
template <class Rhs>
class Extrapolation {
 public:
  static constexpr int columns = 8;  // step numbers 2, 4, …, 16: order 16

  Extrapolation(Rhs rhs, std::size_t size) : rhs_(rhs), n_(size), f0_(size), table_(columns, std::vector<Wide>(size)) {}

  /// One macro step of length H from (t, x); x is replaced by the extrapolated value.
  void step(Wide t, Wide H, std::vector<Wide>& x) {
    rhs_(t, x.data(), f0_.data());
    ++evaluations_;
    std::vector<Wide> current(n_), next(n_);
    for (int j = 0; j < columns; ++j) {
      midpoint(t, H, 2 * (j + 1), x, current);  // T_j,0
      // Aitken–Neville in h²: T_j,k = T_j,k−1 + (T_j,k−1 − T_j−1,k−1) / ((n_j / n_j−k)² − 1),
      // with table_[k] holding row j−1 until it is overwritten by row j
      for (int k = 1; k <= j; ++k) {
        Wide ratio = Wide(j + 1) / Wide(j - k + 1), factor = Wide(1) / (ratio * ratio - Wide(1));
        auto& above = table_[static_cast<std::size_t>(k - 1)];
        for (std::size_t i = 0; i < n_; ++i) next[i] = current[i] + (current[i] - above[i]) * factor;
        above = current;
        std::swap(current, next);
      }
      table_[static_cast<std::size_t>(j)] = current;
    }
    x = table_[static_cast<std::size_t>(columns - 1)];
  }

  long evaluations() const { return evaluations_; }

 private:
  // Gragg's modified midpoint rule with `steps` substeps, ending with the smoothing step
  void midpoint(Wide t, Wide H, int steps, const std::vector<Wide>& x, std::vector<Wide>& out) {
    Wide h = H / Wide(steps), two_h = Wide(2) * h;
    std::vector<Wide> previous = x, current(n_), f(n_);
    for (std::size_t i = 0; i < n_; ++i) current[i] = x[i] + h * f0_[i];
    for (int m = 1; m < steps; ++m) {
      rhs_(t + Wide(m) * h, current.data(), f.data());
      ++evaluations_;
      for (std::size_t i = 0; i < n_; ++i) {
        Wide next = previous[i] + two_h * f[i];
        previous[i] = current[i];
        current[i] = next;
      }
    }
    rhs_(t + H, current.data(), f.data());
    ++evaluations_;
    for (std::size_t i = 0; i < n_; ++i) out[i] = (current[i] + previous[i] + h * f[i]) / Wide(2);
  }

  Rhs rhs_;
  std::size_t n_;
  std::vector<Wide> f0_;
  std::vector<std::vector<Wide>> table_;
  long evaluations_ = 0;
};

/// Integrates x' = rhs(t, x) from (t0, x0) to each of the `count` output times, with
/// equal macro steps of at most `step` in every output interval, and writes the states
/// (num_states each, as double) to `out`. Returns the number of right-hand sides, or
/// −1 − k when the state at output k is not finite.
template <class Rhs>
long integrate(Rhs rhs, std::size_t n, double t0, const double* x0, const double* times, std::size_t count,
               double step, double* out) {
  Extrapolation<Rhs> method(rhs, n);
  std::vector<Wide> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = Wide(x0[i]);
  double start = t0;
  for (std::size_t k = 0; k < count; ++k) {
    long steps = static_cast<long>(std::ceil((times[k] - start) / step - 1e-9));
    if (steps < 1) steps = 1;
    Wide H = (Wide(times[k]) - Wide(start)) / Wide(steps);
    for (long s = 0; s < steps; ++s) method.step(Wide(start) + Wide(s) * H, H, x);
    for (std::size_t i = 0; i < n; ++i) {
      out[k * n + i] = to_double(x[i]);
      if (!std::isfinite(out[k * n + i])) return -1 - static_cast<long>(k);
    }
    start = times[k];
  }
  return method.evaluations();
}

}  // namespace eomgen::reference

/* The reference entry point of a compiled model NAME (extern "C", looked up by name):
 *   long eomgen_reference(p, u, t0, x0, times, count, step, out) as integrate() above. */
#define EOMGEN_REFERENCE_ENTRY(NAME)                                                                        \
  extern "C" const char* eomgen_reference_scalar() { return eomgen::reference::wide_scalar_name; }          \
  extern "C" long eomgen_reference(const double* p, const double* u, double t0, const double* x0,          \
                                   const double* times, std::size_t count, double step, double* out) {       \
    namespace m = eomgen::models::NAME;                                                                     \
    using W = eomgen::reference::Wide;                                                                      \
    std::vector<W> wide_p(m::num_parameters + 1), wide_u(m::num_inputs + 1);                                \
    for (std::size_t i = 0; i < m::num_parameters; ++i) wide_p[i] = W(p[i]);                                \
    for (std::size_t i = 0; i < m::num_inputs; ++i) wide_u[i] = W(u[i]);                                    \
    auto rhs = [&](W t, const W* x, W* xdot) { m::rhs<W>(t, x, wide_u.data(), wide_p.data(), xdot); };     \
    return eomgen::reference::integrate(rhs, m::num_states, t0, x0, times, count, step, out);               \
  }

#endif
