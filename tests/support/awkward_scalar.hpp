/// @file A scalar type that allows only what the generated headers may use:
/// explicit construction from a number, the four operations, unary minus, `<`
/// (which only a model's clamp(x, lo, hi) uses) and math functions found by
/// argument-dependent lookup. Any implicit conversion, other comparison, compound
/// assignment or std:: call in a header fails to compile.
#pragma once

#include <cmath>
#include <type_traits>

namespace awkward {

class Scalar {
 public:
  Scalar() = default;
  template <class Number, class = std::enable_if_t<std::is_arithmetic_v<Number>>>
  explicit Scalar(Number v) : v_(static_cast<double>(v)) {}
  double value() const { return v_; }

  friend Scalar operator+(Scalar a, Scalar b) { return Scalar(a.v_ + b.v_); }
  friend Scalar operator-(Scalar a, Scalar b) { return Scalar(a.v_ - b.v_); }
  friend Scalar operator*(Scalar a, Scalar b) { return Scalar(a.v_ * b.v_); }
  friend Scalar operator/(Scalar a, Scalar b) { return Scalar(a.v_ / b.v_); }
  friend Scalar operator-(Scalar a) { return Scalar(-a.v_); }
  friend bool operator<(Scalar a, Scalar b) { return a.v_ < b.v_; }

 private:
  double v_ = 0;
};

#define EOMGEN_AWKWARD_UNARY(name) \
  inline Scalar name(Scalar a) { return Scalar(std::name(a.value())); }
EOMGEN_AWKWARD_UNARY(sin)
EOMGEN_AWKWARD_UNARY(cos)
EOMGEN_AWKWARD_UNARY(tan)
EOMGEN_AWKWARD_UNARY(asin)
EOMGEN_AWKWARD_UNARY(acos)
EOMGEN_AWKWARD_UNARY(atan)
EOMGEN_AWKWARD_UNARY(sinh)
EOMGEN_AWKWARD_UNARY(cosh)
EOMGEN_AWKWARD_UNARY(tanh)
EOMGEN_AWKWARD_UNARY(exp)
EOMGEN_AWKWARD_UNARY(log)
EOMGEN_AWKWARD_UNARY(sqrt)
EOMGEN_AWKWARD_UNARY(abs)
#undef EOMGEN_AWKWARD_UNARY
inline Scalar atan2(Scalar y, Scalar x) { return Scalar(std::atan2(y.value(), x.value())); }
inline Scalar pow(Scalar a, Scalar b) { return Scalar(std::pow(a.value(), b.value())); }

}  // namespace awkward
