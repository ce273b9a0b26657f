#include "symbolic/canonical_print.hpp"

#include "symbolic/decimal_numbers.hpp"

#include <algorithm>
#include <optional>
#include <sstream>
#include <vector>

#include <fmt/format.h>

namespace eomgen {

using GiNaC::ex;

namespace {

// precedence: 1 sum, 2 product or quotient, 3 power, 4 atom
struct Printed {
  std::string text;
  int precedence;
};

bool negative_text(const std::string& s) { return !s.empty() && s[0] == '-'; }

class Printer {
 public:
  Printer(bool latex, std::function<std::string(const GiNaC::symbol&)> name)
      : latex_(latex), name_(std::move(name)) {}

  Printed print(const ex& e) const {
    if (GiNaC::is_a<GiNaC::numeric>(e)) return number(GiNaC::ex_to<GiNaC::numeric>(e));
    if (GiNaC::is_a<GiNaC::symbol>(e)) return {name_(GiNaC::ex_to<GiNaC::symbol>(e)), 4};
    if (GiNaC::is_a<GiNaC::constant>(e)) return {e.is_equal(GiNaC::Pi) ? (latex_ ? "\\pi" : "Pi") : fallback(e), 4};
    if (GiNaC::is_a<GiNaC::add>(e)) return sum(e);
    if (GiNaC::is_a<GiNaC::mul>(e)) return product(e);
    if (GiNaC::is_a<GiNaC::power>(e)) return power(e);
    if (GiNaC::is_a<GiNaC::function>(e)) return function(e);
    return {fallback(e), 1};
  }

 private:
  static std::string fallback(const ex& e) {
    std::ostringstream s;
    s << e;
    return s.str();
  }

  std::string wrap(const Printed& p, int at_least) const {
    if (p.precedence >= at_least && !negative_text(p.text)) return p.text;
    return latex_ ? "\\left(" + p.text + "\\right)" : "(" + p.text + ")";
  }

  // a decimal as LaTeX: 1.5e-20 → 1.5 \cdot 10^{-20}
  std::string decimal(const std::string& text) const {
    std::size_t e = text.find('e');
    if (!latex_ || e == std::string::npos) return text;
    return text.substr(0, e) + " \\cdot 10^{" + text.substr(e + 1) + "}";
  }

  Printed number(const GiNaC::numeric& n) const {
    if (n.is_integer()) return {number_text(n), n.is_negative() ? 2 : 4};
    if (std::optional<std::string> d = exact_decimal_text(n)) return {decimal(*d), n.is_negative() ? 2 : 4};
    if (n.is_rational()) {
      std::string sign = n.is_negative() ? "-" : "";
      GiNaC::numeric a = GiNaC::abs(n);
      if (latex_) return {sign + "\\frac{" + number_text(a.numer()) + "}{" + number_text(a.denom()) + "}", sign.empty() ? 4 : 2};
      return {sign + number_text(a.numer()) + "/" + number_text(a.denom()), 2};
    }
    if (n.is_real()) {
      double v = n.to_double();
      return {fmt::format("{}", v), v < 0 ? 2 : 4};
    }
    return {fallback(n), 1};
  }

  Printed sum(const ex& e) const {
    std::vector<std::string> terms;
    for (std::size_t i = 0; i < e.nops(); ++i) terms.push_back(print(e.op(i)).text);
    auto key = [](const std::string& s) { return negative_text(s) ? s.substr(1) : s; };
    std::sort(terms.begin(), terms.end(), [&](const std::string& a, const std::string& b) {
      std::string ka = key(a), kb = key(b);
      // numbers last, so that constants trail the symbolic terms
      bool na = !ka.empty() && std::isdigit(static_cast<unsigned char>(ka[0]));
      bool nb = !kb.empty() && std::isdigit(static_cast<unsigned char>(kb[0]));
      if (na != nb) return nb;
      return ka != kb ? ka < kb : a < b;
    });
    std::string out;
    for (const std::string& t : terms) {
      if (out.empty()) out = t;
      else if (negative_text(t)) out += " - " + t.substr(1);
      else out += " + " + t;
    }
    return {out, 1};
  }

