// Numbers from real data in generated code: exact constants for every scalar type
// (no integer literal overflows), exact decimals in the printed equations, and the
// headers of two models with 17-digit numbers (models/measured_arm.toml: a 3-D arm with
// full inertia tensors and products of inertia of 2e-20; models/nearly_unit_mass.toml:
// a mass of 1 + 1.5e-20) against their derived equations evaluated in 50-digit
// arithmetic, in double, long double and __float128.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <random>

#include "emit/cpp_constant.hpp"
#include "emit/cpp_expression.hpp"
#include "reference/reference_solution.hpp"
#include "support/test_support.hpp"
#include "symbolic/canonical_print.hpp"
#include "symbolic/decimal_numbers.hpp"
#include "symbolic/exact_double.hpp"

#include "../generated/measured_arm.hpp"
#include "../generated/nearly_unit_mass.hpp"

namespace eomgen::test {
namespace {

using GiNaC::numeric;

// a square in a denominator is one factor: x/((a + b)*(a + b)), never x/(a + b)*(a + b), which C++
// reads as (x/(a + b))*(a + b) (a quaternion's 1/|q|² differentiated gave exactly that)
TEST(CppExpression, AProductInADenominatorIsWrapped) {
  GiNaC::symbol x("x"), a("a"), b("b");
  auto name = [](const GiNaC::symbol& s) { return s.get_name(); };
  EXPECT_EQ(cpp_expression(x * GiNaC::pow(a + b, -2), name), "x/((a + b)*(a + b))");
  EXPECT_EQ(cpp_expression(x * GiNaC::pow(a, -2), name), "x/(a*a)");
  EXPECT_EQ(cpp_expression(x * GiNaC::pow(a, -1), name), "x/a");
  EXPECT_EQ(cpp_expression(x * GiNaC::pow(a, -1) * GiNaC::pow(b, -2), name), "x/(a*b*b)");
}

numeric power_of_two(int k) { return GiNaC::pow(numeric(2), numeric(k)); }

// a product's numeric factor beyond double's range times a sum of terms far below it (Kinova's
// floating arm, whose turns of pi/2 to 12 digits composed into terms of 1e-300, stopped the header
// with "the number inf is beyond the range of double") is written multiplied into the sum
TEST(CppExpression, AFactorBeyondDoublesRangeGoesIntoTheSumItMultiplies) {
  GiNaC::symbol x("x"), a("a"), b("b");
  auto name = [](const GiNaC::symbol& s) { return s.get_name(); };
  GiNaC::ex tiny_terms = power_of_two(-1100) * (3 * a) + power_of_two(-1101) * b;
  GiNaC::ex huge = power_of_two(1100) * x * tiny_terms, small = power_of_two(-1100) * x * (power_of_two(1100) * a + b);
  ASSERT_TRUE(GiNaC::is_a<GiNaC::mul>(huge)) << huge;
  EXPECT_EQ(cpp_expression(huge, name), cpp_expression(x * (3 * a + b / 2), name));
  EXPECT_EQ(cpp_expression(small, name), cpp_expression(x * (a + power_of_two(-1100) * b), name));
  EXPECT_THROW(cpp_expression(power_of_two(1100) * x, name), std::domain_error) << "no sum to take it: beyond double indeed";
}
numeric decimal(const char* digits, int exponent) { return numeric(digits) * GiNaC::pow(numeric(10), numeric(exponent)); }

TEST(CppConstant, SmallIntegersAndFractionsStayIntegerLiterals) {
  EXPECT_EQ(cpp_constant(numeric(3)).text, "T(3)");
  EXPECT_EQ(cpp_constant(numeric(-3)).text, "-T(3)");
  EXPECT_EQ(cpp_constant(numeric(1, 3)).text, "T(1)/T(3)");
  EXPECT_EQ(cpp_constant(power_of_two(53)).text, "T(9007199254740992)");
  EXPECT_EQ(cpp_constant(numeric(1) / power_of_two(53)).text, "T(1)/T(9007199254740992)");
}

TEST(CppConstant, LargeNumeratorsAndDenominatorsBecomeDoubleExpansions) {
  // the smallest case: 1 + 1.5e-20 = 200000000000000000003/200000000000000000000
  EXPECT_EQ(cpp_constant(numeric(1) + decimal("15", -21)).text, "detail::constant<T>(1.0, 1.5e-20, -1.4342482253919357e-36)");
  EXPECT_EQ(cpp_constant(power_of_two(53) + 1).text, "detail::constant<T>(9007199254740992.0, 1.0, 0.0)");
  EXPECT_EQ(cpp_constant(power_of_two(80)).text, "T(1.2089258196146292e+24)");
  EXPECT_EQ(cpp_constant(-decimal("27425820240206541", -16) * decimal("3", -1)).precedence, 2);
  EXPECT_THROW(cpp_constant(GiNaC::pow(numeric(10), numeric(400))), std::domain_error);
}

TEST(CppConstant, ExpansionStartsWithTheNearestDoubleAndCarriesOver150Bits) {
  std::mt19937_64 random(2026);
  for (int k = 0; k < 200; ++k) {
    numeric r = numeric(static_cast<long>(random() >> 2)) * numeric(static_cast<long>(random() >> 2)) /
                (numeric(static_cast<long>(random() >> 2)) * power_of_two(static_cast<int>(random() % 200) - 100) + 1);
    std::array<double, 3> parts = double_expansion(r);
    numeric error = GiNaC::abs(r - exact_rational(parts[0]));
    for (double neighbour : {std::nextafter(parts[0], 0.0), std::nextafter(parts[0], DBL_MAX)})
      EXPECT_LE(error, GiNaC::abs(r - exact_rational(neighbour))) << r;
    numeric rest = r - exact_rational(parts[0]) - exact_rational(parts[1]) - exact_rational(parts[2]);
    EXPECT_LE(GiNaC::abs(rest), GiNaC::abs(r) * power_of_two(-150)) << r;
  }
}

TEST(CppConstant, TiesRoundToTheEvenDouble) {
  numeric ulp = power_of_two(-52);
  EXPECT_EQ(double_expansion(1 + ulp / 2)[0], 1.0);
  EXPECT_EQ(double_expansion(1 + 3 * ulp / 2)[0], 1.0 + 2 * std::ldexp(1.0, -52));
  EXPECT_EQ(double_expansion(power_of_two(-1074) / 2)[0], 0.0);
}

TEST(DecimalNumbers, NumbersThatCameFromDecimalsPrintAsTheirExactDecimals) {
  EXPECT_EQ(exact_decimal_text(decimal("27425820240206541", -16)).value_or(""), "2.7425820240206541");
  EXPECT_EQ(exact_decimal_text(-decimal("981", -9)).value_or(""), "-9.81e-7");
  EXPECT_EQ(exact_decimal_text(decimal("15", -21)).value_or(""), "1.5e-20");
  EXPECT_EQ(exact_decimal_text(numeric(1) + decimal("15", -21)).value_or(""), "1.000000000000000000015");
  EXPECT_EQ(exact_decimal_text(numeric(1, 2000000)).value_or(""), "5e-7");
  EXPECT_EQ(exact_decimal_text(numeric(12345678, 10000000)).value_or(""), "1.2345678");
  EXPECT_FALSE(exact_decimal_text(numeric(1234567, 1000000)));  // a denominator of a million: the fraction
  for (numeric fraction : {numeric(1, 2), numeric(1, 3), numeric(7, 5), numeric(1, 200), numeric(7), numeric(1, 1048576)})
    EXPECT_FALSE(exact_decimal_text(fraction)) << fraction;
  GiNaC::symbol m("m");
  EXPECT_EQ(canonical_text((numeric(1) + decimal("15", -21)) * m), "1.000000000000000000015*m");
  EXPECT_EQ(latex_text(decimal("15", -21) * m, [](const GiNaC::symbol& s) { return s.get_name(); }),
            "1.5 \\cdot 10^{-20} \\, m");
}

TEST(DecimalNumbers, ReadBackExactly) {
  EXPECT_EQ(decimals_as_fractions("0.15*m + 1.5e-20 - x2*3 + 2E+3 + .5"), "(3/20)*m + (3/200000000000000000000) - x2*3 + (2000) + (1/2)");
  GiNaC::symbol m("m");
  GiNaC::symtab table{{"m", m}};
  GiNaC::ex printed = (numeric(1) + decimal("15", -21)) * m + decimal("27425820240206541", -16);
  GiNaC::ex read = GiNaC::parser(table, true)(decimals_as_fractions(canonical_text(printed)));
  EXPECT_TRUE((read - printed).is_zero()) << canonical_text(printed);
}

// the model's derived equations at (x, u) in 50-digit arithmetic: [v; M^-1 f]
std::vector<numeric> reference_rhs(const Equations& e, const std::vector<double>& x, const std::vector<double>& u) {
  GiNaC::Digits = 50;
  const Symbols& s = e.symbols;
  std::size_t n = s.coordinates.size();
  GiNaC::exmap at;
  for (std::size_t i = 0; i < n; ++i) at[s.coordinates[i]] = exact_rational(x[i]);
  for (std::size_t i = 0; i < n; ++i) at[s.velocities[i]] = exact_rational(x[n + i]);
  for (std::size_t i = 0; i < s.parameters.size(); ++i) at[s.parameters[i]] = exact_rational(s.parameter_defaults[i]);
  for (std::size_t i = 0; i < s.inputs.size(); ++i) at[s.inputs[i]] = exact_rational(u[i]);
  at[s.time] = 0;
  for (const Intermediate& k : e.intermediates) at[k.symbol] = k.definition.subs(at).evalf();
  GiNaC::matrix M(n, n), f(n, 1);
  for (std::size_t i = 0; i < n; ++i) {
    f(i, 0) = e.forcing[i].subs(at).evalf();
    for (std::size_t j = 0; j < n; ++j) M(i, j) = e.mass_matrix(i, j).subs(at).evalf();
  }
  GiNaC::matrix a = M.inverse().mul(f);
  std::vector<numeric> out;
  for (std::size_t i = 0; i < n; ++i) out.push_back(exact_rational(x[n + i]));
  for (std::size_t i = 0; i < n; ++i) out.push_back(GiNaC::ex_to<numeric>(a(i, 0).evalf()));
  GiNaC::Digits = 17;
  return out;
}

// max |computed − reference| / max |reference| over the state
template <class T, class Convert>
double relative_error(const std::vector<T>& computed, const std::vector<numeric>& reference, Convert to_numeric) {
  numeric largest = 0, worst = 0;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    largest = std::max(largest, GiNaC::abs(reference[i]));
    worst = std::max(worst, GiNaC::abs(to_numeric(computed[i]) - reference[i]));
  }
  return (worst / largest).to_double();
}

numeric long_double_value(long double v) {
  long double hi = static_cast<double>(v);
  return exact_rational(static_cast<double>(hi)) + exact_rational(static_cast<double>(v - hi));
}

#ifdef EOMGEN_WITH_QUADMATH
numeric wide_value(reference::Wide w) {
  numeric sum = 0;
  __float128 rest = w.raw();
  for (int k = 0; k < 3; ++k) {
    double part = static_cast<double>(rest);
    sum += exact_rational(part);
    rest -= part;
  }
  return sum;
}
#endif

template <class T, class Rhs>
std::vector<T> rhs_in(Rhs rhs, const std::vector<double>& x, const std::vector<double>& u, const std::vector<double>& p) {
  std::vector<T> xt, ut, pt, out(x.size());
  for (double v : x) xt.push_back(T(v));
  for (double v : u) ut.push_back(T(v));
  for (double v : p) pt.push_back(T(v));
  rhs(T(0), xt.data(), ut.empty() ? nullptr : ut.data(), pt.data(), out.data());
  return out;
}

template <class Header>
void expect_rhs_matches_the_equations(const std::string& model, const Header&) {
  Equations e = derive_model(model);
  std::vector<double> p(Header::default_parameters.begin(), Header::default_parameters.end());
  std::mt19937 random(36);
  std::uniform_real_distribution<double> angle(-3, 3), rate(-2, 2), input(-5, 5);
  for (int k = 0; k < 5; ++k) {
    std::vector<double> x(Header::num_states), u(Header::num_inputs);
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = i < Header::num_coordinates ? angle(random) : rate(random);
    for (double& v : u) v = input(random);
    std::vector<numeric> exact = reference_rhs(e, x, u);
    auto as_numeric = [](double v) { return exact_rational(v); };
    // 16 units of rounding in each type, whose own roundings through M⁻¹ f reach a few (the
    // measured arm's tree: up to 7.3 in double, 3.2 in long double); a constant that lost digits
    // (an integer literal that overflowed, a decimal rounded to double in long double) errs by
    // orders of magnitude more
    EXPECT_LE(relative_error(rhs_in<double>(Header::rhs_double, x, u, p), exact, as_numeric), 16 * DBL_EPSILON) << model;
    EXPECT_LE(relative_error(rhs_in<long double>(Header::rhs_long_double, x, u, p), exact, long_double_value),
              16 * LDBL_EPSILON)
        << model;
#ifdef EOMGEN_WITH_QUADMATH
    EXPECT_LE(relative_error(rhs_in<reference::Wide>(Header::rhs_wide, x, u, p), exact, wide_value), 1e-30) << model;
#endif
  }
}

#define EOMGEN_HEADER_OF(NAME)                                                                            \
  struct NAME##_header {                                                                                  \
    static constexpr auto& default_parameters = eomgen::models::NAME::default_parameters;                 \
    static constexpr std::size_t num_states = eomgen::models::NAME::num_states;                           \
    static constexpr std::size_t num_coordinates = eomgen::models::NAME::num_coordinates;                 \
    static constexpr std::size_t num_inputs = eomgen::models::NAME::num_inputs;                           \
    static constexpr auto rhs_double = &eomgen::models::NAME::rhs<double>;                                 \
    static constexpr auto rhs_long_double = &eomgen::models::NAME::rhs<long double>;                       \
    static constexpr auto rhs_wide = &eomgen::models::NAME::rhs<reference::Wide>;                          \
  };
