#include "emit/cpp_piecewise.hpp"

namespace eomgen {

std::string piecewise_functions(bool with_clamp, bool with_magnitude) {
  std::string out =
      "/// What clamp, below and sign compare: the number, or a complex number's real part (complex-step\n"
      "/// derivatives then carry through an unclamped value and vanish on a clamped one).\n"
      "template <class T>\ninline const T& ordered(const T& x) {\n  return x;\n}\n"
      "template <class T>\ninline T ordered(const std::complex<T>& x) {\n  return x.real();\n}\n\n";
  if (with_clamp)
    out += "/// The model's clamp(x, lo, hi): x held to [lo, hi] (a control to its range, as MuJoCo does).\n"
           "/// A scalar type for a model with clamp needs `<`.\n"
           "template <class T, class L, class H>\ninline T clamp(const T& x, const L& lo, const H& hi) {\n"
           "  return ordered(x) < ordered(T(lo)) ? T(lo) : (ordered(T(hi)) < ordered(x) ? T(hi) : x);\n}\n\n"
           "/// 1 where a < b, else 0: clamp's slopes are 1 - below(x, lo) - below(hi, x) in x.\n"
           "template <class A, class B>\ninline A below(const A& a, const B& b) {\n"
           "  return ordered(a) < ordered(A(b)) ? A(1) : A(0);\n}\n\n";
  if (with_magnitude)
    out += "/// The model's abs(x): std's for a real scalar; for a complex one (complex-step derivatives), x\n"
           "/// turned by the sign of its real part, whose derivative is sign(x) x' (std::abs would drop it).\n"
           "template <class T>\ninline T magnitude(const T& x) {\n  using std::abs;\n  return abs(x);\n}\n"
           "template <class T>\ninline std::complex<T> magnitude(const std::complex<T>& x) {\n"
           "  return x.real() < T(0) ? -x : x;\n}\n\n"
           "/// -1, 0 or 1 as x is negative, zero or positive: the model's sign(x), and abs(x)'s slope.\n"
           "/// A scalar type for a model with abs or sign needs `<`.\n"
           "template <class T>\ninline T sign(const T& x) {\n"
           "  return ordered(x) < ordered(T(0)) ? T(-1) : (ordered(T(0)) < ordered(x) ? T(1) : T(0));\n}\n\n";
  return out;
}

}  // namespace eomgen