  // GiNaC may hold c·(a − b) as (−c)·(b − a), depending on its hash order, which
  // changes between processes; a sum inside a product is printed with its first
  // term positive, the sign going to the coefficient.
  bool leads_negative(const ex& sum_or_other) const {
    return GiNaC::is_a<GiNaC::add>(sum_or_other) && negative_text(sum(sum_or_other).text);
  }

  // GiNaC may evaluate the flipped factor back into −1 times the original (it pulls the
  // sign out of (−a)^n its own way): then the factor stays as it is, or printing would
  // flip it forever
  ex normalized_factor(const ex& f, GiNaC::numeric& coefficient) const {
    if (leads_negative(f)) {
      ex flipped = -f;
      if (!GiNaC::is_a<GiNaC::add>(flipped)) return f;
      coefficient = -coefficient;
      return flipped;
    }
    if (GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::numeric>(f.op(1)) &&
        GiNaC::ex_to<GiNaC::numeric>(f.op(1)).is_integer() && leads_negative(f.op(0))) {
      ex flipped = GiNaC::power(-f.op(0), f.op(1));
      if (!GiNaC::is_a<GiNaC::power>(flipped)) return f;
      if (GiNaC::ex_to<GiNaC::numeric>(f.op(1)).is_odd()) coefficient = -coefficient;
      return flipped;
    }
    return f;
  }

  Printed product(const ex& e) const {
    GiNaC::numeric coefficient = 1;
    for (std::size_t i = 0; i < e.nops(); ++i)
      if (GiNaC::is_a<GiNaC::numeric>(e.op(i))) coefficient *= GiNaC::ex_to<GiNaC::numeric>(e.op(i));
    std::vector<std::string> numerator, denominator;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      if (GiNaC::is_a<GiNaC::numeric>(e.op(i))) continue;
      const ex f = normalized_factor(e.op(i), coefficient);
      if (GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::numeric>(f.op(1)) &&
                 GiNaC::ex_to<GiNaC::numeric>(f.op(1)).is_negative()) {
        denominator.push_back(wrap(print(GiNaC::pow(f.op(0), -f.op(1))), latex_ ? 1 : 3));
      } else {
        numerator.push_back(wrap(print(f), 2));
      }
    }
    // plain parameters first, then factors that carry a function or velocity: m*l^2*sin(q)
    auto factor_less = [](const std::string& a, const std::string& b) {
      bool ca = a.find('(') != std::string::npos, cb = b.find('(') != std::string::npos;
      return ca != cb ? cb : a < b;
    };
    std::sort(numerator.begin(), numerator.end(), factor_less);
    std::sort(denominator.begin(), denominator.end(), factor_less);
    std::string sign = coefficient.is_negative() ? "-" : "";
    coefficient = GiNaC::abs(coefficient);
    if (std::optional<std::string> d = exact_decimal_text(coefficient)) {
      numerator.insert(numerator.begin(), decimal(*d));
    } else if (coefficient.is_rational()) {
      if (coefficient.numer() != 1) numerator.insert(numerator.begin(), number_text(coefficient.numer()));
      if (coefficient.denom() != 1) denominator.insert(denominator.begin(), number_text(coefficient.denom()));
    } else {
      numerator.insert(numerator.begin(), number(coefficient).text);
    }
    std::string sep = latex_ ? " \\, " : "*";
    auto join = [&](const std::vector<std::string>& v) {
      std::string s;
      for (const std::string& x : v) s += (s.empty() ? "" : sep) + x;
      return s.empty() ? std::string("1") : s;
    };
    if (denominator.empty()) return {sign + join(numerator), 2};
    if (latex_) return {sign + "\\frac{" + join(numerator) + "}{" + join(denominator) + "}", 2};
    std::string den = denominator.size() == 1 ? denominator[0] : "(" + join(denominator) + ")";
    return {sign + join(numerator) + "/" + den, 2};
  }

