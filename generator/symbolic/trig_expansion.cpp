#include "symbolic/trig_expansion.hpp"

#include <map>

namespace eomgen {

using GiNaC::ex;

namespace {

// a sum of ±symbol terms (the angles of a chain, differences of them)
bool is_signed_symbol_sum(const ex& e) {
  if (!GiNaC::is_a<GiNaC::add>(e)) return false;
  for (std::size_t i = 0; i < e.nops(); ++i) {
    const ex t = e.op(i);
    if (GiNaC::is_a<GiNaC::symbol>(t)) continue;
    if (GiNaC::is_a<GiNaC::mul>(t) && t.nops() == 2 && GiNaC::is_a<GiNaC::symbol>(t.op(0)) &&
        t.op(1).is_equal(-1))
      continue;
    return false;
  }
  return true;
}

// sin and cos of ±symbol, and of a sum, by sin(x + y) = sin x cos y + cos x sin y,
// cos(x + y) = cos x cos y − sin x sin y; of −x by sin(−x) = −sin x, cos(−x) = cos x, so that the
// code calls sin and cos once per angle (GiNaC keeps sin(−x) as it is)
void sin_cos(const ex& angle, ex& s, ex& c) {
  if (GiNaC::is_a<GiNaC::mul>(angle) && angle.nops() == 2 && GiNaC::is_a<GiNaC::symbol>(angle.op(0)) &&
      angle.op(1).is_equal(-1)) {
    s = -GiNaC::sin(angle.op(0));
    c = GiNaC::cos(angle.op(0));
    return;
  }
  if (!GiNaC::is_a<GiNaC::add>(angle)) {
    s = GiNaC::sin(angle);
    c = GiNaC::cos(angle);
    return;
  }
  ex first = angle.op(0), rest = angle - first, s1, c1, s2, c2;
  sin_cos(first, s1, c1);
  sin_cos(rest, s2, c2);
  s = s1 * c2 + c1 * s2;
  c = c1 * c2 - s1 * s2;
}

struct Expander : GiNaC::map_function {
  ex operator()(const ex& e) override {
    bool is_sin = GiNaC::is_the_function<GiNaC::sin_SERIAL>(e), is_cos = GiNaC::is_the_function<GiNaC::cos_SERIAL>(e);
    if ((is_sin || is_cos) && is_signed_symbol_sum(e.op(0))) {
      ex s, c;
      sin_cos(e.op(0), s, c);
      return is_sin ? s : c;
    }
    return e.map(*this);
  }
};

}  // namespace

ex expand_trig_of_sums(const ex& e) {
  // the functions of a header expand the same M and f several times
  static thread_local std::map<ex, ex, GiNaC::ex_is_less> done;
  auto found = done.find(e);
  if (found != done.end()) return found->second;
  Expander expander;
  return done.emplace(e, expander(e)).first->second;
}

}  // namespace eomgen
