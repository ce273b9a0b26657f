#include "symbolic/magnitude.hpp"

namespace eomgen {

using GiNaC::ex;
using GiNaC::numeric;

namespace {

bool real_value(const ex& x) { return GiNaC::is_a<numeric>(x) && GiNaC::ex_to<numeric>(x).is_real(); }

ex magnitude_eval(const ex& x) {
  if (GiNaC::is_a<numeric>(x)) return GiNaC::abs(GiNaC::ex_to<numeric>(x));
  return magnitude(x).hold();
}

ex magnitude_evalf(const ex& x) { return magnitude_eval(x.evalf()); }

ex magnitude_derivative(const ex& x, unsigned) { return sign(x); }

// |x|^(2k) = x^(2k) for a real x: a rotation angle's derivative holds 1/(u + |w|²), which is u + w²
ex magnitude_power(const ex& x, const ex& exponent) {
  if (GiNaC::is_a<numeric>(exponent) && GiNaC::ex_to<numeric>(exponent).is_even()) return GiNaC::pow(x, exponent);
  return GiNaC::power(magnitude(x), exponent).hold();
}

ex sign_eval(const ex& x) {
  if (real_value(x)) return GiNaC::ex_to<numeric>(x).csgn();
  return sign(x).hold();
}

ex sign_evalf(const ex& x) { return sign_eval(x.evalf()); }

ex sign_derivative(const ex&, unsigned) { return 0; }

}  // namespace

REGISTER_FUNCTION(magnitude, eval_func(magnitude_eval)
                                 .evalf_func(magnitude_evalf)
                                 .derivative_func(magnitude_derivative)
                                 .power_func(magnitude_power))
REGISTER_FUNCTION(sign, eval_func(sign_eval).evalf_func(sign_evalf).derivative_func(sign_derivative))

}  // namespace eomgen
