/// @file clamp(x, lo, hi) in the model's expressions: x held to [lo, hi], as MuJoCo clamps an
/// actuator's control to its ctrlrange and its force to its forcerange. Its slopes are written with
/// below(a, b), 1 where a < b and 0 elsewhere: d clamp/dx = 1 − below(x, lo) − below(hi, x),
/// d clamp/dlo = below(x, lo), d clamp/dhi = below(hi, x). below's own slope is 0 (it is piecewise
/// constant), so Jacobians of a clamped input are exact wherever x is not on a bound.
#pragma once

#include <ginac/ginac.h>

namespace eomgen {

DECLARE_FUNCTION_3P(clamp)
DECLARE_FUNCTION_2P(below)

}  // namespace eomgen
