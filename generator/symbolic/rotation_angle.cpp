#include "symbolic/rotation_angle.hpp"

#include <cmath>
#include <stdexcept>

#include "symbolic/magnitude.hpp"

namespace eomgen {

using GiNaC::ex;
using GiNaC::numeric;

namespace {

// Where u < cut a², A^(n) by its series, whose terms shrink by u / a² ≤ 0.3; above, by the recurrence
// 2u A^(m+1) = (−1)^m m! a / (u + a²)^(m+1) − (2m+1) A^(m) from A itself, which loses at most a factor
// of about 6 of its accuracy there (at u = 0.3 a², (2m+1) A^(m) / (2u A^(m+1)) ≈ 6.3 for m = 0).
template <class Number, class Ops>
Number atan_ratio_of(int n, const Number& u, const Number& a, const Ops& ops) {
  if (u < Number(3) / Number(10) * a * a) {
    Number ratio = u / (a * a), t = Number(n % 2 ? -1 : 1), inverse = Number(1) / a;
    for (int k = 2; k <= n; ++k) t = t * Number(k);
    for (int k = 0; k <= 2 * n; ++k) t = t * inverse;
    Number sum = t / Number(2 * n + 1);
    // term k: (−1)^k k!/(k−n)! u^(k−n) / ((2k+1) a^(2k+1)); stop where it no longer changes the sum
    for (int k = n + 1; k < n + 1000; ++k) {
      t = -(t * Number(k) / Number(k - n)) * ratio;
      Number next = sum + t / Number(2 * k + 1);
      if (next == sum) break;
      sum = next;
    }
    return sum;
  }
  Number s = ops.sqrt(u);
  // atan2(s, a) for a ≥ 0, s > 0, without atan2: atan(s/a), or π/2 − atan(a/s) where a ≤ s
  Number A = (s < a ? ops.atan(s / a) : ops.half_pi() - ops.atan(a / s)) / s;
  Number c = a / (u + a * a);  // (−1)^m m! a / (u + a²)^(m+1) at m = 0
  for (int m = 0; m < n; ++m) {
    A = (c - Number(2 * m + 1) * A) / (Number(2) * u);
    c = -(c * Number(m + 1)) / (u + a * a);
  }
  return A;
}

struct DoubleOps {
  double sqrt(double x) const { return std::sqrt(x); }
  double atan(double x) const { return std::atan(x); }
  double half_pi() const { return std::atan(1.0) * 2; }
};

struct NumericOps {
  numeric sqrt(const numeric& x) const { return GiNaC::sqrt(x); }
  numeric atan(const numeric& x) const { return GiNaC::atan(x); }
  numeric half_pi() const { return GiNaC::ex_to<numeric>(GiNaC::Pi.evalf()) / 2; }
};

bool order(const ex& n) {
  return GiNaC::is_a<numeric>(n) && GiNaC::ex_to<numeric>(n).is_nonneg_integer();
}

// At u = 0 the series' first term, (−1)^n n! / ((2n+1) a^(2n+1)), for any a: the value at a turn of 0
ex atan_ratio_eval(const ex& n, const ex& u, const ex& a) {
  if (order(n) && u.is_zero()) {
    int k = GiNaC::ex_to<numeric>(n).to_int();
    return GiNaC::pow(-1, k) * GiNaC::factorial(k) / ((2 * k + 1) * GiNaC::pow(a, 2 * k + 1));
  }
  return atan_ratio(n, u, a).hold();
}

ex atan_ratio_evalf(const ex& n, const ex& u, const ex& a) {
  ex uf = u.evalf(), af = a.evalf();
  if (!order(n) || !GiNaC::is_a<numeric>(uf) || !GiNaC::is_a<numeric>(af) || !GiNaC::ex_to<numeric>(uf).is_real() ||
      !GiNaC::ex_to<numeric>(af).is_real())
    return atan_ratio(n, u, a).hold();
  return atan_ratio_of(GiNaC::ex_to<numeric>(n).to_int(), GiNaC::ex_to<numeric>(uf), GiNaC::ex_to<numeric>(af), NumericOps{});
}

// ∂/∂u: the next of the family; ∂/∂a = ∂ⁿ/∂uⁿ (−1 / (u + a²)) = (−1)^(n+1) n! / (u + a²)^(n+1)
ex atan_ratio_derivative(const ex& n, const ex& u, const ex& a, unsigned parameter) {
  if (parameter == 0) return 0;
  if (!order(n)) throw std::logic_error("atan_ratio's order is not a non-negative integer");
  if (parameter == 1) return atan_ratio(n + 1, u, a);
  int k = GiNaC::ex_to<numeric>(n).to_int();
  return GiNaC::pow(-1, k + 1) * GiNaC::factorial(k) / GiNaC::pow(u + a * a, k + 1);
}

}  // namespace

// the order stays an integer under evalf: GiNaC would otherwise pass it as a float
REGISTER_FUNCTION(atan_ratio, eval_func(atan_ratio_eval)
                                  .evalf_func(atan_ratio_evalf)
                                  .do_not_evalf_params()
                                  .derivative_func(atan_ratio_derivative))

ex rotation_angle(const ex& w, const ex& x, const ex& y, const ex& z) {
  ex u = x * x + y * y + z * z;
  return 2 * GiNaC::sqrt(u) * atan_ratio(0, u, magnitude(w));
}

double atan_ratio_value(int n, double u, double a) { return atan_ratio_of(n, u, a, DoubleOps{}); }

}  // namespace eomgen
