#include "emit/cpp_expression.hpp"

#include "emit/cpp_constant.hpp"
#include "emit/statement_order.hpp"
#include "symbolic/exact_double.hpp"
#include "symbolic/decimal_numbers.hpp"

#include <algorithm>
#include <array>
#include <cfloat>
#include <optional>
#include <vector>

#include <fmt/format.h>

namespace eomgen {

using GiNaC::ex;

namespace {

// std's functions that the C++ below calls unqualified: found by argument-dependent lookup for a
// user's scalar type, by cpp_math_usings' declarations for double (abs is written as the header's
// own detail::magnitude)
constexpr std::array<std::string_view, 14> std_functions{"sin",  "cos",  "tan", "asin", "acos", "atan", "atan2",
                                                         "sinh", "cosh", "tanh", "exp", "log", "sqrt", "pow"};

}  // namespace

std::string cpp_math_usings(std::string_view code) {
  std::array<bool, std_functions.size()> called{};
  for_each_identifier(code, 0, code.size(), [&](std::string_view id) {
    std::size_t at = std::size_t(id.data() - code.data()), end = at + id.size();
    if (end == code.size() || code[end] != '(' || (at > 0 && code[at - 1] == ':')) return;
    for (std::size_t k = 0; k < std_functions.size(); ++k) called[k] = called[k] || id == std_functions[k];
  });
  std::string out;
  int on_line = 0;
  for (std::size_t k = 0; k < std_functions.size(); ++k) {
    if (!called[k]) continue;
    if (on_line == 6) {
      out += "\n  ";
      on_line = 0;
    }
    out += fmt::format("{}using std::{};", on_line ? " " : "", std_functions[k]);
    ++on_line;
  }
  return out;
}

namespace {

// precedence: 1 sum, 2 product, 4 atom or call
struct Code {
  std::string text;
  int precedence;
};

class CppPrinter {
 public:
  CppPrinter(const std::function<std::string(const GiNaC::symbol&)>& name_of,
             const std::function<std::string(const ex&)>& name_of_call)
      : name_of_(name_of), name_of_call_(name_of_call) {}

  Code print(const ex& e) const {
    if (GiNaC::is_a<GiNaC::numeric>(e)) return number(GiNaC::ex_to<GiNaC::numeric>(e));
    if (GiNaC::is_a<GiNaC::symbol>(e)) return {name_of_(GiNaC::ex_to<GiNaC::symbol>(e)), 4};
    if (e.is_equal(GiNaC::Pi)) return {"T(3.141592653589793238462643383279502884L)", 4};
    if (GiNaC::is_a<GiNaC::add>(e)) return sum(e);
    if (GiNaC::is_a<GiNaC::mul>(e)) return product(e);
    if (GiNaC::is_a<GiNaC::power>(e)) return power(e.op(0), e.op(1));
    if (GiNaC::is_a<GiNaC::function>(e)) return call(e);
    throw std::runtime_error(fmt::format("cannot write {} as C++", static_cast<const void*>(&e)));
  }

 private:
  // a * or / outside parentheses
  static bool is_product_text(const std::string& text) {
    int depth = 0;
    for (char c : text) {
      depth += c == '(' ? 1 : c == ')' ? -1 : 0;
      if (depth == 0 && (c == '*' || c == '/')) return true;
    }
    return false;
  }

  static std::string wrap(const Code& c, int at_least) {
    return c.precedence >= at_least && c.text[0] != '-' ? c.text : "(" + c.text + ")";
  }

  Code number(const GiNaC::numeric& n) const {
    CppConstant c = cpp_constant(n);
    return {c.text, c.precedence};
  }

  Code sum(const ex& e) const {
    std::vector<std::string> terms;
    for (std::size_t i = 0; i < e.nops(); ++i) terms.push_back(print(e.op(i)).text);
    std::sort(terms.begin(), terms.end(), [](const std::string& a, const std::string& b) {
      std::string ka = a[0] == '-' ? a.substr(1) : a, kb = b[0] == '-' ? b.substr(1) : b;
      return ka != kb ? ka < kb : a < b;
    });
    std::string out;
    for (const std::string& t : terms) {
      if (out.empty()) out = t;
      else if (t[0] == '-') out += " - " + t.substr(1);
      else out += " + " + t;
    }
    return {out, 1};
  }

