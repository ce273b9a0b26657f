#include <gtest/gtest.h>

#include "parse/model_file.hpp"
#include "pipeline.hpp"

namespace eomgen {
namespace {

TEST(ParseModelFile, KeepsFileOrderAndLocations) {
  Diagnostics d;
  ModelFile m = parse_model_text(R"([model]
name = "x"
[parameters]
zeta = 1.0
alpha = 2
[coordinates]
q2 = 0.5
q1 = { initial = "Pi/4", rate = 1 }
)", "inline.toml", d);
  ASSERT_TRUE(d.empty()) << d.format();
  ASSERT_EQ(m.parameters.size(), 2u);
  EXPECT_EQ(m.parameters[0].name, "zeta");
  EXPECT_EQ(m.parameters[1].name, "alpha");
  EXPECT_EQ(m.parameters[1].value, 2.0);
  ASSERT_EQ(m.coordinates.size(), 2u);
  EXPECT_EQ(m.coordinates[0].name, "q2");
  EXPECT_EQ(m.coordinates[1].initial.text, "Pi/4");
  EXPECT_EQ(m.coordinates[1].where.line, 8);
}

TEST(ParseModelFile, ReportsAllStructuralMistakesTogether) {
  Diagnostics d;
  parse_model_text(R"([model]
name = "x"
colour = "red"
[parameters]
m = "heavy"
[[particles]]
name = "p"
position = ["0", "0"]
)", "inline.toml", d);
  EXPECT_EQ(d.size(), 4u) << d.format();  // colour, m, missing mass, short position
}

TEST(Pipeline, InitialValuesMayBeConstantExpressions) {
  Derivation r = derive_model_text(R"([model]
name = "x"
[parameters]
m = 2.0
[coordinates]
q = { initial = "Pi/4", rate = "2*m" }
[energy]
kinetic = "m*der(q)^2/2"
potential = "m*q^2"
)", "inline.toml");
  ASSERT_TRUE(r.equations) << r.diagnostics.format();
  EXPECT_NEAR(r.equations->symbols.initial_coordinates[0], 0.7853981633974483, 1e-15);
  EXPECT_EQ(r.equations->symbols.initial_velocities[0], 4.0);
}

TEST(Pipeline, ConstraintsAreRefusedNamingTheMethod) {
  Derivation r = derive_model_text(R"([model]
name = "x"
[coordinates]
a = 0.0
b = 0.0
[energy]
kinetic = "der(a)^2/2 + der(b)^2/2"
[[constraints]]
holonomic = "a - 2*b"
)", "inline.toml");
  ASSERT_FALSE(r.equations);
  EXPECT_NE(r.diagnostics.format().find("method = \"lagrange1\""), std::string::npos) << r.diagnostics.format();
}

TEST(Pipeline, KineticEnergyFromEnergySectionUsesGeneralFormula) {
  // T = ½ (1 + q²) q̇²: M = 1 + q², f = −q q̇² (from ∂T/∂q − (∂²T/∂q̇∂q) q̇)
  Derivation r = derive_model_text(R"([model]
name = "x"
[coordinates]
q = 0.0
[energy]
kinetic = "(1 + q^2)*der(q)^2/2"
)", "inline.toml");
  ASSERT_TRUE(r.equations) << r.diagnostics.format();
  const Symbols& s = r.equations->symbols;
  EXPECT_TRUE((r.equations->mass_matrix(0, 0) - (1 + GiNaC::pow(s.coordinates[0], 2))).expand().is_zero());
  EXPECT_TRUE((r.equations->forcing[0] + s.coordinates[0] * GiNaC::pow(s.velocities[0], 2)).expand().is_zero())
      << r.equations->forcing[0];
}

}  // namespace
}  // namespace eomgen
