#include "symbolic/clamp.hpp"

namespace eomgen {

using GiNaC::ex;
using GiNaC::numeric;

namespace {

bool real_number(const ex& x) { return GiNaC::is_a<numeric>(x) && GiNaC::ex_to<numeric>(x).is_real(); }

ex clamp_eval(const ex& x, const ex& lo, const ex& hi) {
  if (real_number(x) && real_number(lo) && real_number(hi)) {
    const numeric &v = GiNaC::ex_to<numeric>(x), &a = GiNaC::ex_to<numeric>(lo), &b = GiNaC::ex_to<numeric>(hi);
    return v < a ? a : (b < v ? b : v);
  }
  return clamp(x, lo, hi).hold();
}

ex clamp_evalf(const ex& x, const ex& lo, const ex& hi) { return clamp_eval(x.evalf(), lo.evalf(), hi.evalf()); }

ex clamp_derivative(const ex& x, const ex& lo, const ex& hi, unsigned which) {
  if (which == 0) return 1 - below(x, lo) - below(hi, x);
  return which == 1 ? below(x, lo) : below(hi, x);
}

ex below_eval(const ex& a, const ex& b) {
  if (real_number(a) && real_number(b)) return GiNaC::ex_to<numeric>(a) < GiNaC::ex_to<numeric>(b) ? 1 : 0;
  return below(a, b).hold();
}

ex below_evalf(const ex& a, const ex& b) { return below_eval(a.evalf(), b.evalf()); }

ex below_derivative(const ex&, const ex&, unsigned) { return 0; }

}  // namespace

REGISTER_FUNCTION(clamp, eval_func(clamp_eval).evalf_func(clamp_evalf).derivative_func(clamp_derivative))
REGISTER_FUNCTION(below, eval_func(below_eval).evalf_func(below_evalf).derivative_func(below_derivative))

}  // namespace eomgen
