#include "symbolic/trig_orientation.hpp"

#include <map>

#include "symbolic/canonical_print.hpp"

namespace eomgen {

namespace {

// true when −a is the canonical way to write the argument a
bool flip(const GiNaC::ex& argument) {
  std::string as_is = canonical_text(argument), negated = canonical_text(-argument);
  bool minus = !as_is.empty() && as_is[0] == '-', negated_minus = !negated.empty() && negated[0] == '-';
  if (minus != negated_minus) return minus;
  return negated < as_is;
}

// printing both orientations is the cost; a model repeats the same few arguments many times
struct Orient : GiNaC::map_function {
  std::map<GiNaC::ex, bool, GiNaC::ex_is_less> flipped;
  bool flip_cached(const GiNaC::ex& argument) {
    auto it = flipped.find(argument);
    return it != flipped.end() ? it->second : flipped.emplace(argument, flip(argument)).first->second;
  }

  GiNaC::ex operator()(const GiNaC::ex& e) override {
    if (!e.has(GiNaC::sin(GiNaC::wild())) && !e.has(GiNaC::cos(GiNaC::wild())) && !e.has(GiNaC::tan(GiNaC::wild()))) return e;
    bool is_sin = GiNaC::is_the_function<GiNaC::sin_SERIAL>(e), is_cos = GiNaC::is_the_function<GiNaC::cos_SERIAL>(e),
         is_tan = GiNaC::is_the_function<GiNaC::tan_SERIAL>(e);
    if (!is_sin && !is_cos && !is_tan) return e.map(*this);
    GiNaC::ex argument = (*this)(e.op(0));
    if (!flip_cached(argument)) return e.op(0).is_equal(argument) ? e : (is_sin ? GiNaC::sin(argument) : is_cos ? GiNaC::cos(argument) : GiNaC::tan(argument));
    if (is_cos) return GiNaC::cos(-argument);
    return is_sin ? -GiNaC::sin(-argument) : -GiNaC::tan(-argument);
  }
};

}  // namespace

GiNaC::ex orient_trigonometric_arguments(const GiNaC::ex& e) {
  Orient orient;
  return orient(e);
}

}  // namespace eomgen
