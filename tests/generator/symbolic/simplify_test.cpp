#include <gtest/gtest.h>

#include "symbolic/canonical_print.hpp"
#include "symbolic/simplify.hpp"

namespace eomgen {
namespace {

using GiNaC::cos;
using GiNaC::sin;

struct Symbols2 {
  GiNaC::realsymbol a{"a"}, b{"b"}, m{"m"}, k{"k"};
  MotionSymbols motion;
  Symbols2() { motion.symbols = {a, b}; }
};

TEST(Simplify, ProductsOfSinesAndCosinesBecomeDifferences) {
  Symbols2 s;
  GiNaC::ex e = s.m * (cos(s.a) * cos(s.b) + sin(s.a) * sin(s.b));
  EXPECT_EQ(canonical_text(tidy(e, s.motion)), "m*cos(a - b)");
  GiNaC::ex f = s.m * (sin(s.a) * cos(s.b) - cos(s.a) * sin(s.b)) * s.k;
  EXPECT_EQ(canonical_text(tidy(f, s.motion)), "k*m*sin(a - b)");
  GiNaC::ex g = 3 * (cos(s.a) * cos(s.b) - sin(s.a) * sin(s.b));
  EXPECT_EQ(canonical_text(tidy(g, s.motion)), "3*cos(a + b)");
}

TEST(Simplify, LoneProductIsLeftAlone) {
  Symbols2 s;
  GiNaC::ex e = s.m * cos(s.a) * cos(s.b);
  EXPECT_TRUE(tidy(e, s.motion).is_equal(e));
}

TEST(Simplify, PythagorasRemovesSquares) {
  Symbols2 s;
  GiNaC::ex e = s.m * s.k * GiNaC::pow(sin(s.a), 2) + s.m * s.k * GiNaC::pow(cos(s.a), 2) + s.b;
  EXPECT_EQ(canonical_text(tidy(e, s.motion)), "b + k*m");
}

TEST(Simplify, PythagorasFiresWhateverTheSignInsideTheArgument) {
  Symbols2 s;
  GiNaC::ex e = s.m * GiNaC::pow(sin(-s.a), 2) + s.m * GiNaC::pow(cos(s.a), 2) + s.k * GiNaC::pow(cos(s.b - s.a), 2) +
                s.k * GiNaC::pow(sin(s.a - s.b), 2);
  EXPECT_EQ(canonical_text(tidy(e, s.motion)), "k + m");
}

TEST(Simplify, CollectsParametersByMotion) {
  Symbols2 s;
  GiNaC::ex e = s.m * cos(s.a) + s.k * cos(s.a) + s.m;
  EXPECT_EQ(canonical_text(tidy(e, s.motion)), "(k + m)*cos(a) + m");
}

TEST(Simplify, ResultEqualsInputAtRandomPoints) {
  Symbols2 s;
  GiNaC::ex e = GiNaC::pow(s.m * sin(s.a) + s.k * cos(s.b), 2) * cos(s.a - s.b) + sin(s.a) * sin(s.b) * s.k;
  GiNaC::ex t = tidy(e, s.motion);
  for (double x : {0.3, -1.2, 2.5})
    for (double y : {0.7, -2.1}) {
      GiNaC::exmap p{{s.a, x}, {s.b, y}, {s.m, 1.3}, {s.k, 0.4}};
      double u = GiNaC::ex_to<GiNaC::numeric>(e.subs(p).evalf()).to_double();
      double v = GiNaC::ex_to<GiNaC::numeric>(t.subs(p).evalf()).to_double();
      EXPECT_NEAR(u, v, 1e-13 * std::max(1.0, std::abs(u)));
    }
}

TEST(CanonicalPrint, ReadsBackWithGinacParser) {
  Symbols2 s;
  GiNaC::realsymbol v("der(a)");
  GiNaC::ex e = -GiNaC::numeric(1, 2) * s.m * GiNaC::pow(v, 2) / (s.k + s.m) + GiNaC::sqrt(s.k) * GiNaC::pow(s.a, -2) -
                3 * GiNaC::atan2(s.a, s.b) + GiNaC::pow(s.m, GiNaC::numeric(3, 2)) + GiNaC::Pi;
  std::string text = canonical_text(e);
  GiNaC::realsymbol dv("dv");
  std::string replaced = text;
  for (std::size_t p; (p = replaced.find("der(a)")) != std::string::npos;) replaced.replace(p, 6, "dv");
  GiNaC::symtab table{{"a", s.a}, {"b", s.b}, {"m", s.m}, {"k", s.k}, {"dv", dv}};
  GiNaC::ex back = GiNaC::parser(table, true)(replaced).subs(dv == v);
  EXPECT_TRUE((back - e).expand().is_zero()) << text;
}

TEST(CanonicalPrint, OrderDoesNotDependOnSymbolCreation) {
  std::string first, second;
  {
    GiNaC::realsymbol x("x"), y("y");
    first = canonical_text(sin(x - y) * x + y * y - 2 * x * y);
  }
  {
    GiNaC::realsymbol y("y"), x("x");
    second = canonical_text(sin(x - y) * x + y * y - 2 * x * y);
  }
  EXPECT_EQ(first, second);
}

}  // namespace
}  // namespace eomgen
