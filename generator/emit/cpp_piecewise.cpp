#include "emit/cpp_piecewise.hpp"

namespace eomgen {

std::string piecewise_functions(bool with_clamp, bool with_magnitude, bool with_atan_ratio) {
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
  if (with_atan_ratio)
    out += "/// The n-th derivative in u of A(u, a) = atan2(sqrt(u), a)/sqrt(u), a >= 0: the model's\n"
           "/// rotation_angle(w, x, y, z) is 2 sqrt(u) A(u, |w|), u = x^2 + y^2 + z^2, so that the square of a\n"
           "/// turn's angle and its derivatives stay finite where the turn vanishes. Where u < 0.3 a^2 by A's\n"
           "/// series, sum over k >= n of (-1)^k k!/(k-n)! u^(k-n) / ((2k+1) a^(2k+1)), to the last term that\n"
           "/// changes the sum; else from A by 2u A^(m+1) = (-1)^m m! a/(u + a^2)^(m+1) - (2m+1) A^(m).\n"
           "template <class T>\ninline T atan_ratio(int n, const T& u, const T& a) {\n"
           "  using std::atan;\n  using std::sqrt;\n"
           "  if (ordered(u) < ordered(T(3) / T(10) * a * a)) {\n"
           "    T ratio = u / (a * a), t = T(n % 2 ? -1 : 1), inverse = T(1) / a;\n"
           "    for (int k = 2; k <= n; ++k) t = t * T(k);\n"
           "    for (int k = 0; k <= 2 * n; ++k) t = t * inverse;\n"
           "    T sum = t / T(2 * n + 1);\n"
           "    for (int k = n + 1; k < n + 1000; ++k) {\n"
           "      t = -(t * T(k) / T(k - n)) * ratio;\n"
           "      T next = sum + t / T(2 * k + 1);\n"
           "      if (!(ordered(next) < ordered(sum)) && !(ordered(sum) < ordered(next))) break;\n"
           "      sum = next;\n"
           "    }\n"
           "    return sum;\n"
           "  }\n"
           "  T s = sqrt(u);\n"
           "  // atan2(s, a) for a >= 0 and s > 0 without atan2, which a complex scalar lacks\n"
           "  T A = (ordered(s) < ordered(a) ? atan(s / a) : T(2) * atan(T(1)) - atan(a / s)) / s;\n"
           "  T c = a / (u + a * a);\n"
           "  for (int m = 0; m < n; ++m) {\n"
           "    A = (c - T(2 * m + 1) * A) / (T(2) * u);\n"
           "    c = -(c * T(m + 1)) / (u + a * a);\n"
           "  }\n"
           "  return A;\n"
           "}\n\n";
  return out;
}

}  // namespace eomgen
