// emit/cpp_avx_dispatch: a function template as the emitter writes it, with the two signatures
// that get a copy for AVX2 and FMA (the fused gradient's, which solves for q'' inside, and
// inverse_dynamics_gradient's, at a given q''), followed by the copy and the double overload.
// Compiled with g++ and clang++ (C++17 and C++20, warnings as errors) and run: with
// -ffp-contract=off the overload and the copy give the template's double results to the last bit
// (the copy does the template's operations); with the compilers' default contraction the copy fuses
// multiplies and adds and agrees with the template within rounding; with -mavx (where __AVX__ says
// the whole program has AVX) and with EOMGEN_NO_AVX_DISPATCH there is no copy, and the program
// still compiles and calls the template.
#include <gtest/gtest.h>

#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "emit/cpp_avx_dispatch.hpp"
#include "emit/cpp_ldlt.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

// divisions, square roots and long sums: rounding in every entry, so that a copy that did other
// operations, or the same ones in another order, would differ in some bit, and one that fused
// multiplies and adds would differ in some entry within rounding
const char* fused_gradient_source = R"cpp(template <class T>
void fused_gradient(T t, const T* x, const input_t<T>* u, const T* p, const T* given_ddq, T* L, T* D, T* F) {
  T ddq[3];
  for (int i = 0; i < 3; ++i) ddq[i] = given_ddq ? given_ddq[i] : (x[i] * p[0] + u[i]) / (T(3) + x[3 + i] * x[3 + i]);
  for (int i = 0; i < 3; ++i) {
    D[i] = sqrt(T(1) + x[i] * x[i] + t);
    for (int j = 0; j < 3; ++j) L[3 * i + j] = (x[i] - x[j]) / D[i] + p[1] * ddq[j];
    for (int j = 0; j < 6; ++j) {
      T sum = T(0);
      for (int k = 0; k < 6; ++k) sum = sum + x[k] * x[(j + k) % 6] / (T(1) + k) - ddq[i] * p[2];
      F[6 * i + j] = sum * T(0.1) + u[i] * x[j];
    }
  }
}
)cpp";

const char* inverse_dynamics_gradient_source = R"cpp(template <class T>
void inverse_dynamics_gradient(T t, const T* x, const T* ddq, const input_t<T>* u, const T* p, T* F) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 6; ++j) F[6 * i + j] = sqrt(T(2) + x[j] * x[j]) / (p[0] + ddq[i]) - u[i] * t / T(7);
}
)cpp";

const char* avx_check_source = R"cpp(
#include <cmath>
#include <cstdio>
#include <cstring>
#include <initializer_list>
#include <limits>
// the copy's results against the template's: the same bits (SAME_BITS), or each within 64 units of
// rounding of the larger of 1 and the largest result (fused multiply-adds round once where the
// template rounds twice, in sums of a few terms of about that size)
bool differ(const double* a, const double* b, int n) {
#ifdef SAME_BITS
  return std::memcmp(a, b, sizeof(double) * std::size_t(n)) != 0;
#else
  double scale = 1, most = 0;
  for (int i = 0; i < n; ++i) scale = std::fmax(scale, std::fabs(a[i]));
  for (int i = 0; i < n; ++i) most = std::fmax(most, std::fabs(a[i] - b[i]));
  return !(most <= 64 * std::numeric_limits<double>::epsilon() * scale);
#endif
}
int main() {
  const double x[6] = {0.3, -1.7, 2.9, 0.11, -0.45, 1.3}, u[3] = {0.2, -0.9, 1.1}, p[3] = {9.81, 0.37, -2.2};
  const double ddq[3] = {1.5, -0.25, 3.75};
  int failures = 0;
  for (const double* given : {static_cast<const double*>(nullptr), ddq}) {
    double L[2][9], D[2][3], F[2][18];
    fused_gradient<double>(0.25, x, u, p, given, L[0], D[0], F[0]);
    fused_gradient(0.25, x, u, p, given, L[1], D[1], F[1]);
    failures += differ(L[0], L[1], 9) || differ(D[0], D[1], 3) || differ(F[0], F[1], 18);
#ifdef EXPECT_COPY
    fused_gradient_fma(0.25, x, u, p, given, L[1], D[1], F[1]);
    failures += differ(L[0], L[1], 9) || differ(D[0], D[1], 3) || differ(F[0], F[1], 18);
#endif
  }
  double G[2][18];
  inverse_dynamics_gradient<double>(0.5, x, ddq, u, p, G[0]);
  inverse_dynamics_gradient(0.5, x, ddq, u, p, G[1]);
  failures += differ(G[0], G[1], 18);
#ifdef EXPECT_COPY
  inverse_dynamics_gradient_fma(0.5, x, ddq, u, p, G[1]);
  failures += differ(G[0], G[1], 18);
#endif
  std::printf("%d results differ from the template's\n", failures);
  return failures;
}
)cpp";

