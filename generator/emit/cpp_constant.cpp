#include "emit/cpp_constant.hpp"

#include <cfloat>
#include <cmath>
#include <stdexcept>

#include <cln/real.h>
#include <fmt/format.h>

#include "symbolic/decimal_numbers.hpp"
#include "symbolic/exact_double.hpp"

namespace eomgen {

namespace {

using GiNaC::numeric;

const numeric& largest_exact_integer() {
  static const numeric two_53 = GiNaC::pow(numeric(2), numeric(53));
  return two_53;
}

numeric as_rational(const numeric& value) {
  if (value.is_rational()) return value;
  return numeric(cln::cl_N(cln::rational(cln::realpart(value.to_cl_N()))));
}

// shortest text that reads back as exactly d, always a floating literal
std::string double_literal(double d) {
  std::string s = fmt::format("{}", d);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

}  // namespace

bool is_exact_integer_literal(const numeric& value) {
  return value.is_integer() && GiNaC::abs(value) <= largest_exact_integer();
}

std::array<double, 3> double_expansion(const numeric& rational) {
  std::array<double, 3> parts{};
  numeric rest = rational;
  for (double& part : parts) {
    part = nearest_double(rest);
    // a part below the normal range would be a subnormal literal, which compilers may warn about
    if (std::fabs(part) < DBL_MIN) part = 0;
    rest -= exact_rational(part);
  }
  return parts;
}

CppConstant cpp_constant(const numeric& value) {
  if (!value.is_real()) throw std::domain_error("a complex number cannot be written as a real scalar");
  std::string sign = value.is_negative() ? "-" : "";
  int signed_precedence = sign.empty() ? 4 : 2;
  numeric a = as_rational(GiNaC::abs(value));
  if (is_exact_integer_literal(a)) return {sign + "T(" + number_text(a) + ")", signed_precedence};
  if (is_exact_integer_literal(a.numer()) && is_exact_integer_literal(a.denom()))
    return {sign + "T(" + number_text(a.numer()) + ")/T(" + number_text(a.denom()) + ")", 2};
  static const numeric largest = exact_rational(DBL_MAX);
  if (a > largest)
    throw std::domain_error(fmt::format("the number {:.6g} is beyond the range of double", a.to_double()));
  std::array<double, 3> parts = double_expansion(a);
  if (parts[1] == 0 && parts[2] == 0) return {sign + "T(" + double_literal(parts[0]) + ")", signed_precedence};
  return {fmt::format("{}detail::constant<T>({}, {}, {})", sign, double_literal(parts[0]), double_literal(parts[1]),
                      double_literal(parts[2])),
          signed_precedence};
}

const char* cpp_constant_function() {
  return "/// A number of the model that no small fraction of integers states exactly: hi is the\n"
         "/// double nearest to it, mid and lo the doubles nearest to what the former leave.\n"
         "/// double, and scalars whose width std::numeric_limits does not give (AD types over\n"
         "/// double), take hi, the correctly rounded value; wider scalars (long double,\n"
         "/// __float128) take hi + (mid + lo), 159 bits (mid + lo is exact in 113 bits), rounded once.\n"
         "template <class T>\ninline T constant(double hi, double mid, double lo) {\n"
         "  (void)mid;\n  (void)lo;\n"
         "  if constexpr (std::numeric_limits<T>::is_specialized && (std::numeric_limits<T>::digits > 53)) {\n"
         "    return T(hi) + (T(mid) + T(lo));\n"
         "  } else {\n    return T(hi);\n  }\n}\n\n";
}

}  // namespace eomgen
