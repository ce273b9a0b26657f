// Common subexpressions (symbolic/cse.hpp): a call whose square the printer writes as the call
// twice, f*f, is a temporary even where the square is its only use, so that the header calls it once
// (a ball spring's ½ k θ² had called atan_ratio twice); a square of a symbol stays as it is.
#include <gtest/gtest.h>

#include <ginac/ginac.h>

#include "symbolic/cse.hpp"

namespace eomgen::test {
namespace {

using GiNaC::ex;

TEST(CommonSubexpressions, TheSquaredCallIsComputedOnce) {
  GiNaC::symbol x("x"), y("y"), z("z");
  for (int k : {2, 3, -2}) {
    CommonSubexpressions cse;
    CseBatch batch = cse.add({GiNaC::pow(GiNaC::sin(x + y), k) * z});
    ASSERT_EQ(batch.temporaries.size(), 1u) << k;
    EXPECT_TRUE(batch.temporaries[0].definition.is_equal(GiNaC::sin(x + y))) << batch.temporaries[0].definition;
    EXPECT_TRUE(batch.outputs[0].is_equal(GiNaC::pow(batch.temporaries[0].name, k) * z)) << batch.outputs[0];
  }
}

TEST(CommonSubexpressions, ASquaredSymbolAndACallUsedOnceStayInline) {
  GiNaC::symbol x("x"), y("y");
  CommonSubexpressions cse;
  CseBatch batch = cse.add({GiNaC::pow(x, 2) * GiNaC::sin(y), GiNaC::pow(GiNaC::sin(x), 5)});
  EXPECT_TRUE(batch.temporaries.empty());
  EXPECT_TRUE(batch.outputs[0].is_equal(GiNaC::pow(x, 2) * GiNaC::sin(y)));
}

}  // namespace
}  // namespace eomgen::test
