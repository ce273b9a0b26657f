// The fastest oscillation's period and the warning when the output interval cannot follow it: a
// pendulum of ω = √(g/l) at time scales from 1e-6 to 1e6 (g scaled by s²), against an interval of
// 0.01 s: a warning exactly when 0.01 s is longer than half the period. The same for a linear
// system's A, with its slowest time against a response's end.
#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>

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

// x'' + 2ζω x' + ω² x = 0 beside a free drift y' = 0 and a slow decay z' = −ω z/1e3, at time
// scales 1e-12 … 1e12: the fastest period 2π/(ω√(1 − ζ²)), the slowest time 1e3/ω (the drift's zero
// eigenvalue left out), and each warning exactly where the defaults 0.01 s and 10 s miss them.
TEST(OutputInterval, ALinearSystemsFastestPeriodAndSlowestTimeAtEveryScale) {
  const double zeta = 0.1;
  for (double omega : {1e-12, 1e-9, 1e-6, 1e-3, 1.0, 1e3, 1e6, 1e9, 1e12}) {
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(4, 4);
    A(0, 1) = 1, A(1, 0) = -omega * omega, A(1, 1) = -2 * zeta * omega, A(3, 3) = -omega / 1e3;
    double period = 2 * M_PI / (omega * std::sqrt(1 - zeta * zeta)), slowest = 1e3 / omega;
    EXPECT_NEAR(runtime::fastest_period(A) / period, 1, 1e-9) << "omega = " << omega;
    EXPECT_NEAR(runtime::slowest_time(A) / slowest, 1, 1e-9) << "omega = " << omega;
    EXPECT_EQ(runtime::aliasing_warning(period, 0.01, "the fastest mode").has_value(), 0.01 > period / 2) << omega;
    auto span = runtime::span_warning(slowest, 10, 0.01);
    EXPECT_EQ(span.has_value(), 10 < slowest) << "omega = " << omega;
    if (span) {
      EXPECT_NE(span->find(fmt::format("--t-end {:.2g}", 10 * slowest)), std::string::npos) << *span;
    }
  }
  // nothing but a drift: no time to show, no warning
  EXPECT_EQ(runtime::slowest_time(Eigen::MatrixXd::Zero(2, 2)), 0);
  EXPECT_FALSE(runtime::span_warning(0, 10, 0.01));
}

}  // namespace
}  // namespace eomgen::test
