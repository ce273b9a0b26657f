#include <gtest/gtest.h>

#include "emit/formats.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

TEST(CanonicalText, NamesEveryEquationOnItsOwnLine) {
  std::string text = emit_canonical_text(derive_model("double_pendulum"));
  for (const char* line : {"\nM[0][0] = ", "\nM[0][1] = ", "\nM[1][0] = ", "\nM[1][1] = ", "\nf[0] = ", "\nf[1] = ",
                           "\nT = ", "\nV = ", "\nR = 0\n", "\ny[tip_x] = ", "\ndegrees_of_freedom: 2\n"})
    EXPECT_NE(text.find(line), std::string::npos) << line;
  EXPECT_EQ(text.find("/work"), std::string::npos) << "no absolute paths";
}

TEST(Latex, GreekNamesAreTypesetAsGreekLetters) {
  std::string tex = emit_latex(derive_model("heavy_symmetric_top"));
  for (const char* piece : {"\\theta", "\\dot{\\psi}", "\\dot{\\phi}", "\\sin\\left(\\theta\\right)", "\\begin{align*}"})
    EXPECT_NE(tex.find(piece), std::string::npos) << piece << "\n" << tex;
  std::string pendulum = emit_latex(derive_model("double_pendulum"));
  EXPECT_NE(pendulum.find("\\phi_{1}"), std::string::npos);
  EXPECT_NE(pendulum.find("\\dot{\\phi}_{2}"), std::string::npos);
  EXPECT_NE(pendulum.find("\\tau"), std::string::npos);
}

TEST(Json, HasTheDocumentedKeysInOrder) {
  std::string json = emit_json(derive_model("double_pendulum"));
  std::size_t at = 0;
  for (const char* key : {"\"model\"", "\"method\"", "\"time\"", "\"coordinates\"", "\"velocities\"", "\"parameters\"",
                          "\"inputs\"", "\"degrees_of_freedom\"", "\"mass_matrix\"", "\"forcing\"",
                          "\"kinetic_energy\"", "\"potential_energy\"", "\"dissipation\"", "\"outputs\""}) {
    std::size_t found = json.find(key, at);
    ASSERT_NE(found, std::string::npos) << key;
    at = found;
  }
  EXPECT_NE(json.find("\"velocities\": [\"der(phi1)\", \"der(phi2)\"]"), std::string::npos);
  EXPECT_NE(json.find("\"g\": 9.81"), std::string::npos);
}

TEST(Formats, RegistryKnowsEveryFormat) {
  for (const std::string& name : equation_format_names()) EXPECT_TRUE(find_equation_format(name)) << name;
  EXPECT_FALSE(find_equation_format("pdf"));
  EXPECT_EQ(format_number(0.1), "0.1");
  EXPECT_EQ(format_number(9.81), "9.81");
}

}  // namespace
}  // namespace eomgen::test
