// IndependentRows (generator/common/independent_rows.hpp): a row in the span of the rows kept before
// it is dependent, whatever the rows' units (1e-12 to 1e12); a zero row is dependent; a row that
// leaves the span by 1e-6 of its size is independent, by 1e-12 not.
#include <gtest/gtest.h>

#include "common/independent_rows.hpp"

namespace eomgen::test {
namespace {

TEST(IndependentRows, ARowInTheSpanOfThoseBeforeIsDependentAtEveryScale) {
  for (double unit : {1e-12, 1.0, 1e12}) {
    IndependentRows rows;
    EXPECT_TRUE(rows.add({1 * unit, 2 * unit, 0}));
    EXPECT_TRUE(rows.add({0, 1 * unit, 1 * unit}));
    EXPECT_FALSE(rows.add({2 * unit, 5 * unit, 1 * unit})) << "2 r1 + r2, unit " << unit;
    EXPECT_FALSE(rows.add({0, 0, 0}));
    EXPECT_TRUE(rows.add({1 * unit, 3 * unit, (1 + 1e-6) * unit})) << "r1 + r2 moved off the span by 1e-6, unit " << unit;
  }
  IndependentRows rows;
  rows.add({1, 0});
  EXPECT_FALSE(rows.add({1, 1e-12})) << "off the span by 1e-12 of its size";
}

}  // namespace
}  // namespace eomgen::test