  // x^k as x*x*…, x^(-k) in the denominator, x^(1/2) as sqrt
  Code power(const ex& base, const ex& exponent) const {
    if (exponent.is_equal(GiNaC::numeric(1, 2))) return {"sqrt(" + print(base).text + ")", 4};
    if (exponent.is_equal(GiNaC::numeric(-1, 2))) return {"T(1)/sqrt(" + print(base).text + ")", 2};
    if (exponent.info(GiNaC::info_flags::integer)) return integer_power(print(base), GiNaC::ex_to<GiNaC::numeric>(exponent).to_int());
    return {"pow(" + print(base).text + ", " + print(exponent).text + ")", 4};
  }

  Code integer_power(const Code& base, int k) const {
    if (k < 0) return {"T(1)/" + wrap(integer_power(base, -k), 4), 2};
    if (k > 4) return {"pow(" + base.text + ", " + number(GiNaC::numeric(k)).text + ")", 4};
    std::string b = wrap(base, 4), out = b;
    for (int i = 1; i < k; ++i) out += "*" + b;
    return {out, k == 1 ? 4 : 2};
  }

  // A product's numeric factor beyond double's range, 1e310 × (1e-300 x + 2e-302 y): 17-digit
  // constants multiplied many times over (a robot file's turns of π/2 to 12 digits, 1e-13 off
  // their right angles, composed down a tree) leave terms of 1e-300 whose common factor GiNaC
  // takes out. Multiplied into a sum it stands with, the terms are numbers double holds.
  static bool beyond_double(const GiNaC::numeric& c) {
    static const GiNaC::numeric largest = exact_rational(DBL_MAX), smallest = exact_rational(DBL_MIN);
    GiNaC::numeric size = GiNaC::abs(c);
    return size > largest || (!size.is_zero() && size < smallest);
  }
  // (printed as two factors: GiNaC, given the product back, would take the factor out again)
  std::optional<Code> coefficient_into_a_sum(const ex& e, const GiNaC::numeric& coefficient) const {
    for (std::size_t i = 0; i < e.nops(); ++i) {
      if (!GiNaC::is_a<GiNaC::add>(e.op(i))) continue;
      ex rest = 1;
      for (std::size_t j = 0; j < e.nops(); ++j)
        if (j != i && !GiNaC::is_a<GiNaC::numeric>(e.op(j))) rest *= e.op(j);
      Code scaled = print((coefficient * e.op(i)).expand());
      if (rest.is_equal(1)) return scaled;
      return Code{wrap(print(rest), 2) + "*" + wrap(scaled, 2), 2};
    }
    return std::nullopt;
  }

  // a sum inside a product is written with its first term positive (GiNaC's choice of sign
  // there follows an order that changes between processes); the sum's text, with the sign it
  // moved into `coefficient`. Printed here rather than rebuilt as (−s)^k: GiNaC would take
  // the sign out of the power again.
  Code oriented_sum(const ex& s, int exponent, GiNaC::numeric& coefficient) const {
    Code text = sum(s);
    if (text.text[0] != '-') return text;
    if (exponent % 2 != 0) coefficient = -coefficient;
    return sum(-s);
  }

