// The closed-form solution of linear systems against known results: partial
// fractions that recombine to the function split; the space rendezvous' Φ(t) in
// the orbit rate n against the Clohessy–Wiltshire solution (Hiller §6.4); the cart
// pendulum's transfer function X/F in its parameters; repeated complex roots
// (resonance, t sin) and real irrational roots (cosh); a cubic factor refused.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "symbolic_analysis/closed_form_solution.hpp"
#include "symbolic_analysis/exact_linear_system.hpp"
#include "symbolic_analysis/partial_fractions.hpp"
#include "pipeline.hpp"
#include "support/test_support.hpp"
#include "symbolic/canonical_print.hpp"

namespace eomgen::test {
namespace {

using GiNaC::ex;

double value_of(const ex& e, const GiNaC::exmap& point) {
  ex v = GiNaC::evalf(e.subs(point));
  EXPECT_TRUE(GiNaC::is_a<GiNaC::numeric>(v)) << v;
  return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
}

// the symbol of the given name in e (the parameters become positive symbols)
ex symbol_named(const ex& e, const std::string& name) {
  for (GiNaC::const_preorder_iterator i = e.preorder_begin(); i != e.preorder_end(); ++i)
    if (GiNaC::is_a<GiNaC::symbol>(*i) && GiNaC::ex_to<GiNaC::symbol>(*i).get_name() == name) return *i;
  ADD_FAILURE() << "no symbol " << name << " in " << e;
  return 0;
}

TEST(PartialFractions, TermsRecombineToTheFunction) {
  GiNaC::symbol s("s"), a("a");
  ex f = (s + 3) / (GiNaC::pow(s + 1, 2) * (s * s + 4) * (s - a));
  PartialFractions parts = partial_fractions(f, s);
  EXPECT_EQ(parts.polynomial, 0);
  ex sum = parts.polynomial;
  int quadratic = 0;
  for (const PartialFraction& p : parts.terms) {
    EXPECT_LT(p.numerator.degree(s), p.factor.degree(s));
    sum += p.numerator / GiNaC::pow(p.factor, p.power);
    quadratic += p.factor.degree(s) == 2;
  }
  EXPECT_EQ(parts.terms.size(), 4u) << "(s+1), (s+1)^2, s^2+4, s-a";
  EXPECT_EQ(quadratic, 1);
  EXPECT_TRUE((sum - f).normal().is_zero()) << sum;
  PartialFractions improper = partial_fractions((s * s * s + 2) / (s * s - 2), s);
  EXPECT_TRUE((improper.polynomial - s).expand().is_zero()) << improper.polynomial;
  ASSERT_EQ(improper.terms.size(), 1u) << "s^2 - 2 is irreducible over the rationals";
  EXPECT_TRUE((improper.terms[0].numerator - (2 * s + 2)).expand().is_zero()) << improper.terms[0].numerator;
}

TEST(ClosedFormSolution, RendezvousIsTheClohessyWiltshireSolutionInTheOrbitRate) {
  Equations e = derive_model("space_rendezvous");
  ExactLinearSystem system = exact_linear_system(e, e.symbols.parameter_defaults, e.symbols.input_defaults,
                                                 std::vector<double>(6, 0.0), true);
  ASSERT_TRUE(system.refusal.empty()) << system.refusal;
  ClosedFormSolution solution = closed_form_solution(system.A, system.B, system.C, system.D, system.parameter_values);
  ASSERT_TRUE(solution.refusal.empty()) << solution.refusal;
  EXPECT_TRUE(solution.conditions.empty()) << "n^2 > 0 needs no condition for positive n";
  ex n = symbol_named(system.A, "n");
  const ex& t = solution.t;
  ex c = GiNaC::cos(n * t), s = GiNaC::sin(n * t);
  // x radial, y along track, z out of plane; the state [x, y, z, x', y', z']
  ex cw[6][6] = {{4 - 3 * c, 0, 0, s / n, 2 * (1 - c) / n, 0},
                 {6 * (s - n * t), 1, 0, 2 * (c - 1) / n, (4 * s - 3 * n * t) / n, 0},
                 {0, 0, c, 0, 0, s / n},
                 {3 * n * s, 0, 0, c, 2 * s, 0},
                 {6 * n * (c - 1), 0, 0, -2 * s, 4 * c - 3, 0},
                 {0, 0, -n * s, 0, 0, c}};
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      EXPECT_TRUE((solution.fundamental(i, j) - cw[i][j]).expand().normal().is_zero())
          << "[" << i << "][" << j << "] = " << canonical_text(solution.fundamental(i, j)) << ", expected " << cw[i][j];
}

TEST(ClosedFormSolution, CartPendulumTransferFunctionInItsParameters) {
  Equations e = derive_model("cart_pendulum");
  ExactLinearSystem system = exact_linear_system(e, e.symbols.parameter_defaults, e.symbols.input_defaults,
                                                 std::vector<double>(4, 0.0), true, {"x"});
  ASSERT_TRUE(system.refusal.empty()) << system.refusal;
  ClosedFormSolution solution = closed_form_solution(system.A, system.B, system.C, system.D, system.parameter_values);
  ASSERT_TRUE(solution.refusal.empty()) << solution.refusal;
  ex G = solution.transfer(0, 0);
  ex mc = symbol_named(G, "mc"), m = symbol_named(G, "m"), l = symbol_named(G, "l"), g = symbol_named(G, "g");
  const ex& s = solution.s;
  ex expected = (l * s * s + g) / (s * s * (mc * l * s * s + (mc + m) * g));
  EXPECT_TRUE((G - expected).normal().is_zero()) << canonical_text(G);
  // Φ(t) in the parameters too: the pendulum's frequency sqrt((mc + m) g / (mc l)) appears
  std::mt19937 random(7);
  std::uniform_real_distribution<double> draw(0.3, 2.0);
  GiNaC::exmap point{{mc, draw(random)}, {m, draw(random)}, {l, draw(random)}, {g, 9.81}, {solution.t, draw(random)}};
  double w = std::sqrt(value_of((mc + m) * g / (mc * l), point)), time = value_of(solution.t, point);
  // theta(t) from theta(0) alone is cos(w t)
  EXPECT_NEAR(value_of(solution.fundamental(1, 1), point), std::cos(w * time), 1e-14);
}

// M x'' + K x = 0 with exact matrices, as a linear system of first order
ClosedFormSolution solved(const std::vector<std::vector<ex>>& lower) {
  unsigned n = lower.size();
  GiNaC::matrix A(n, n);
  for (unsigned i = 0; i < n; ++i)
    for (unsigned j = 0; j < n; ++j) A(i, j) = lower[i][j];
  return closed_form_solution(A, GiNaC::matrix(), GiNaC::matrix(), GiNaC::matrix(), {});
}

TEST(ClosedFormSolution, ResonanceRealRootsAndACubicFactor) {
  // x'' + 4 x = y, y'' + 4 y = 0: y = cos 2t, x = t sin(2t)/4 (resonance)
  ClosedFormSolution resonant = solved({{0, 0, 1, 0}, {0, 0, 0, 1}, {-4, 1, 0, 0}, {0, -4, 0, 0}});
  ASSERT_TRUE(resonant.refusal.empty()) << resonant.refusal;
  const ex& t = resonant.t;
  EXPECT_TRUE((resonant.fundamental(0, 1) - t * GiNaC::sin(2 * t) / 4).expand().is_zero())
      << canonical_text(resonant.fundamental(0, 1));
  // x'' = 2 x: cosh(sqrt(2) t), sinh(sqrt(2) t)/sqrt(2)
  ClosedFormSolution saddle = solved({{0, 1}, {2, 0}});
  ASSERT_TRUE(saddle.refusal.empty()) << saddle.refusal;
  ex r = GiNaC::sqrt(ex(2));
  EXPECT_TRUE((saddle.fundamental(0, 0) - GiNaC::cosh(r * saddle.t)).expand().is_zero()) << saddle.fundamental(0, 0);
  EXPECT_TRUE((saddle.fundamental(0, 1) - GiNaC::sinh(r * saddle.t) / r).expand().normal().is_zero()) << saddle.fundamental(0, 1);
  // x''' = x + 1·... : the companion matrix of s^3 - s - 1, irreducible
  ClosedFormSolution cubic = solved({{0, 1, 0}, {0, 0, 1}, {1, 1, 0}});
  EXPECT_NE(cubic.refusal.find("of degree 3"), std::string::npos) << cubic.refusal;
}

// the inverted pendulum at phi = π (--at phi=Pi): the double nearest π is taken as π, so A is rational
// (cos π = −1) and the exact analysis applies; 3π/4 is taken as 3π/4, whose cosine is no rational
TEST(ExactLinearSystem, AnAngleThatIsAMultipleOfPiIsExact) {
  Equations e = derive_model("pendulum");
  std::vector<double> p = e.symbols.parameter_defaults, u = e.symbols.input_defaults;
  ExactLinearSystem upright = exact_linear_system(e, p, u, {M_PI, 0}, false);
  ASSERT_TRUE(upright.refusal.empty()) << upright.refusal;
  double g = p[2], l = p[1];
  EXPECT_NEAR(GiNaC::ex_to<GiNaC::numeric>(upright.A(1, 0).evalf()).to_double(), g / l, 1e-15 * g / l);
  ExactLinearSystem oblique = exact_linear_system(e, p, u, {3 * M_PI / 4, 0}, false);
  EXPECT_NE(oblique.refusal.find("sqrt(2)"), std::string::npos) << oblique.refusal;
  ExactLinearSystem decimal = exact_linear_system(e, p, u, {0.5, 0}, false);
  EXPECT_NE(decimal.refusal.find("cos(1/2)"), std::string::npos) << decimal.refusal;
}

// critical damping (c² = 4km at the model's values): the characteristic polynomial's quadratic factor
// has a double root there, and Φ(t) is the Jordan form's e^(−ct/2m) (1 + ct/2m, t; −kt/m, 1 − ct/2m),
// not the sinh form, which is 0/0 at c² = 4km; it says where it holds
TEST(ClosedFormSolution, CriticalDampingIsTheJordanFormsSolution) {
  GiNaC::symbol m("m"), c("c"), k("k");
  GiNaC::matrix A{{0, 1}, {-k / m, -c / m}};
  GiNaC::exmap values{{m, 2}, {c, 4}, {k, 2}};  // c² = 4km = 16
  ClosedFormSolution solution = closed_form_solution(A, GiNaC::matrix(2, 0), GiNaC::matrix(0, 2), GiNaC::matrix(0, 0), values);
  ASSERT_TRUE(solution.refusal.empty()) << solution.refusal;
  ASSERT_EQ(solution.conditions.size(), 1u);
  EXPECT_NE(solution.conditions[0].find("= 0"), std::string::npos) << solution.conditions[0];
  ex t = solution.t, decay = GiNaC::exp(-c * t / (2 * m));
  GiNaC::matrix expected{{decay * (1 + c * t / (2 * m)), decay * t}, {-decay * k * t / m, decay * (1 - c * t / (2 * m))}};
  for (double time : {0.0, 0.3, 1.7, 6.0}) {
    GiNaC::exmap at = values;
    at[t] = time;
    for (unsigned i = 0; i < 2; ++i)
      for (unsigned j = 0; j < 2; ++j)
        EXPECT_NEAR(value_of(solution.fundamental(i, j), at), value_of(expected(i, j), at), 1e-14)
            << "Φ(" << time << ")[" << i << "][" << j << "] = " << solution.fundamental(i, j);
  }
}

}  // namespace
}  // namespace eomgen::test
