/// @file Expressions as scalar-generic C++: literals converted to the scalar
/// type T, math calls found by argument-dependent lookup, small integer powers
/// as products, operands in an order fixed by their text.
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include <ginac/ginac.h>

namespace eomgen {

/// C++ for `e` with scalar type `T`; `name_of` gives each symbol's C++ name, and `name_of_call`
/// (when given) the name of a function call computed elsewhere, or "" to write the call.
std::string cpp_expression(const GiNaC::ex& e, const std::function<std::string(const GiNaC::symbol&)>& name_of,
                           const std::function<std::string(const GiNaC::ex&)>& name_of_call = {});

/// The using-declarations of std's math functions that the statements `code` call unqualified, so
/// that the calls resolve for double and for user scalar types (by argument-dependent lookup)
/// alike; "" when they call none. Only those called: a header has dozens of functions, and the
/// full list in each cost a 7-joint arm's header 1.5 KB of its 200.
std::string cpp_math_usings(std::string_view code);

}  // namespace eomgen
