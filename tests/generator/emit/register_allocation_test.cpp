// emit/cpp_register_allocation: a gradient-like function template, once wrapped for IRA's priority
// colouring and once not, in one program compiled by g++ and clang++ (C++17 and C++20, warnings as
// errors, so that an option g++ did not take, a "bad option" warning, fails): both give the same
// results to the last bit, since the option decides only which register holds which value.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "emit/cpp_register_allocation.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

// long dependent sums, divisions and square roots of many live values: register pressure, and
// rounding in every entry, so that other operations or another order would show in some bit
const char* gradient_source = R"cpp(template <class T>
void gradient(const T* x, T* F) {
  T v[24];
  for (int i = 0; i < 24; ++i) v[i] = sqrt(T(1) + x[i % 6] * x[(i + 1) % 6] + T(i)) / (T(2) + x[(i + 3) % 6]);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 12; ++j) {
      T sum = T(0);
      for (int k = 0; k < 24; ++k) sum = sum + v[k] * v[(k + i + j) % 24] / (T(1) + k + j);
      F[12 * i + j] = sum - x[i] * v[j];
    }
}
)cpp";

const char* check_source = R"cpp(
#include <cstdio>
#include <cstring>
int main() {
  volatile double seed = 0.3;  // read at run time: not folded into constants by the compiler
  const double x[6] = {seed, -1.7 * seed, 2.9, 0.11 + seed, -0.45, 1.3};
  double F[2][72];
  plain::gradient(x, F[0]);
  wrapped::gradient(x, F[1]);
  int differ = std::memcmp(F[0], F[1], sizeof F[0]) != 0;
  std::printf("%s\n", differ ? "the wrapped function's results differ" : "the same bits");
  return differ;
}
)cpp";

TEST(RegisterAllocation, OnlyGccSeesThePragmaWhichSetsNoOptimizationLevel) {
  std::string text = with_priority_register_allocation("void f();\n");
  std::size_t guard = text.find("#if defined(__GNUC__) && !defined(__clang__)\n#pragma GCC push_options\n");
  std::size_t option = text.find("#pragma GCC optimize(\"ira-algorithm=priority\")\n#endif\nvoid f();\n");
  std::size_t back = text.find("void f();\n#if defined(__GNUC__) && !defined(__clang__)\n#pragma GCC pop_options\n#endif\n");
  EXPECT_EQ(guard, 0u) << text;
  EXPECT_NE(option, std::string::npos) << text;
  EXPECT_NE(back, std::string::npos) << text;
  // no -O level in the pragma: it would replace the user's
  EXPECT_EQ(text.find("optimize(\"O"), std::string::npos) << text;
}

TEST(RegisterAllocation, TheWrappedFunctionCompilesWithoutWarningsAndGivesTheSameBits) {
  std::string program = "#include <cmath>\nusing std::sqrt;\nnamespace plain {\n" + std::string(gradient_source) +
                        "}\nnamespace wrapped {\n" + with_priority_register_allocation(gradient_source) + "}\n" + check_source;
  for (const std::string compiler : {"g++", "clang++"}) {
    if (run_command("command -v " + compiler + " > /dev/null") != 0) continue;
    for (const char* flags : {"-std=c++17 -O2", "-std=c++20 -O3 -ffast-math", "-std=c++17 -O0"}) {
      std::string dir = temporary_directory();
      std::ofstream(dir + "/check.cpp") << program;
      EXPECT_EQ(run_command("cd '" + dir + "' && " + compiler + " " + flags + " -Wall -Wextra -Wpedantic -Werror check.cpp -o check && ./check"),
                0)
          << compiler << " " << flags;
    }
  }
}

}  // namespace
}  // namespace eomgen::test
