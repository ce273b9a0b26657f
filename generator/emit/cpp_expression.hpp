/// @file Expressions as scalar-generic C++: literals converted to the scalar
/// type T, math calls found by argument-dependent lookup, small integer powers
/// as products, operands in an order fixed by their text.
#pragma once

#include <functional>
#include <string>

#include <ginac/ginac.h>

namespace eomgen {

/// C++ for `e` with scalar type `T`; `name_of` gives each symbol's C++ name, and `name_of_call`
/// (when given) the name of a function call computed elsewhere, or "" to write the call.
std::string cpp_expression(const GiNaC::ex& e, const std::function<std::string(const GiNaC::symbol&)>& name_of,
                           const std::function<std::string(const GiNaC::ex&)>& name_of_call = {});

/// The using-declarations a function needs so that math calls resolve for
/// double and for user scalar types alike.
const char* cpp_math_usings();

}  // namespace eomgen
