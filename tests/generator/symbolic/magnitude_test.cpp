// abs(x) and sign(x) in a model's expressions (symbolic/magnitude.hpp): air drag c v |v| has the
// slope −2 c |v| in v, 0 at rest, where GiNaC's own abs had given v·v/|v| = 0/0 (a NaN in every
// Jacobian at rest); Coulomb friction μ sign(v) has the slope 0; numbers are taken at once; the
// equations print abs as the model wrote it and the header calls its own detail::magnitude
// (complex-step derivatives through it keep sign(x) x') and detail::sign.
#include <gtest/gtest.h>

#include <cmath>

#include "emit/cpp_expression.hpp"
#include "symbolic/canonical_print.hpp"
#include "symbolic/evaluate.hpp"
#include "symbolic/magnitude.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

const char* const sliding_block = R"toml(
[model]
name = "sliding_block"
[parameters]
m = 2.0
c = 0.3
mu = 0.5
[coordinates]
x = 0
[[particles]]
name = "block"
mass = "m"
position = ["x", "0", "0"]
[[forces]]
generalized = { x = "-c*der(x)*abs(der(x)) - mu*sign(der(x))" }
)toml";

TEST(Magnitude, DragAndFrictionHaveTheirSlopesAtRestToo) {
  Equations e = derive_text(sliding_block);
  const GiNaC::symbol& v = e.symbols.velocities[0];
  GiNaC::ex force = e.forcing[0], slope = force.diff(v);
  const double c = 0.3, mu = 0.5;
  for (double speed : {0.0, 2.0, -3.0, 1e-300}) {
    GiNaC::exmap at = point_by_name(e, {{"m", 2}, {"c", c}, {"mu", mu}, {"x", 0}, {"der(x)", speed}});
    double sign_of_speed = speed > 0 ? 1 : (speed < 0 ? -1 : 0);
    EXPECT_DOUBLE_EQ(value_at(force, at), -c * speed * std::abs(speed) - mu * sign_of_speed) << "v = " << speed;
    EXPECT_DOUBLE_EQ(value_at(slope, at), -2 * c * std::abs(speed)) << "v = " << speed << ": 0 at rest, not 0/0";
  }
  EXPECT_TRUE(slope.diff(v).diff(v).is_zero()) << "sign is piecewise constant: " << slope.diff(v);
}

TEST(Magnitude, NumbersAreTakenAtOnce) {
  GiNaC::realsymbol x("x");
  EXPECT_EQ(magnitude(GiNaC::numeric(-3, 2)), GiNaC::numeric(3, 2));
  EXPECT_EQ(sign(GiNaC::numeric(-2)), -1);
  EXPECT_EQ(sign(GiNaC::numeric(0)), 0);
  EXPECT_EQ(sign(GiNaC::numeric(1, 7)), 1);
  EXPECT_EQ(magnitude(x).diff(x), sign(x));
  // an even power of |x| is that power of x; an odd one keeps |x|
  EXPECT_TRUE((GiNaC::pow(magnitude(x), 2) - x * x).is_zero());
  EXPECT_TRUE((GiNaC::pow(magnitude(x), -4) - GiNaC::pow(x, -4)).is_zero());
  EXPECT_FALSE((GiNaC::pow(magnitude(x), 3) - GiNaC::pow(x, 3)).is_zero());
  auto at = [](double value) { return [value](const GiNaC::symbol&) { return value; }; };
  EXPECT_DOUBLE_EQ(evaluate(magnitude(x), at(-2.5)), 2.5);
  EXPECT_DOUBLE_EQ(evaluate(sign(x), at(-2.5)), -1.0);
  EXPECT_DOUBLE_EQ(evaluate(sign(x), at(0.0)), 0.0);
}

TEST(Magnitude, TheEquationsWriteAbsAndTheHeaderItsOwnFunctions) {
  GiNaC::realsymbol u("u");
  auto name = [](const GiNaC::symbol& s) { return s.get_name(); };
  EXPECT_EQ(canonical_text(magnitude(u)), "abs(u)");
  EXPECT_EQ(canonical_text(sign(u)), "sign(u)");
  EXPECT_EQ(cpp_expression(magnitude(u), name), "detail::magnitude(u)");
  EXPECT_EQ(cpp_expression(sign(u), name), "detail::sign(u)");
  Equations e = derive_text(sliding_block);
  EXPECT_EQ(canonical_text(e.forcing[0]).find("magnitude"), std::string::npos) << canonical_text(e.forcing[0]);
}

}  // namespace
}  // namespace eomgen::test
