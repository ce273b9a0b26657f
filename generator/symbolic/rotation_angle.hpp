/// @file The angle θ of the turn that a quaternion (w, x, y, z) of any length states, in [0, π]: the
/// model's rotation_angle(w, x, y, z), as MuJoCo's spring on a ball or free joint takes it (½k θ² of
/// the turn from the spring's rest). θ = 2 atan2(|v|, |w|) with v = (x, y, z) is not smooth where it
/// vanishes, but θ² is, and the derivatives of ½k θ², which are what a spring's force and its
/// Jacobian take, are 0/0 at the rest pose when written with |v| = sqrt(u), u = |v|². So θ is written
/// as 2 sqrt(u) A(u, |w|) with A(u, a) = atan2(sqrt(u), a)/sqrt(u), which is analytic in u at u = 0
/// (A = Σ (−1)^k u^k / ((2k+1) a^(2k+1))): θ² = 4 u A², and every derivative of A is again of the
/// family atan_ratio(n, u, a) = ∂ⁿA/∂uⁿ, with ∂A^(n)/∂a = (−1)^(n+1) n! / (u + a²)^(n+1).
#pragma once

#include <ginac/ginac.h>

namespace eomgen {

/// atan_ratio(n, u, a): the n-th derivative in u of A(u, a) = atan2(sqrt(u), a)/sqrt(u), a ≥ 0;
/// n a non-negative integer
DECLARE_FUNCTION_3P(atan_ratio)

/// θ = 2 sqrt(x² + y² + z²) atan_ratio(0, x² + y² + z², |w|): the model's rotation_angle
GiNaC::ex rotation_angle(const GiNaC::ex& w, const GiNaC::ex& x, const GiNaC::ex& y, const GiNaC::ex& z);

/// atan_ratio(n, u, a) in double (symbolic/evaluate.cpp); the header's detail::atan_ratio computes
/// the same way (emit/cpp_piecewise.cpp)
double atan_ratio_value(int n, double u, double a);

}  // namespace eomgen
