#include "symbolic/evaluate.hpp"

#include "symbolic/rotation_angle.hpp"

#include <algorithm>
#include <cmath>

namespace eomgen {

double evaluate(const GiNaC::ex& e, const std::function<double(const GiNaC::symbol&)>& value_of) {
  using namespace GiNaC;
  if (is_a<numeric>(e)) return ex_to<numeric>(e).to_double();
  if (is_a<symbol>(e)) return value_of(ex_to<symbol>(e));
  if (is_a<constant>(e)) return ex_to<numeric>(e.evalf()).to_double();
  if (is_a<add>(e)) {
    double s = 0;
    for (std::size_t i = 0; i < e.nops(); ++i) s += evaluate(e.op(i), value_of);
    return s;
  }
  if (is_a<mul>(e)) {
    double p = 1;
    for (std::size_t i = 0; i < e.nops(); ++i) p *= evaluate(e.op(i), value_of);
    return p;
  }
  if (is_a<power>(e)) {
    double base = evaluate(e.op(0), value_of);
    if (e.op(1).info(info_flags::integer)) {
      int k = ex_to<numeric>(e.op(1)).to_int();
      double r = 1, b = k < 0 ? 1 / base : base;
      for (int i = 0; i < std::abs(k); ++i) r *= b;
      return r;
    }
    return std::pow(base, evaluate(e.op(1), value_of));
  }
  if (is_a<function>(e)) {
    std::string name = ex_to<function>(e).get_name();
    double a = evaluate(e.op(0), value_of);
    if (name == "sin") return std::sin(a);
    if (name == "cos") return std::cos(a);
    if (name == "tan") return std::tan(a);
    if (name == "asin") return std::asin(a);
    if (name == "acos") return std::acos(a);
    if (name == "atan") return std::atan(a);
    if (name == "atan2") return std::atan2(a, evaluate(e.op(1), value_of));
    if (name == "sinh") return std::sinh(a);
    if (name == "cosh") return std::cosh(a);
    if (name == "tanh") return std::tanh(a);
    if (name == "exp") return std::exp(a);
    if (name == "log") return std::log(a);
    if (name == "abs" || name == "magnitude") return std::abs(a);
    if (name == "sign") return a < 0 ? -1.0 : (a > 0 ? 1.0 : 0.0);
    if (name == "clamp") return std::min(std::max(a, evaluate(e.op(1), value_of)), evaluate(e.op(2), value_of));
    if (name == "below") return a < evaluate(e.op(1), value_of) ? 1.0 : 0.0;
    if (name == "atan_ratio") return atan_ratio_value(int(a), evaluate(e.op(1), value_of), evaluate(e.op(2), value_of));
  }
  throw std::runtime_error("cannot evaluate this expression numerically");
}

}  // namespace eomgen
