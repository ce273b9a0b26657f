// The fastest oscillation's period and the warning when the output interval cannot follow it: a
// pendulum of ω = √(g/l) at time scales from 1e-6 to 1e6 (g scaled by s²), against an interval of
// 0.01 s: a warning exactly when 0.01 s is longer than half the period.
#include <gtest/gtest.h>

#include <cmath>

#include "analyse/output_interval.hpp"
#include "generated/header_registry.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

TEST(OutputInterval, AWarningExactlyWhenTheIntervalSkipsHalfAPeriod) {
  const eomgen_model_abi* m = generated_model("pendulum").abi;
  for (double s : {1e-6, 1e-3, 1.0, 1e3, 1e6}) {
    runtime::Problem p{m, std::vector<double>(m->default_parameters, m->default_parameters + m->num_parameters),
                       std::vector<double>(m->num_inputs, 0.0)};
    double g = 0, l = 0;
    for (std::size_t i = 0; i < m->num_parameters; ++i) {
      std::string name = m->parameter_names[i];
      if (name == "g") p.parameters[i] *= s * s, g = p.parameters[i];
      if (name == "l") l = p.parameters[i];
      if (name == "d") p.parameters[i] = 0;
    }
    std::vector<double> hanging{0.0, 0.0};
    double period = 2 * M_PI / std::sqrt(g / l);
    EXPECT_NEAR(runtime::fastest_period(p, 0.0, hanging) / period, 1, 1e-9) << "s = " << s;
    auto warning = runtime::aliasing_warning(p, 0.0, hanging, 0.01);
    EXPECT_EQ(warning.has_value(), 0.01 > period / 2) << "s = " << s;
    if (warning) {
      EXPECT_NE(warning->find("cannot show it"), std::string::npos) << *warning;
    }
  }
  // upright, nothing oscillates: no period, no warning
  runtime::Problem upright{m, std::vector<double>(m->default_parameters, m->default_parameters + m->num_parameters),
                           std::vector<double>(m->num_inputs, 0.0)};
  EXPECT_TRUE(std::isinf(runtime::fastest_period(upright, 0.0, {M_PI, 0.0})));
  EXPECT_FALSE(runtime::aliasing_warning(upright, 0.0, {M_PI, 0.0}, 10.0));
}

}  // namespace
}  // namespace eomgen::test
