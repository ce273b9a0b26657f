#include "symbolic/trig_rational.hpp"

#include <stdexcept>
#include <vector>

#include "symbolic/canonical_print.hpp"
#include "symbolic/trig_functions.hpp"

namespace eomgen {

namespace {

using GiNaC::ex;


// the arguments of sin, cos and tan; false when another function (or a nested one) appears
bool trig_arguments(const ex& e, GiNaC::exset& arguments) {
  if (is_sin(e) || is_cos(e) || is_tan(e)) {
    if (e.op(0).has(GiNaC::sin(GiNaC::wild())) || e.op(0).has(GiNaC::cos(GiNaC::wild()))) return false;
    arguments.insert(e.op(0));
    return true;
  }
  if (GiNaC::is_a<GiNaC::function>(e)) return false;
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (!trig_arguments(e.op(i), arguments)) return false;
  return true;
}

struct TrigSymbols {
  std::vector<GiNaC::symbol> s, c;
  GiNaC::exmap forward, back;
};

TrigSymbols trig_symbols(const GiNaC::exset& arguments) {
  TrigSymbols t;
  for (const ex& a : arguments) {
    t.s.emplace_back(), t.c.emplace_back();
    t.forward[GiNaC::sin(a)] = t.s.back();
    t.forward[GiNaC::cos(a)] = t.c.back();
    t.forward[GiNaC::tan(a)] = t.s.back() / t.c.back();
    t.back[t.s.back()] = GiNaC::sin(a);
    t.back[t.c.back()] = GiNaC::cos(a);
  }
  return t;
}

// p modulo every s² + c² − 1, to degree one in s (eliminate_sine) or in c
ex reduce(ex p, const TrigSymbols& t, bool eliminate_sine) {
  for (std::size_t i = 0; i < t.s.size(); ++i) {
    const GiNaC::symbol& x = eliminate_sine ? t.s[i] : t.c[i];
    p = GiNaC::rem(p.expand(), GiNaC::pow(t.s[i], 2) + GiNaC::pow(t.c[i], 2) - 1, x);
  }
  return p.expand();
}

ex reduced_quotient(const ex& rational, const TrigSymbols& t, bool eliminate_sine) {
  ex nd = rational.numer_denom();
  ex n = reduce(nd.op(0), t, eliminate_sine), d = reduce(nd.op(1), t, eliminate_sine);
  if (d.is_zero()) return rational;
  ex n_cofactor, d_cofactor;
  GiNaC::gcd(n, d, &n_cofactor, &d_cofactor);
  return n_cofactor / d_cofactor;
}

std::size_t printed_size(const ex& e) { return canonical_text(e).size(); }

}  // namespace

ex simplify_trig_rational(const ex& e, const MotionSymbols& motion) {
  GiNaC::exset arguments;
  if (!trig_arguments(e, arguments) || arguments.empty()) return e;
  TrigSymbols t = trig_symbols(arguments);
  ex rational = e.subs(t.forward, GiNaC::subs_options::no_pattern);
  if (rational.has(GiNaC::sin(GiNaC::wild())) || rational.has(GiNaC::cos(GiNaC::wild())) ||
      rational.has(GiNaC::tan(GiNaC::wild())))
    return e;
  ex best = e;
  std::size_t best_size = printed_size(e);
  // GiNaC's rem and gcd take polynomials over the rationals only: a coefficient such as √26/5 (an
  // oblique axis's unit vector) or abs(x) makes them throw, and the expression stays as it is (it
  // had stopped the derivation of an arm with such an axis, for Appell, with a hint about constraints)
  try {
    rational = rational.normal();
    for (bool eliminate_sine : {true, false}) {
      ex candidate = tidy(reduced_quotient(rational, t, eliminate_sine).subs(t.back, GiNaC::subs_options::no_pattern), motion);
      std::size_t size = printed_size(candidate);
      if (size < best_size) best = candidate, best_size = size;
    }
  } catch (const std::invalid_argument&) {
    return e;
  }
  return best;
}

}  // namespace eomgen
