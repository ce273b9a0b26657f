// Pictures of the modes against their geometry: the double pendulum's bobs move across
// by l1 φ1 and l1 φ1 + l2 φ2 (the first-order motion of r = (l sin φ, −l cos φ)); a spring
// chain, whose bodies all sit at the origin, is drawn at stations with its shape across.
#include <gtest/gtest.h>

#include "symbolic_analysis/deformed_shapes.hpp"
#include "pipeline.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

TEST(DeformedShapes, DoublePendulumBobsMoveAcrossByTheirLinks) {
  Equations e = derive_model("double_pendulum");
  std::vector<double> parameters = e.symbols.parameter_defaults;
  auto value = [&](const std::string& name) {
    for (std::size_t i = 0; i < parameters.size(); ++i)
      if (e.symbols.parameter_names[i] == name) return parameters[i];
    ADD_FAILURE() << name;
    return 0.0;
  };
  const double l1 = value("l1"), l2 = value("l2"), phi1 = 0.3, phi2 = -0.8;
  DeformedShapes d = deformed_shapes(e, parameters, e.symbols.input_defaults, {0, 0, 0, 0}, {{phi1, phi2}});
  ASSERT_TRUE(d.refusal.empty()) << d.refusal;
  EXPECT_FALSE(d.stations);
  EXPECT_EQ(d.horizontal, "x");
  EXPECT_EQ(d.vertical, "y");
  ASSERT_EQ(d.rest.size(), 2u);
  EXPECT_NEAR(d.rest[1][1], -l1 - l2, 1e-15);
  // displacements across in the ratio of l1 φ1 to l1 φ1 + l2 φ2, the largest a third of the bodies' span
  double first = d.modes[0][0][0] - d.rest[0][0], second = d.modes[0][1][0] - d.rest[1][0];
  EXPECT_NEAR(second / first, (l1 * phi1 + l2 * phi2) / (l1 * phi1), 1e-12);
  EXPECT_NEAR(std::max(std::abs(first), std::abs(second)), l2 / 3, 1e-12) << "the bobs span l2 at rest";
  EXPECT_NEAR(d.modes[0][0][1], d.rest[0][1], 1e-15) << "no vertical motion to first order";
}

TEST(DeformedShapes, ASpringChainIsDrawnAtStations) {
  Equations e = derive_model("two_mass_chain");
  DeformedShapes d = deformed_shapes(e, e.symbols.parameter_defaults, e.symbols.input_defaults, {0, 0, 0, 0}, {{0.5, -0.25}});
  ASSERT_TRUE(d.refusal.empty()) << d.refusal;
  EXPECT_TRUE(d.stations);
  EXPECT_EQ(d.vertical, "displacement along x");
  ASSERT_EQ(d.modes[0].size(), 2u);
  EXPECT_DOUBLE_EQ(d.modes[0][0][0], 1);
  EXPECT_NEAR(d.modes[0][0][1], 1.0 / 3, 1e-15);
  EXPECT_NEAR(d.modes[0][1][1], -1.0 / 6, 1e-15);
}

}  // namespace
}  // namespace eomgen::test
