/// @file Doubles and exact rationals: the rational a double stands for, and the double
/// nearest to a rational, decided in exact arithmetic (CLN's own conversion is within an
/// ulp; writing a constant into generated code needs the correctly rounded one).
#pragma once

#include <ginac/ginac.h>

namespace eomgen {

/// The rational that `d` stands for, exactly (d = m·2^e with m an integer of 53 bits).
GiNaC::numeric exact_rational(double d);

/// The double nearest to the rational `r`, ties to even; r must lie within double's range.
double nearest_double(const GiNaC::numeric& r);

}  // namespace eomgen
