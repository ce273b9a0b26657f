// The angle of a quaternion's turn (symbolic/rotation_angle.hpp): atan_ratio(n, u, a), the n-th
// derivative in u of A(u, a) = atan2(sqrt(u), a)/sqrt(u), against GiNaC's own derivatives of that
// closed form taken to 40 digits (where u > 0), and against its series' first term at u = 0; in
// double (evaluate.cpp), in GiNaC's numbers and in the header's C++ (the same steps), on both sides
// of the cut between the series and the recurrence; its derivatives in a and u are the family's;
// rotation_angle gives the turn's angle for a quaternion of any length and either sign, and its
// square's derivatives are finite at the rest pose.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "symbolic/canonical_print.hpp"
#include "symbolic/evaluate.hpp"
#include "symbolic/magnitude.hpp"
#include "symbolic/rotation_angle.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

using GiNaC::ex;
using GiNaC::numeric;

// ∂ⁿ/∂uⁿ of atan(sqrt(u)/a)/sqrt(u) by GiNaC, at (u, a), to 40 digits
double closed_form_derivative(int n, double u, double a) {
  GiNaC::symbol U("U"), A("A");
  ex f = GiNaC::atan(GiNaC::sqrt(U) / A) / GiNaC::sqrt(U);
  ex d = f.diff(U, unsigned(n));
  long digits = GiNaC::Digits;
  GiNaC::Digits = 40;
  double value = GiNaC::ex_to<numeric>(d.subs(GiNaC::lst{U == numeric(u), A == numeric(a)}).evalf()).to_double();
  GiNaC::Digits = digits;
  return value;
}

double relative(double x, double y) { return std::abs(x - y) / std::max(std::abs(y), 1e-300); }

TEST(RotationAngle, TheRatiosFamilyIsTheClosedFormsDerivatives) {
  // u / a² from the series' far end through the cut at 0.3 to the recurrence's
  for (double a : {1.0, 0.37, 1e-3, 250.0})
    for (double ratio : {1e-12, 1e-6, 0.01, 0.2, 0.2999, 0.3001, 0.5, 1.0, 7.0, 1e4})
      for (int n = 0; n <= 3; ++n) {
        double u = ratio * a * a, exact = closed_form_derivative(n, u, a);
        double in_double = atan_ratio_value(n, u, a);
        double in_ginac = GiNaC::ex_to<numeric>(atan_ratio(n, numeric(u), numeric(a)).evalf()).to_double();
        // the recurrence loses up to a factor of about 6 per order near the cut (rotation_angle.cpp)
        EXPECT_LT(relative(in_double, exact), 2e-14 * std::pow(6, n)) << "n = " << n << ", u = " << u << ", a = " << a;
        EXPECT_LT(relative(in_ginac, exact), 1e-15) << "n = " << n << ", u = " << u << ", a = " << a;
      }
}

TEST(RotationAngle, AtNoTurnTheRatiosAreTheSeriesFirstTerms) {
  GiNaC::symbol a("a");
  for (int n = 0; n <= 4; ++n) {
    // (−1)^n n! / ((2n+1) a^(2n+1)), exactly
    ex first = GiNaC::pow(-1, n) * GiNaC::factorial(n) / ((2 * n + 1) * GiNaC::pow(a, 2 * n + 1));
    EXPECT_TRUE((atan_ratio(n, 0, a) - first).expand().is_zero()) << n;
    EXPECT_DOUBLE_EQ(atan_ratio_value(n, 0.0, 0.8), GiNaC::ex_to<numeric>(first.subs(a == numeric(4, 5)).evalf()).to_double());
  }
}

TEST(RotationAngle, ItsDerivativesAreTheFamilys) {
  GiNaC::symbol u("u"), a("a");
  EXPECT_TRUE((atan_ratio(2, u, a).diff(u) - atan_ratio(3, u, a)).is_zero());
  // ∂A/∂a = −1/(u + a²), and its n-th derivative in u
  EXPECT_TRUE((atan_ratio(0, u, a).diff(a) + 1 / (u + a * a)).normal().is_zero());
  EXPECT_TRUE((atan_ratio(2, u, a).diff(a) - (-1 / (u + a * a)).diff(u, 2)).normal().is_zero());
}

// the angle of the turn (w, x, y, z) states, the shorter way: 2 atan2(|v|, |w|) in long double
double turn_angle(double w, double x, double y, double z) {
  long double v = std::sqrt((long double)x * x + (long double)y * y + (long double)z * z);
  return double(2 * std::atan2(v, std::abs((long double)w)));
}

TEST(RotationAngle, IsTheTurnsAngleForAQuaternionOfAnyLengthAndSign) {
  GiNaC::symbol w("w"), x("x"), y("y"), z("z");
  ex theta = rotation_angle(w, x, y, z);
  for (const std::array<double, 4>& q : {std::array<double, 4>{0.9, 0.3, -0.2, 0.1}, {-0.9, 0.3, -0.2, 0.1}, {0.1, 0.7, 0.7, 0.1},
                                         {2.0, 0.0, 0.0, 1e-7}, {0.0, 1.0, 0.0, 0.0}, {-3.0, 1.0, 2.0, 2.0}}) {
    double value = evaluate(theta, [&](const GiNaC::symbol& s) { return s == w ? q[0] : s == x ? q[1] : s == y ? q[2] : q[3]; });
    EXPECT_NEAR(value, turn_angle(q[0], q[1], q[2], q[3]), 1e-14) << q[0] << " " << q[1] << " " << q[2] << " " << q[3];
  }
  EXPECT_EQ(canonical_text(rotation_angle(w, x, 0, 0)), "2*atan_ratio(0, x^2, abs(w))*sqrt(x^2)");
  EXPECT_EQ(latex_text(atan_ratio(1, x, w), [](const GiNaC::symbol& s) { return s.get_name(); }), "A^{(1)}\\left(x, w\\right)");
}

TEST(RotationAngle, ItsSquaresDerivativesAreFiniteWhereTheTurnVanishes) {
  GiNaC::symbol w("w"), x("x"), y("y"), z("z");
  ex square = GiNaC::pow(rotation_angle(w, x, y, z), 2);
  auto at_rest = [&](const GiNaC::symbol& s) { return s == w ? 1.0 : 0.0; };
  for (const GiNaC::symbol& s : {x, y, z}) {
    // θ² ≈ 4|v|²/w² near the rest: its slope there 0, its curvature 8/w²
    EXPECT_EQ(evaluate(square.diff(s), at_rest), 0.0);
    EXPECT_DOUBLE_EQ(evaluate(square.diff(s, 2), at_rest), 8.0);
  }
  EXPECT_EQ(evaluate(square.diff(w), at_rest), 0.0);
}

}  // namespace
}  // namespace eomgen::test
