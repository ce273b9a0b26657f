/// @file Exact numbers of the equations as C++ constants of any scalar type T.
///
/// A model's numbers are read exactly (0.1 is 1/10), so products of 17-digit decimals
/// are rationals of 40 digits and more, which no C++ integer literal holds. A number is
/// written as
///  - `T(n)` when it is an integer of at most 2^53 in magnitude;
///  - `T(p)/T(q)` when numerator and denominator are such integers: each converts to
///    double (and every wider type) exactly, and the division rounds once, correctly;
///  - otherwise `detail::constant<T>(hi, mid, lo)`: three doubles, each the double
///    nearest to what the former leave of the number (hi is the correctly rounded
///    double). `detail::constant` returns hi for double and for scalars of unknown
///    width (AD types over double), and hi + (mid + lo) for wider scalars: 159 bits,
///    more than __float128's 113. A decimal literal of 36 digits would not do: without
///    a suffix it is a double, with `L` a long double (rounded to 64 bits before a
///    __float128 sees it), and __float128's `Q` is not standard C++.
#pragma once

#include <array>
#include <string>

#include <ginac/ginac.h>

namespace eomgen {

/// The C++ text of `value` (a rational, or a floating-point numeric) for scalar type T,
/// with its precedence as the C++ printer counts it: 4 an atom, 2 a product or quotient
/// (a negative number, a fraction). Throws std::domain_error for a number beyond
/// double's range.
struct CppConstant {
  std::string text;
  int precedence = 4;
};
CppConstant cpp_constant(const GiNaC::numeric& value);

/// Whether `value` (an integer) is written as a plain integer literal: |value| <= 2^53.
bool is_exact_integer_literal(const GiNaC::numeric& value);

/// The three doubles hi, mid, lo of a rational, each the nearest (ties to even) to the
/// rest of the ones before it; parts below double's normal range are dropped.
std::array<double, 3> double_expansion(const GiNaC::numeric& rational);

/// The definition of detail::constant that headers using it carry.
const char* cpp_constant_function();

}  // namespace eomgen
