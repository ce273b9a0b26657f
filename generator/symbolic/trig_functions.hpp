/// @file Which trigonometric function an expression is a call of, for the passes that rewrite
/// sines and cosines (simplify, trig_rational).
#pragma once

#include <ginac/ginac.h>

namespace eomgen {

inline bool is_sin(const GiNaC::ex& e) { return GiNaC::is_the_function<GiNaC::sin_SERIAL>(e); }
inline bool is_cos(const GiNaC::ex& e) { return GiNaC::is_the_function<GiNaC::cos_SERIAL>(e); }
inline bool is_tan(const GiNaC::ex& e) { return GiNaC::is_the_function<GiNaC::tan_SERIAL>(e); }

}  // namespace eomgen
