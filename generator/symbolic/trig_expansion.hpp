/// @file For code, not for reading: sin and cos of sums of coordinates expanded
/// by the addition theorems, sin(a − b) = sin a cos b − cos a sin b, so that the
/// generated code evaluates sin and cos once per coordinate and the n² angle
/// differences of a chain cost a few multiplications each instead of a call.
#pragma once

#include <ginac/ginac.h>

namespace eomgen {

/// Expands sin(±x ± y ± …) and cos(…) whose argument is a sum of ±symbols.
GiNaC::ex expand_trig_of_sums(const GiNaC::ex& e);

}  // namespace eomgen
