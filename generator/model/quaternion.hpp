/// @file A unit quaternion q = (w, x, y, z) as an orientation (MJCF's quat, ball and free joints):
/// its rotation R(q) = E + 2w[v]× + 2[v]×² over |q|², which any nonzero q makes a rotation, and the
/// rates q' = ½ q ⊗ (0, ω) that the angular velocity ω in the turned frame's axes gives, which keep |q|.
#pragma once

#include <array>

#include <ginac/ginac.h>

namespace eomgen {

/// R(q) body components to parent ones, with 1/|q|² given (a number, or a named intermediate).
GiNaC::matrix quaternion_rotation(const std::array<GiNaC::ex, 4>& q, const GiNaC::ex& inverse_square_norm);

/// R(q) with 1/|q|² written out.
GiNaC::matrix quaternion_rotation(const std::array<GiNaC::ex, 4>& q);

/// q' = ½ q ⊗ (0, ω).
std::array<GiNaC::ex, 4> quaternion_rates(const std::array<GiNaC::ex, 4>& q, const std::array<GiNaC::ex, 3>& omega);

}  // namespace eomgen
