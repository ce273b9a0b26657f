#include "symbolic/exact_double.hpp"

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace eomgen {

using GiNaC::numeric;

numeric exact_rational(double d) {
  if (d == 0) return 0;
  int e = 0;
  double m = std::frexp(d, &e);
  return numeric(static_cast<long>(std::ldexp(m, 53))) * GiNaC::pow(numeric(2), numeric(e - 53));
}

namespace {

bool even_mantissa(double d) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &d, sizeof bits);
  return (bits & 1U) == 0;
}

// CLN's double approximation, kept away from its overflow and underflow: within an ulp
double approximate(const numeric& r) {
  static const numeric tiny = GiNaC::pow(numeric(2), numeric(-1000)), scale = GiNaC::pow(numeric(2), numeric(1100));
  static const numeric negligible = GiNaC::pow(numeric(2), numeric(-2000));
  if (GiNaC::abs(r) >= tiny) return r.to_double();
  if (GiNaC::abs(r) < negligible) return 0;
  return std::ldexp((r * scale).to_double(), -1100);
}

}  // namespace

// the approximation or one of its two neighbours, compared exactly
double nearest_double(const numeric& r) {
  if (r.is_zero()) return 0;
  double guess = approximate(r), best = guess;
  numeric best_error = GiNaC::abs(r - exact_rational(guess));
  for (double candidate : {std::nextafter(guess, -DBL_MAX), std::nextafter(guess, DBL_MAX)}) {
    numeric error = GiNaC::abs(r - exact_rational(candidate));
    if (error < best_error || (error == best_error && even_mantissa(candidate) && !even_mantissa(best))) {
      best = candidate;
      best_error = error;
    }
  }
  return best;
}

}  // namespace eomgen