std::string avx_dispatch_program() {
  return std::string("#include <cmath>\nusing std::sqrt;\ntemplate <class T>\nusing input_t = T;\n") +
         with_avx_dispatch(fused_gradient_source) + with_avx_dispatch(inverse_dynamics_gradient_source) + avx_check_source;
}

int compile_and_run_avx_check(const std::string& compiler, const std::string& flags, bool quiet = false) {
  std::string dir = temporary_directory();
  std::ofstream(dir + "/check.cpp") << avx_dispatch_program();
  return run_command("cd '" + dir + "' && " + compiler + " " + flags + " -Wall -Wextra -Wpedantic -Werror check.cpp -o check" +
                     (quiet ? " 2> /dev/null" : "") + " && ./check");
}

TEST(AvxDispatch, TheCopyAndTheOverloadGiveTheTemplatesResultsWithGccAndClang) {
#if !defined(__x86_64__)
  GTEST_SKIP() << "the copy is for x86-64";
#else
  if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) GTEST_SKIP() << "this processor has no AVX2 and FMA";
  std::vector<std::string> compilers{"g++"};
  if (run_command("command -v clang++ > /dev/null") == 0) compilers.push_back("clang++");
  for (const std::string& compiler : compilers)
    for (const char* standard : {"-std=c++17", "-std=c++20"}) {
      EXPECT_EQ(compile_and_run_avx_check(compiler, std::string(standard) + " -O2 -DEXPECT_COPY"), 0) << compiler << " " << standard;
      EXPECT_EQ(compile_and_run_avx_check(compiler, std::string(standard) + " -O2 -ffp-contract=off -DEXPECT_COPY -DSAME_BITS"), 0)
          << compiler << " " << standard;
    }
#endif
}

// The tolerance above is no wider than fused multiply-adds need: the default build's copy does
// differ from the template in some bit (else the test of the results within rounding would test
// nothing fused)
TEST(AvxDispatch, TheDefaultCopyFusesMultipliesAndAdds) {
#if !defined(__x86_64__)
  GTEST_SKIP() << "the copy is for x86-64";
#else
  if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) GTEST_SKIP() << "this processor has no AVX2 and FMA";
  EXPECT_NE(compile_and_run_avx_check("g++", "-std=c++17 -O2 -DEXPECT_COPY -DSAME_BITS", true), 0);
#endif
}

TEST(AvxDispatch, NoCopyWhereTheProgramHasAvxOrTheMacroSaysNot) {
#if !defined(__x86_64__)
  GTEST_SKIP() << "the copy is for x86-64";
#else
  if (!__builtin_cpu_supports("avx")) GTEST_SKIP() << "this processor has no AVX";
  // fused_gradient_fma would not be declared: EXPECT_COPY left out, and the overload's call
  // resolves to the template
  EXPECT_EQ(compile_and_run_avx_check("g++", "-std=c++17 -O2 -mavx"), 0);
  EXPECT_EQ(compile_and_run_avx_check("g++", "-std=c++17 -O2 -DEOMGEN_NO_AVX_DISPATCH"), 0);
  EXPECT_NE(compile_and_run_avx_check("g++", "-std=c++17 -O2 -DEOMGEN_NO_AVX_DISPATCH -DEXPECT_COPY", true), 0)
      << "with the macro the copy must be left out";
#endif
}

