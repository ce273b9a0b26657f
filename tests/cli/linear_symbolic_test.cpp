// `eomgen linear --symbolic` against independent results: the printed closed forms,
// read back with GiNaC's parser, equal the numeric Φ(t) = e^{At} and the transfer
// function from poles, zeros and gain at several points (the two-mass chain, whose
// quartic does not factor in the parameters, at its values); the rendezvous in its
// orbit rate; the cart pendulum's X/F in its parameters; refusals said.
#include <gtest/gtest.h>

#include <complex>

#include <ginac/ginac.h>

#include "parse/json_reader.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {


// a printed closed form at a point: its symbols by name → values
std::complex<double> evaluate(const std::string& text, const std::map<std::string, std::complex<double>>& values) {
  GiNaC::parser reader;
  GiNaC::ex e = reader(text);
  GiNaC::exmap point;
  for (const auto& [name, symbol] : reader.get_syms())
    if (auto v = values.find(name); v != values.end())
      point[symbol] = GiNaC::numeric(v->second.real()) + GiNaC::I * GiNaC::numeric(v->second.imag());
  GiNaC::ex v = GiNaC::evalf(e.subs(point));
  EXPECT_TRUE(GiNaC::is_a<GiNaC::numeric>(v)) << text << " = " << v;
  GiNaC::numeric z = GiNaC::ex_to<GiNaC::numeric>(v);
  return {GiNaC::real(z).to_double(), GiNaC::imag(z).to_double()};
}

TEST(LinearSymbolic, TwoMassChainAtItsValuesEqualsTheNumericSolution) {
  JsonValue json = run_json("linear '" + model_path("two_mass_chain") + "' --at x1=0 --at x2=0 --times 0.3,0.7,2.5 "
                            "--symbolic --transfer F:x2");
  const JsonValue* symbolic = json.find("symbolic");
  ASSERT_NE(symbolic, nullptr);
  EXPECT_FALSE(symbolic->find("in_parameters")->truth);
  EXPECT_NE(symbolic->find("parameter_refusal")->text.find("of degree 4 in s"), std::string::npos)
      << "the generic chain's characteristic polynomial is an irreducible quartic";
  const auto& rows = symbolic->find("fundamental_matrix")->items;
  ASSERT_EQ(rows.size(), 4u);
  for (const JsonValue& sample : json.find("fundamental_matrix")->items) {
    double t = at(sample, "t");
    const auto& numeric = sample.find("matrix")->items;
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t j = 0; j < 4; ++j) {
        std::complex<double> closed = evaluate(rows[i].items[j].text, {{"t", t}});
        EXPECT_NEAR(closed.real(), numeric[i].items[j].value, 1e-12) << "t = " << t << " [" << i << "][" << j << "]";
        EXPECT_EQ(closed.imag(), 0);
      }
  }
  // G(s) against k Π(s − z) / Π(s − p) from the numeric poles and zeros
  const JsonValue& g_numeric = json.find("transfer_functions")->items.at(0);
  std::string g_closed = symbolic->find("transfer_functions")->items.at(0).find("G")->text;
  for (std::complex<double> s : {std::complex<double>(0, 3), std::complex<double>(0.5, 12), std::complex<double>(-1, 40)}) {
    std::complex<double> g = at(g_numeric, "gain");
    for (const JsonValue& z : g_numeric.find("zeros")->items) g *= s - std::complex<double>(z.items[0].value, z.items[1].value);
    for (const JsonValue& p : g_numeric.find("poles")->items) g /= s - std::complex<double>(p.items[0].value, p.items[1].value);
    EXPECT_LT(std::abs(evaluate(g_closed, {{"s", s}}) - g), 1e-12 * std::abs(g)) << "s = " << s << ": " << g_closed;
  }
}

TEST(LinearSymbolic, RendezvousAndCartPendulumInTheirParameters) {
  CommandOutput text = run_eomgen("linear '" + model_path("space_rendezvous") + "' --at x=0 --symbolic");
  EXPECT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("in the parameters, for m > 0, n > 0"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("z(t) = (cos(n*t))*z(0) + (sin(n*t)/n)*der(z)(0)"), std::string::npos) << text.out;
  JsonValue json = run_json("linear '" + model_path("cart_pendulum") + "' --at x=0 --at theta=0 --symbolic --transfer F:x");
  const JsonValue* symbolic = json.find("symbolic");
  ASSERT_NE(symbolic, nullptr);
  EXPECT_TRUE(symbolic->find("in_parameters")->truth);
  // X/F = (l s² + g) / (s² (mc l s² + (mc + m) g)) at random parameters and s
  std::string g = symbolic->find("transfer_functions")->items.at(0).find("G")->text;
  for (auto [mc, m, l, s] : {std::tuple{1.3, 0.4, 0.6, std::complex<double>(0.2, 1.7)}, {0.7, 2.1, 1.9, {-0.4, 0.3}}}) {
    std::complex<double> expected = (l * s * s + 9.81) / (s * s * (mc * l * s * s + (mc + m) * 9.81));
    EXPECT_LT(std::abs(evaluate(g, {{"mc", mc}, {"m", m}, {"l", l}, {"g", 9.81}, {"s", s}}) - expected), 1e-13 * std::abs(expected)) << g;
  }
}

TEST(LinearSymbolic, RefusalsAreSaid) {
  // the upright pendulum: the double nearest π is taken as π, so cos(π) = −1 and A is rational: the
  // closed form is the saddle's cosh, not a refusal (as it was when π counted as a decimal)
  for (const char* at : {"phi=3.141592653589793", "phi=Pi"}) {
    CommandOutput upright = run_eomgen("linear '" + model_path("pendulum") + "' --at " + at + " --symbolic");
    EXPECT_EQ(upright.status, 0) << upright.err;
    EXPECT_NE(upright.out.find("phi(t) = (cosh("), std::string::npos) << at << "\n" << upright.out;
  }
  // the double pendulum: a biquadratic that does not factor
  JsonValue json = run_json("linear '" + model_path("double_pendulum") + "' --at phi1=0 --at phi2=0 --symbolic");
  EXPECT_NE(json.find("symbolic")->find("refusal")->text.find("of degree 4 in s"), std::string::npos);
}

}  // namespace
}  // namespace eomgen::test
