/// @file Rational trigonometric simplification: an expression that is a rational
/// function of sines and cosines is written with s = sin(a), c = cos(a) as a quotient
/// of polynomials, each reduced modulo s² + c² − 1 (to degree one in s, or in c), and
/// the common factors of numerator and denominator cancelled. It undoes what a
/// transformation of velocities leaves behind, such as the 1/cos³ terms of Cardan
/// rates that cancel in a rolling ball's mass matrix.
#pragma once

#include <ginac/ginac.h>

#include "symbolic/simplify.hpp"

namespace eomgen {

/// The shortest (in printed size) of e and its two reduced forms, each tidied.
GiNaC::ex simplify_trig_rational(const GiNaC::ex& e, const MotionSymbols& motion);

}  // namespace eomgen
