/// @file Sine and cosine of the coordinates, all of a function's at once: the generated header's
/// detail::sin_cos. For double it reduces each angle by a multiple of π/2 and evaluates two
/// polynomials, two angles at a time in SIMD registers (GCC and Clang vector extensions); other
/// scalar types, other compilers, angles the reduction does not cover, and every double under
/// -ffast-math or when EOMGEN_STD_SIN_COS is defined go to sin and cos found by lookup.
#pragma once

#include <string>

namespace eomgen {

/// |x| below this is reduced in three parts of π/2 (exact products for k < 2^20); beyond it,
/// and for 0, NaN and infinities, std::sin and std::cos give the values.
inline constexpr double sin_cos_reduction_limit = 1e6;

/// The text of detail::sin_cos(const T (&angle)[N], T (&s)[N], T (&c)[N]), the generic template
/// and its overload for double.
std::string sin_cos_function();

}  // namespace eomgen
