/// @file Numeric evaluation of an expression many times over, without GiNaC's
/// substitution and evalf (a stability map evaluates its conditions at every point).
#pragma once

#include <functional>
#include <stdexcept>

#include <ginac/ginac.h>

namespace eomgen {

/// The value of `e` in double precision, with `value_of` giving each symbol's value.
double evaluate(const GiNaC::ex& e, const std::function<double(const GiNaC::symbol&)>& value_of);

}  // namespace eomgen
