/// @file The generated header's piecewise functions, each written where a function uses it:
/// detail::clamp and detail::below for the model's clamp(x, lo, hi) and its slopes
/// (symbolic/clamp.hpp), detail::magnitude and detail::sign for its abs(x) and abs's slope
/// (symbolic/magnitude.hpp), detail::atan_ratio for its rotation_angle (symbolic/rotation_angle.hpp),
/// and detail::ordered, by which they compare: a complex scalar (complex-step derivatives) by its
/// real part.
#pragma once

#include <string>

namespace eomgen {

/// The text of the helpers for clamp and below, for magnitude and sign, for atan_ratio, or several,
/// with ordered.
std::string piecewise_functions(bool with_clamp, bool with_magnitude, bool with_atan_ratio);

}  // namespace eomgen