// M's solve for many columns (emit/cpp_ldlt), dense unrolled, dense in loops and a tree's, each
// with its AVX copy: at random L and D, the overload (the copy from 8 columns on) and the copy give
// the template's bits for 42, 14, 9 and 6 columns (remainders of 2, 2, 1 and 2 after the
// four-wide loop), with g++ and clang++; with -mavx (no copy) the overload is left out.
std::string solves_in(const std::string& name, const LdltCode& code, std::size_t n) {
  return "namespace " + name + " {\n" + solve_rows_functions(code, n) + "}\n";
}

const char* solve_rows_check = R"cpp(
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>
template <std::size_t m, class Template, class Overload, class Copy>
int same_bits(int n, Template by_template, Overload overload, Copy copy) {
  std::mt19937 g(5);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> L(n * n), D(n), B(n * m);
  for (double& l : L) l = u(g);
  for (double& d : D) d = 1.5 + u(g) / 2;
  for (double& b : B) b = u(g);
  std::vector<double> X = B, Y = B, Z = B;
  by_template(L.data(), D.data(), X.data());
  overload(L.data(), D.data(), Y.data());
#ifdef EXPECT_COPY
  copy(L.data(), D.data(), Z.data());
#else
  (void)copy;
  Z = X;
#endif
  int differ = std::memcmp(X.data(), Y.data(), X.size() * sizeof(double)) != 0;
  differ += std::memcmp(X.data(), Z.data(), X.size() * sizeof(double)) != 0;
  if (differ) std::printf("n = %d, m = %zu: results differ from the template's\n", n, m);
  return differ;
}
#ifdef EXPECT_COPY
#define COPY(ns, m) ns::ldlt_solve_rows_avx<m, true>
#else
#define COPY(ns, m) 0
#endif
#define SAME_BITS(ns, n, m) \
  same_bits<m>(n, ns::ldlt_solve_rows<m, true, double>, \
               [](const double* L, const double* D, double* B) { ns::ldlt_solve_rows<m, true>(L, D, B); }, COPY(ns, m))
int main() {
  int failures = 0;
  failures += SAME_BITS(unrolled, 7, 14) + SAME_BITS(unrolled, 7, 9) + SAME_BITS(unrolled, 7, 6);
  failures += SAME_BITS(loops, 30, 42) + SAME_BITS(loops, 30, 9);
  failures += SAME_BITS(tree, 14, 42) + SAME_BITS(tree, 14, 14) + SAME_BITS(tree, 14, 6);
  return failures;
}
)cpp";

TEST(AvxDispatch, TheSolveForManyColumnsGivesTheTemplatesBits) {
#if !defined(__x86_64__)
  GTEST_SKIP() << "the AVX copy is for x86-64";
#else
  if (!__builtin_cpu_supports("avx")) GTEST_SKIP() << "this processor has no AVX";
  std::string program = "#include <cstddef>\n" + solves_in("unrolled", ldlt_code(7), 7) + solves_in("loops", ldlt_code(30), 30) +
                        solves_in("tree", tree_ldlt_code({-1, 0, 1, 2, 3, 4, 5, 6, 7, 5, 9, 10, 5, 12}), 14) +
                        solve_rows_check;
  ASSERT_FALSE(ldlt_code(30).unrolled) << "the loops are checked";
  for (const std::string compiler : {"g++", "clang++"}) {
    if (run_command("command -v " + compiler + " > /dev/null") != 0) continue;
    for (const char* flags : {"-std=c++17 -O2 -DEXPECT_COPY", "-std=c++20 -O2 -mavx"}) {
      std::string dir = temporary_directory();
      std::ofstream(dir + "/solve.cpp") << program;
      EXPECT_EQ(run_command("cd '" + dir + "' && " + compiler + " " + flags +
                            " -Wall -Wextra -Wpedantic -Werror solve.cpp -o solve && ./solve"),
                0)
          << compiler << " " << flags;
    }
  }
#endif
}

TEST(AvxDispatch, OnlyAFunctionTemplateIsCopied) {
  EXPECT_THROW(with_avx_dispatch("inline void f(double x) {}\n"), std::logic_error);
}

}  // namespace
}  // namespace eomgen::test
