// clamp(x, lo, hi) in a model's expressions (symbolic/clamp.hpp): a clamped input's force is
// gain × clamp(u, lo, hi), its slope in u 1 inside the range and 0 outside (below(a, b), the
// indicator it is written with, is piecewise constant), numbers clamp at once, the generated
// C++ calls the header's own detail::clamp and detail::below, and the text form reads back.
#include <gtest/gtest.h>

#include "emit/cpp_expression.hpp"
#include "symbolic/clamp.hpp"
#include "symbolic/evaluate.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

const char* const clamped_motor = R"toml(
[model]
name = "clamped_motor"
[parameters]
m = 2.0
[inputs]
u = 0.0
[coordinates]
x = 0
[[particles]]
name = "slider"
mass = "m"
position = ["x", "0", "0"]
[[forces]]
generalized = { x = "3*clamp(u, -1, 0.5)" }
)toml";

TEST(Clamp, AClampedInputsForceAndItsSlope) {
  Equations e = derive_text(clamped_motor);
  GiNaC::ex force = e.forcing[0], slope = force.diff(e.symbols.inputs[0]);
  for (auto [u, expected_force, expected_slope] : {std::tuple{0.2, 0.6, 3.0}, {-3.0, -3.0, 0.0}, {2.0, 1.5, 0.0}, {0.5, 1.5, 3.0}}) {
    GiNaC::exmap at = point_by_name(e, {{"m", 2}, {"x", 0}, {"der(x)", 0}});
    at[e.symbols.inputs[0]] = u;
    EXPECT_DOUBLE_EQ(value_at(force, at), expected_force) << "u = " << u;
    EXPECT_DOUBLE_EQ(value_at(slope, at), expected_slope) << "u = " << u;
  }
  EXPECT_TRUE(slope.diff(e.symbols.inputs[0]).is_zero()) << "below is piecewise constant";
}

TEST(Clamp, NumbersClampAtOnceAndTheSlopesInTheBounds) {
  GiNaC::realsymbol x("x"), lo("lo"), hi("hi");
  EXPECT_EQ(clamp(GiNaC::numeric(3), -1, 2), 2);
  EXPECT_EQ(clamp(GiNaC::numeric(-3), -1, 2), -1);
  EXPECT_EQ(clamp(GiNaC::numeric(1, 2), -1, 2), GiNaC::numeric(1, 2));
  EXPECT_EQ(clamp(x, lo, hi).diff(lo), below(x, lo));
  EXPECT_EQ(clamp(x, lo, hi).diff(hi), below(hi, x));
  EXPECT_DOUBLE_EQ(evaluate(clamp(x, -1, 2), [&](const GiNaC::symbol&) { return 5.0; }), 2.0);
  EXPECT_DOUBLE_EQ(evaluate(below(x, 2), [&](const GiNaC::symbol&) { return 1.0; }), 1.0);
}

TEST(Clamp, TheHeaderCallsItsOwnClamp) {
  GiNaC::realsymbol u("u");
  auto name = [](const GiNaC::symbol& s) { return s.get_name(); };
  EXPECT_EQ(cpp_expression(clamp(u, -1, 2), name), "detail::clamp(u, -T(1), T(2))");
  EXPECT_EQ(cpp_expression(below(u, 2), name), "detail::below(u, T(2))");
}

}  // namespace
}  // namespace eomgen::test
