// The using-declarations of a generated function (emit/cpp_expression's cpp_math_usings): exactly
// the std math functions its statements call unqualified, in a fixed order, six to a line.
#include <gtest/gtest.h>

#include <string>

#include "emit/cpp_expression.hpp"

namespace eomgen::test {
namespace {

TEST(MathUsings, NameTheFunctionsCalledAndNoOthers) {
  EXPECT_EQ(cpp_math_usings("  const T a = cos(q) + sin(q)*sqrt(r);\n"), "using std::sin; using std::cos; using std::sqrt;");
  EXPECT_EQ(cpp_math_usings("  const T a = atan2(y, x);\n"), "using std::atan2;");
  EXPECT_EQ(cpp_math_usings("  const T a = atan(y);\n"), "using std::atan;");
}

// names inside identifiers, qualified calls and the header's own functions need none
TEST(MathUsings, AreEmptyWhereNothingIsCalledUnqualified) {
  EXPECT_EQ(cpp_math_usings(""), "");
  EXPECT_EQ(cpp_math_usings("  detail::sin_cos(trig_angle, trig_sin, trig_cos);\n"
                            "  const T sin_q = trig_sin[0];\n"
                            "  const T a = std::exp(b) + k_log(c) + detail::magnitude(d) + powers[2];\n"),
            "");
}

TEST(MathUsings, WrapAfterSixDeclarations) {
  EXPECT_EQ(cpp_math_usings("sin(a) cos(a) tan(a) asin(a) acos(a) atan(a) exp(a)"),
            "using std::sin; using std::cos; using std::tan; using std::asin; using std::acos; using std::atan;\n"
            "  using std::exp;");
}

}  // namespace
}  // namespace eomgen::test
