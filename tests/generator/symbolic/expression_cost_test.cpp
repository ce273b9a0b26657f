// The operations an expression costs (symbolic/expression_cost.hpp), counted on GiNaC's tree as
// the generated code would evaluate it: sums and products one per operand after the first, a
// coefficient of −1 a subtraction, whole powers by repeated products (and a division where
// negative), functions and other powers ten each; and the joint tree's choice that counts with it.
#include <gtest/gtest.h>

#include "symbolic/expression_cost.hpp"

namespace eomgen::test {
namespace {

TEST(ExpressionCost, CountsTheOperationsOfTheTree) {
  GiNaC::symbol a("a"), b("b"), c("c");
  EXPECT_EQ(arithmetic_operations(a), 0);
  EXPECT_EQ(arithmetic_operations(GiNaC::ex(3)), 0);
  EXPECT_EQ(arithmetic_operations(a * b + c), 2);
  EXPECT_EQ(arithmetic_operations(a * b - c), 2) << "−c is a subtraction";
  EXPECT_EQ(arithmetic_operations(-a * b), 1);
  EXPECT_EQ(arithmetic_operations(3 * a * b + 2), 3);
  EXPECT_EQ(arithmetic_operations(GiNaC::pow(a, 3)), 2);
  EXPECT_EQ(arithmetic_operations(1 / a), 1);
  EXPECT_EQ(arithmetic_operations(GiNaC::pow(a + b, -2)), 3);
  EXPECT_EQ(arithmetic_operations(GiNaC::sqrt(a)), 10);
  EXPECT_EQ(arithmetic_operations(GiNaC::sin(a * b) + 1), 12);
  EXPECT_EQ(arithmetic_operations(std::vector<GiNaC::ex>{a * b, a + b + c, GiNaC::ex(0)}), 3);
}

}  // namespace
}  // namespace eomgen::test