EOMGEN_HEADER_OF(measured_arm)
EOMGEN_HEADER_OF(nearly_unit_mass)
#undef EOMGEN_HEADER_OF

TEST(RealNumbers, ArmWithMeasuredInertiasMatchesItsEquationsIn50Digits) {
  expect_rhs_matches_the_equations("measured_arm", measured_arm_header{});
}

TEST(RealNumbers, NearlyUnitMassMatchesItsEquationsIn50Digits) {
  expect_rhs_matches_the_equations("nearly_unit_mass", nearly_unit_mass_header{});
}

TEST(RealNumbers, MassOfOnePlus15eMinus20KeepsItsTailInWideScalars) {
  namespace m = eomgen::models::nearly_unit_mass;
  double x[2] = {0.01, 0};
  double M = 0;
  m::mass_matrix<double>(0, x, nullptr, &M);
  EXPECT_EQ(M, 1.0);
#ifdef EOMGEN_WITH_QUADMATH
  reference::Wide xw[2] = {reference::Wide(0.01), reference::Wide(0)}, Mw;
  m::mass_matrix<reference::Wide>(reference::Wide(0), xw, nullptr, &Mw);
  EXPECT_NEAR(((wide_value(Mw) - 1) / decimal("15", -21)).to_double(), 1.0, 1e-14);
#endif
}

TEST(RealNumbers, SimulateRunsTheModelsWithRealNumbers) {
  for (const char* model : {"measured_arm", "nearly_unit_mass"}) {
    CommandOutput r = run_eomgen("simulate '" + model_path(model) + "' --t-end 0.5 --format json");
    EXPECT_EQ(r.status, 0) << model << ": " << r.err;
  }
}

}  // namespace
}  // namespace eomgen::test
