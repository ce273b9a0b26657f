/// @file abs(x) and sign(x) in the model's expressions. GiNaC's own abs is differentiated for a complex
/// argument, (x' conj(x) + x conj(x)') / (2 |x|), which for a real x is x x' / |x|: 0/0, a silent NaN
/// in every Jacobian where x = 0 (air drag c v |v| at rest). Here d|x|/dx = sign(x), 0 at x = 0 (the
/// slope of v |v| there, 2 |v|, is 0 too), and sign is piecewise constant (its slope 0). The
/// function is named magnitude here (GiNaC's name abs is taken); the printed equations still write
/// abs(x) (canonical_print), the header detail::magnitude and detail::sign.
#pragma once

#include <ginac/ginac.h>

namespace eomgen {

DECLARE_FUNCTION_1P(magnitude)
DECLARE_FUNCTION_1P(sign)

}  // namespace eomgen
