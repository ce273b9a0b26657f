// One orientation of trigonometric arguments: cos(-x) = cos(x), sin(-x) = -sin(x),
// and the same two-link arm written three ways (cos(q1+q2), the addition theorem
// expanded, and with negated arguments) derives to the same canonical text.
#include <gtest/gtest.h>

#include "emit/formats.hpp"
#include "pipeline.hpp"
#include "symbolic/canonical_print.hpp"
#include "symbolic/trig_orientation.hpp"

namespace eomgen {
namespace {

using GiNaC::cos;
using GiNaC::sin;
using GiNaC::tan;

TEST(TrigOrientation, NegatedArgumentsBecomePositive) {
  GiNaC::realsymbol a("a"), b("b");
  EXPECT_EQ(canonical_text(orient_trigonometric_arguments(cos(-a))), "cos(a)");
  EXPECT_EQ(canonical_text(orient_trigonometric_arguments(sin(-a))), "-sin(a)");
  EXPECT_EQ(canonical_text(orient_trigonometric_arguments(tan(-a))), "-tan(a)");
  EXPECT_EQ(canonical_text(orient_trigonometric_arguments(cos(b - a))), canonical_text(cos(a - b)));
  EXPECT_EQ(canonical_text(orient_trigonometric_arguments(sin(b - a) + sin(a - b))), "0");
  // nested: the inner argument first
  EXPECT_EQ(canonical_text(orient_trigonometric_arguments(cos(sin(-a)))), "cos(sin(a))");
  // the value is unchanged
  GiNaC::ex e = 3 * sin(b - 2 * a) * cos(-b) + tan(a - b);
  GiNaC::exmap at{{a, GiNaC::numeric(3, 10)}, {b, GiNaC::numeric(-7, 10)}};
  EXPECT_NEAR(GiNaC::ex_to<GiNaC::numeric>((orient_trigonometric_arguments(e) - e).subs(at).evalf()).to_double(), 0, 1e-15);
}

std::string two_link_arm(const std::string& hand_x, const std::string& hand_y) {
  return "[model]\nname = \"arm\"\ntitle = \"two-link arm\"\n[parameters]\nm1 = 1.0\nm2 = 1.0\nl1 = 1.0\nl2 = 1.0\n"
         "g = 9.81\n[coordinates]\nq1 = 0.1\nq2 = 0.2\n[[particles]]\nname = \"elbow\"\nmass = \"m1\"\n"
         "position = [\"l1*cos(q1)\", \"l1*sin(q1)\", \"0\"]\n[[particles]]\nname = \"hand\"\nmass = \"m2\"\n"
         "position = [\"l1*cos(q1) + " + hand_x + "\", \"l1*sin(q1) + " + hand_y + "\", \"0\"]\n"
         "[gravity]\nacceleration = [\"0\", \"-g\", \"0\"]\n";
}

std::string canonical_equations(const std::string& text) {
  Derivation d = derive_model_text(text, "arm.toml");
  EXPECT_TRUE(d.diagnostics.empty()) << d.diagnostics.format();
  if (!d.equations) return {};
  std::string out = emit_canonical_text(*d.equations);
  return out.substr(out.find("\nM[0][0]"));
}

TEST(TrigOrientation, TheSameArmWrittenThreeWaysPrintsTheSame) {
  std::string sum = canonical_equations(two_link_arm("l2*cos(q1+q2)", "l2*sin(q1+q2)"));
  std::string expanded = canonical_equations(
      two_link_arm("l2*(cos(q1)*cos(q2) - sin(q1)*sin(q2))", "l2*(sin(q1)*cos(q2) + cos(q1)*sin(q2))"));
  std::string negated = canonical_equations(two_link_arm("l2*cos(-q2-q1)", "-l2*sin(-q1-q2)"));
  EXPECT_NE(sum.find("M[0][1] = l1*l2*m2*cos(q2) + l2^2*m2"), std::string::npos) << sum;
  EXPECT_EQ(sum.find("(-"), std::string::npos) << sum;
  EXPECT_EQ(expanded, sum);
  EXPECT_EQ(negated, sum);
}

}  // namespace
}  // namespace eomgen