  // may_flip: false inside a flip, so that a base GiNaC turns back (or that leads with a minus
  // either way) is printed as it is instead of flipped without end
  Printed power(const ex& e, bool may_flip = true) const {
    const ex base = e.op(0), exponent = e.op(1);
    if (exponent.is_equal(GiNaC::numeric(1, 2))) return root(base);
    if (GiNaC::is_a<GiNaC::numeric>(exponent) && GiNaC::ex_to<GiNaC::numeric>(exponent).is_negative()) {
      Printed positive = print(GiNaC::pow(base, -exponent));
      if (latex_) return {"\\frac{1}{" + positive.text + "}", 4};
      return {"1/" + wrap(positive, 3), 2};
    }
    if (GiNaC::is_a<GiNaC::numeric>(exponent) && GiNaC::ex_to<GiNaC::numeric>(exponent).is_integer() &&
        may_flip && leads_negative(base) && GiNaC::is_a<GiNaC::power>(ex(GiNaC::power(-base, exponent)))) {
      Printed flipped = power(GiNaC::power(-base, exponent), false);
      if (GiNaC::ex_to<GiNaC::numeric>(exponent).is_even()) return flipped;
      return {"-" + flipped.text, 2};
    }
    std::string b = wrap(print(base), 4);
    Printed x = print(exponent);
    if (latex_) return {b + "^{" + x.text + "}", 3};
    bool simple = GiNaC::is_a<GiNaC::numeric>(exponent) && GiNaC::ex_to<GiNaC::numeric>(exponent).is_pos_integer();
    return {b + "^" + (simple ? x.text : "(" + x.text + ")"), 3};
  }

  Printed root(const ex& base) const {
    std::string inner = print(base).text;
    return {latex_ ? "\\sqrt{" + inner + "}" : "sqrt(" + inner + ")", 4};
  }

  Printed function(const ex& e) const {
    std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    if (name == "magnitude") name = "abs";  // the model's abs (symbolic/magnitude.hpp), as it wrote it
    std::string args;
    for (std::size_t i = 0; i < e.nops(); ++i) args += (i ? ", " : "") + print(e.op(i)).text;
    if (!latex_) return {name + "(" + args + ")", 4};
    if (name == "abs") return {"\\left|" + args + "\\right|", 4};
    // atan_ratio(n, u, a), the n-th derivative in u of A(u, a) (symbolic/rotation_angle.hpp), as A^{(n)}(u, a)
    if (name == "atan_ratio")
      return {"A^{(" + print(e.op(0)).text + ")}\\left(" + print(e.op(1)).text + ", " + print(e.op(2)).text + "\\right)", 4};
    static const std::vector<std::pair<std::string, std::string>> tex = {
        {"sin", "\\sin"},     {"cos", "\\cos"},     {"tan", "\\tan"},   {"asin", "\\arcsin"},
        {"acos", "\\arccos"}, {"atan", "\\arctan"}, {"sinh", "\\sinh"}, {"cosh", "\\cosh"},
        {"tanh", "\\tanh"},   {"exp", "\\exp"},     {"log", "\\ln"}};
    std::string head = "\\operatorname{" + name + "}";
    for (const auto& [plain, command] : tex)
      if (plain == name) head = command;
    return {head + "\\left(" + args + "\\right)", 4};
  }

  bool latex_;
  std::function<std::string(const GiNaC::symbol&)> name_;
};

}  // namespace

std::string canonical_text(const ex& e) {
  return Printer(false, [](const GiNaC::symbol& s) { return s.get_name(); }).print(e).text;
}

std::string latex_text(const ex& e, const std::function<std::string(const GiNaC::symbol&)>& symbol_name) {
  return Printer(true, symbol_name).print(e).text;
}

}  // namespace eomgen
