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

ex sign_eval(const ex& x) {
  if (real_value(x)) return GiNaC::ex_to<numeric>(x).csgn();
  return sign(x).hold();
}

ex sign_evalf(const ex& x) { return sign_eval(x.evalf()); }

ex sign_derivative(const ex&, unsigned) { return 0; }

}  // namespace

REGISTER_FUNCTION(magnitude, eval_func(magnitude_eval).evalf_func(magnitude_evalf).derivative_func(magnitude_derivative))
REGISTER_FUNCTION(sign, eval_func(sign_eval).evalf_func(sign_evalf).derivative_func(sign_derivative))

}  // namespace eomgen
