/// @file One orientation for the argument of every sine, cosine and tangent, so that
/// equal equations print equally however the model was written: of the two ways to
/// write an argument, a and −a, the one whose canonical text does not start with a minus
/// sign is kept (cos(−a) = cos(a), sin(−a) = −sin(a), tan(−a) = −tan(a)); `cos(q1 − q2)`
/// and `cos(q2 − q1)` both become `cos(q1 - q2)`, `sin(-q2)` becomes `-sin(q2)`.
#pragma once

#include <ginac/ginac.h>

namespace eomgen {

GiNaC::ex orient_trigonometric_arguments(const GiNaC::ex& e);

}  // namespace eomgen