  Code product(const ex& e) const {
    GiNaC::numeric coefficient = 1;
    for (std::size_t i = 0; i < e.nops(); ++i)
      if (GiNaC::is_a<GiNaC::numeric>(e.op(i))) coefficient *= GiNaC::ex_to<GiNaC::numeric>(e.op(i));
    if (beyond_double(coefficient))
      if (std::optional<Code> within = coefficient_into_a_sum(e, coefficient)) return *within;
    std::vector<std::string> numerator, denominator;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      if (GiNaC::is_a<GiNaC::numeric>(e.op(i))) continue;
      const ex& f = e.op(i);
      bool whole_power = GiNaC::is_a<GiNaC::power>(f) && f.op(1).info(GiNaC::info_flags::integer);
      int k = whole_power ? GiNaC::ex_to<GiNaC::numeric>(f.op(1)).to_int() : 1;
      if (GiNaC::is_a<GiNaC::add>(f)) numerator.push_back(wrap(oriented_sum(f, 1, coefficient), 2));
      else if (whole_power && GiNaC::is_a<GiNaC::add>(f.op(0))) {
        Code base = oriented_sum(f.op(0), k, coefficient);
        (k < 0 ? denominator : numerator).push_back(wrap(integer_power(base, std::abs(k)), 2));
      } else if (whole_power && k < 0) {
        denominator.push_back(wrap(power(f.op(0), -k), 2));
      } else {
        numerator.push_back(wrap(print(f), 2));
      }
    }
    std::sort(numerator.begin(), numerator.end());
    std::sort(denominator.begin(), denominator.end());
    std::string sign = coefficient.is_negative() ? "-" : "";
    coefficient = GiNaC::abs(coefficient);
    if (coefficient != 1) {
      if (coefficient.is_rational() && coefficient.denom() != 1 && is_exact_integer_literal(coefficient.numer()) &&
          is_exact_integer_literal(coefficient.denom())) {
        // one factor (T(p)/T(q)), which the compiler folds into the correctly rounded constant: a
        // trailing /T(q) is a division on every call (x/c becomes x*(1/c) only where 1/c is exact)
        std::string fraction = "T(" + number_text(coefficient.numer()) + ")/T(" + number_text(coefficient.denom()) + ")";
        numerator.insert(numerator.begin(), numerator.empty() && denominator.empty() ? fraction : "(" + fraction + ")");
      } else {
        numerator.insert(numerator.begin(), number(coefficient).text);
      }
    }
    std::string out;
    for (const std::string& f : numerator) out += (out.empty() ? "" : "*") + f;
    if (out.empty()) out = "T(1)";
    if (!denominator.empty()) {
      std::string den;
      for (const std::string& f : denominator) den += (den.empty() ? "" : "*") + f;
      // the denominator is one factor: x/(s*s), never x/s*s, which C++ reads as (x/s)*s
      out += "/" + (denominator.size() == 1 && !is_product_text(den) ? den : "(" + den + ")");
    }
    return {sign + out, 2};
  }

  Code call(const ex& e) const {
    if (name_of_call_)
      if (std::string computed = name_of_call_(e); !computed.empty()) return {computed, 4};
    std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    // clamp, below, sign and abs are the header's own (detail_functions), not std's: abs (the
    // model's, symbolic/magnitude.hpp, or GiNaC's) as detail::magnitude, whose complex-step
    // derivative is sign(x) x' (std::abs of a complex number is its modulus, which drops it)
    if (name == "abs") name = "magnitude";
    bool own = name == "clamp" || name == "below" || name == "sign" || name == "magnitude" || name == "atan_ratio";
    if (!own && std::find(std_functions.begin(), std_functions.end(), name) == std_functions.end())
      throw std::runtime_error("no C++ for the function " + name);
    std::string args;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      // atan_ratio's order (symbolic/rotation_angle.hpp) is an int, not a number of type T
      bool order = name == "atan_ratio" && i == 0 && GiNaC::is_a<GiNaC::numeric>(e.op(0));
      args += (i ? ", " : "") + (order ? std::to_string(GiNaC::ex_to<GiNaC::numeric>(e.op(0)).to_int()) : print(e.op(i)).text);
    }
    return {(own ? "detail::" : "") + name + "(" + args + ")", 4};
  }

  const std::function<std::string(const GiNaC::symbol&)>& name_of_;
  const std::function<std::string(const ex&)>& name_of_call_;
};

}  // namespace

std::string cpp_expression(const ex& e, const std::function<std::string(const GiNaC::symbol&)>& name_of,
                           const std::function<std::string(const ex&)>& name_of_call) {
  return CppPrinter(name_of, name_of_call).print(e).text;
}

}  // namespace eomgen
