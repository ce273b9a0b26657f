// The Jordan structure by exact arithmetic against known forms: the space
// rendezvous (λ² + n²)² λ² with ±i n semisimple and one block of size 2 at 0; a
// chain x'' = c y, y'' = 0 whose A is one Jordan block of size 4; and refusals
// where A is not rational.
#include <gtest/gtest.h>

#include "symbolic_analysis/exact_jordan.hpp"
#include "pipeline.hpp"
#include "support/test_support.hpp"
#include "symbolic/canonical_print.hpp"

namespace eomgen::test {
namespace {

ExactJordan exact_at(const Equations& e, const std::vector<double>& state) {
  return exact_jordan_structure(e, e.symbols.parameter_defaults, e.symbols.input_defaults, state);
}

TEST(ExactJordan, RendezvousHasOneBlockOfSizeTwoAtZero) {
  Equations e = derive_model("space_rendezvous");  // n = 0.0011 = 11/10000
  ExactJordan j = exact_at(e, std::vector<double>(6, 0.0));
  ASSERT_TRUE(j.refusal.empty()) << j.refusal;
  ASSERT_EQ(j.factors.size(), 2u);
  for (const ExactFactor& f : j.factors) {
    std::string text = canonical_text(f.polynomial);
    EXPECT_EQ(f.multiplicity, 2) << text;
    if (f.degree == 1) {
      EXPECT_EQ(text, "lambda");
      EXPECT_EQ(f.jordan_blocks, (std::vector<int>{2})) << "the along-track drift";
    } else {
      EXPECT_EQ(text, "lambda^2 + 1.21e-6");  // n^2, exact: the decimal of a long power of ten
      EXPECT_EQ(f.jordan_blocks, (std::vector<int>{1, 1})) << "semisimple";
    }
  }
}

TEST(ExactJordan, ACirculatoryChainIsOneBlockOfSizeFour) {
  // x'' = c y, y'' = 0: x grows like t³, A is nilpotent of index 4
  Derivation d = derive_model_text("[model]\nname = \"chain\"\ntitle = \"x'' = c y, y'' = 0\"\n\n[parameters]\nc = 2.0\n\n"
                                   "[coordinates]\nx = 0.0\ny = 0.0\n\n[[particles]]\nname = \"a\"\nmass = \"1\"\n"
                                   "position = [\"x\", \"0\", \"0\"]\n\n[[particles]]\nname = \"b\"\nmass = \"1\"\n"
                                   "position = [\"y\", \"0\", \"0\"]\n\n[[forces]]\ngeneralized = { x = \"c*y\" }\n",
                                   "chain.toml");
  ASSERT_TRUE(d.equations) << d.diagnostics.format();
  ExactJordan j = exact_at(*d.equations, std::vector<double>(4, 0.0));
  ASSERT_TRUE(j.refusal.empty()) << j.refusal;
  ASSERT_EQ(j.factors.size(), 1u);
  EXPECT_EQ(canonical_text(j.factors[0].polynomial), "lambda");
  EXPECT_EQ(j.factors[0].multiplicity, 4);
  EXPECT_EQ(j.factors[0].jordan_blocks, (std::vector<int>{4}));
}

TEST(ExactJordan, AVelocityCouplingGivesBlocksOfSizesThreeAndOne) {
  // x'' = c y', y'' = 0: y' constant, x' linear, x quadratic in t: blocks [3, 1] at 0
  Derivation d = derive_model_text("[model]\nname = \"chain\"\ntitle = \"x'' = c y', y'' = 0\"\n\n[parameters]\nc = 0.5\n\n"
                                   "[coordinates]\nx = 0.0\ny = 0.0\n\n[[particles]]\nname = \"a\"\nmass = \"1\"\n"
                                   "position = [\"x\", \"0\", \"0\"]\n\n[[particles]]\nname = \"b\"\nmass = \"1\"\n"
                                   "position = [\"y\", \"0\", \"0\"]\n\n[[forces]]\ngeneralized = { x = \"c*der(y)\" }\n",
                                   "chain.toml");
  ASSERT_TRUE(d.equations) << d.diagnostics.format();
  ExactJordan j = exact_at(*d.equations, std::vector<double>(4, 0.0));
  ASSERT_TRUE(j.refusal.empty()) << j.refusal;
  ASSERT_EQ(j.factors.size(), 1u);
  EXPECT_EQ(j.factors[0].multiplicity, 4);
  EXPECT_EQ(j.factors[0].jordan_blocks, (std::vector<int>{3, 1}));
}

TEST(ExactJordan, RefusedWhereAIsNotRational) {
  Equations pendulum = derive_model("pendulum");
  // at phi = 0.5, cos(1/2) is no rational; at the double nearest π the angle is π (cos π = −1)
  ExactJordan oblique = exact_at(pendulum, {0.5, 0.0});
  EXPECT_NE(oblique.refusal.find("is not rational at this state"), std::string::npos) << oblique.refusal;
  EXPECT_TRUE(exact_at(pendulum, {3.141592653589793, 0.0}).refusal.empty());
  Equations appell = derive_model("knife_edge");
  EXPECT_FALSE(exact_at(appell, std::vector<double>(5, 0.0)).refusal.empty());
}

}  // namespace
}  // namespace eomgen::test
