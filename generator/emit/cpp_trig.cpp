#include "emit/cpp_trig.hpp"

#include <fmt/format.h>

namespace eomgen {

// The polynomials are Chebyshev fits (mpmath's chebyfit, 50 digits) on z = r² ∈ [0, (π/4)²] of
// (sin r − r)/r³ and (cos r − 1 + r²/2)/r⁴, degree 5 each: fit errors 2.0e-17 and 1.3e-18, far
// below half an ulp of sin r and cos r. π/2 = C1 + C2 + C3 with C1 and C2 of 33 significant bits,
// so that k C1 and k C2 are exact for k < 2^20 (Cody and Waite's reduction).
std::string sin_cos_function() {
  return fmt::format(
      "/// sin and cos of every angle at once, for the coordinates a function takes the sine or cosine of.\n"
      "template <std::size_t N, class T>\n"
      "inline void sin_cos(const T (&angle)[N], T (&s)[N], T (&c)[N]) {{\n"
      "  using std::sin; using std::cos;\n"
      "  for (std::size_t i = 0; i < N; ++i) {{\n"
      "    s[i] = sin(angle[i]);\n"
      "    c[i] = cos(angle[i]);\n"
      "  }}\n"
      "}}\n\n"
      "// EOMGEN_STD_SIN_COS, defined before the header is included, keeps std::sin and std::cos for double\n"
      "// too (the C library's values to the last bit, at about twice the cost); so does -ffast-math, whose\n"
      "// reassociation would undo the reduction below (as would -fassociative-math alone: define it then).\n"
      "#if defined(__GNUC__) && !defined(__FAST_MATH__) && !defined(EOMGEN_STD_SIN_COS)\n"
      "using double_pair = double __attribute__((vector_size(16)));\n"
      "using uint64_pair = unsigned long long __attribute__((vector_size(16)));\n\n"
      "/// x = k pi/2 + r with |r| <= pi/4, then (sin, cos) = (sin r, cos r), (cos r, -sin r), (-sin r, -cos r)\n"
      "/// or (-cos r, sin r) as k mod 4 = 0, 1, 2, 3; within 2 ulp of the exact values for |x| < {0:g}.\n"
      "/// x 2/pi + 1.5 2^52 rounds to the integer k + 1.5 2^52, k in the low bits of its mantissa;\n"
      "/// r = x - k pi/2 as r + r_low (two-sum), r_low carried into the polynomials to first order.\n"
      "inline void sin_cos_pair(double_pair x, double_pair& s, double_pair& c) {{\n"
      "  const double_pair shifted = x * 0x1.45f306dc9c883p-1 + 0x1.8p52;\n"
      "  const double_pair kd = shifted - 0x1.8p52;\n"
      "  uint64_pair k;\n"
      "  __builtin_memcpy(&k, &shifted, sizeof k);\n"
      "  const double_pair a = x - kd * 0x1.921fb544p+0, b = kd * 0x1.0b4611a6p-34;\n"
      "  const double_pair a_minus_b = a - b, b_rounded = a - a_minus_b;\n"
      "  const double_pair low = ((a - (a_minus_b + b_rounded)) + (b_rounded - b)) - kd * 0x1.3198a2e037073p-69;\n"
      "  const double_pair r = a_minus_b + low, r_low = low - (r - a_minus_b);\n"
      "  const double_pair z = r * r;\n"
      "  const double_pair sin_r = r + r * z * (-0x1.5555555555555p-3 + z * (0x1.1111111110bb2p-7 + z * (-0x1.a01a019e83aaep-13 +\n"
      "      z * (0x1.71de37968a100p-19 + z * (-0x1.ae600b02b6262p-26 + z * 0x1.5e0b19f8b1451p-33))))) + r_low * (1.0 - 0.5 * z);\n"
      "  const double_pair cos_r = (1.0 - 0.5 * z) + z * z * (0x1.5555555555555p-5 + z * (-0x1.6c16c16c16967p-10 +\n"
      "      z * (0x1.a01a019f4eb01p-16 + z * (-0x1.27e4fa17da09ep-22 + z * (0x1.1eeb68e93b64cp-29 + z * -0x1.907da367a37cbp-37))))) - r_low * r;\n"
      "  const uint64_pair odd = -(k & 1ULL);  // all bits set where k is odd\n"
      "  uint64_pair sin_bits, cos_bits;\n"
      "  __builtin_memcpy(&sin_bits, &sin_r, sizeof sin_bits);\n"
      "  __builtin_memcpy(&cos_bits, &cos_r, sizeof cos_bits);\n"
      "  const uint64_pair sin_k = ((cos_bits & odd) | (sin_bits & ~odd)) ^ ((k & 2ULL) << 62);\n"
      "  const uint64_pair cos_k = ((sin_bits & odd) | (cos_bits & ~odd)) ^ (((k + 1ULL) & 2ULL) << 62);\n"
      "  __builtin_memcpy(&s, &sin_k, sizeof s);\n"
      "  __builtin_memcpy(&c, &cos_k, sizeof c);\n"
      "}}\n\n"
      "/// For double: two angles at a time by sin_cos_pair; std::sin and std::cos where |angle| >= {0:g}\n"
      "/// (the reduction's products would no longer be exact), for NaN, infinities and 0 (whose sign sin keeps).\n"
      "template <std::size_t N>\n"
      "inline void sin_cos(const double (&angle)[N], double (&s)[N], double (&c)[N]) {{\n"
      "  for (std::size_t i = 0; i + 1 < N; i += 2) {{\n"
      "    double_pair sp, cp;\n"
      "    sin_cos_pair(double_pair{{angle[i], angle[i + 1]}}, sp, cp);\n"
      "    s[i] = sp[0]; s[i + 1] = sp[1]; c[i] = cp[0]; c[i + 1] = cp[1];\n"
      "  }}\n"
      "  if constexpr (N % 2 == 1) {{\n"
      "    double_pair sp, cp;\n"
      "    sin_cos_pair(double_pair{{angle[N - 1], 0.0}}, sp, cp);\n"
      "    s[N - 1] = sp[0]; c[N - 1] = cp[0];\n"
      "  }}\n"
      "  for (std::size_t i = 0; i < N; ++i)\n"
      "    if (!(std::abs(angle[i]) > 0.0 && std::abs(angle[i]) < {0:g})) {{  // no == on doubles: -Wfloat-equal\n"
      "      s[i] = std::sin(angle[i]);\n"
      "      c[i] = std::cos(angle[i]);\n"
      "    }}\n"
      "}}\n"
      "#endif\n\n",
      sin_cos_reduction_limit);
}

}  // namespace eomgen
