// The parts of a Monte-Carlo ensemble: sample statistics against values worked by hand
// (type-7 quantiles as in R and NumPy), the measures of known signals, the draws' moments,
// and a share of the samples equal to the same samples of the whole ensemble.
#include <gtest/gtest.h>

#include <cmath>

#include "analyse/ensemble.hpp"
#include "analyse/sample_statistics.hpp"
#include "analyse/signal_measures.hpp"
#include "generated/header_registry.hpp"

namespace eomgen::test {
namespace {

TEST(SampleStatistics, MeanDeviationAndType7QuantilesOfASmallSample) {
  // 1..10 shuffled, with a NaN left out: mean 5.5, variance 55/6
  runtime::SampleStatistics s = runtime::sample_statistics({7, 3, NAN, 10, 1, 4, 9, 2, 8, 6, 5}, {0, 0.25, 0.5, 0.9, 1});
  EXPECT_EQ(s.count, 10);
  EXPECT_DOUBLE_EQ(s.mean, 5.5);
  EXPECT_DOUBLE_EQ(s.standard_deviation, std::sqrt(55.0 / 6));
  EXPECT_DOUBLE_EQ(s.standard_error, std::sqrt(55.0 / 6) / std::sqrt(10.0));
  // h = p (n − 1): 0 → 1; 2.25 → 3.25; 4.5 → 5.5; 8.1 → 9.1; 9 → 10
  EXPECT_DOUBLE_EQ(s.quantiles[0], 1);
  EXPECT_DOUBLE_EQ(s.quantiles[1], 3.25);
  EXPECT_DOUBLE_EQ(s.quantiles[2], 5.5);
  EXPECT_NEAR(s.quantiles[3], 9.1, 1e-14);
  EXPECT_DOUBLE_EQ(s.quantiles[4], 10);
  runtime::SampleStatistics none = runtime::sample_statistics({NAN}, {0.5});
  EXPECT_EQ(none.count, 0);
  EXPECT_TRUE(std::isnan(none.mean));
  EXPECT_TRUE(std::isnan(none.quantiles[0]));
}

TEST(SignalMeasures, PeriodExtremesAndTimeMeanOfKnownSignals) {
  // 0.3 + 2 sin(2π t/T + 0.4) sampled coarsely (20 samples a period): the cubic finds each crossing
  const double T = 1.7;
  std::vector<double> t, v;
  for (int k = 0; k <= 200; ++k) {
    t.push_back(k * T / 20);
    v.push_back(0.3 + 2 * std::sin(2 * M_PI * t.back() / T + 0.4));
  }
  EXPECT_NEAR(runtime::measure_signal(runtime::MeasureKind::period, t, v), T, 1e-6);
  EXPECT_NEAR(runtime::measure_signal(runtime::MeasureKind::mean, t, v), 0.3, 1e-12);  // whole periods, trapezoids exact
  EXPECT_NEAR(runtime::measure_signal(runtime::MeasureKind::maximum, t, v), 2.3, 0.05);
  EXPECT_DOUBLE_EQ(runtime::measure_signal(runtime::MeasureKind::final_value, t, v), v.back());
  // a decaying signal has no period of two crossings in this window
  std::vector<double> decay;
  for (double s : t) decay.push_back(std::exp(-s));
  EXPECT_TRUE(std::isnan(runtime::measure_signal(runtime::MeasureKind::period, t, decay)));
}

TEST(EnsembleDraws, MomentsOfTheDistributionsAndIndependenceOfTheSampleOrder) {
  runtime::Distribution normal{runtime::Distribution::Kind::normal, 2.0, 0.5};
  runtime::Distribution uniform{runtime::Distribution::Kind::uniform, -1.0, 3.0};
  runtime::Distribution lognormal{runtime::Distribution::Kind::lognormal, 0.1, 0.2};
  const long n = 200000;
  double sum = 0, squares = 0, low = INFINITY, high = -INFINITY, log_sum = 0, correlation = 0;
  for (long k = 0; k < n; ++k) {
    double x = normal.draw(7, k, 0), u = uniform.draw(7, k, 1);
    sum += x, squares += x * x;
    low = std::min(low, u), high = std::max(high, u);
    log_sum += lognormal.draw(7, k, 2);
    correlation += (x - 2.0) * (normal.draw(7, k, 3) - 2.0);  // another variable of the same sample
  }
  double mean = sum / n, sd = std::sqrt(squares / n - mean * mean);
  EXPECT_NEAR(mean, 2.0, 4 * 0.5 / std::sqrt(double(n)));
  EXPECT_NEAR(sd, 0.5, 4 * 0.5 / std::sqrt(2.0 * n));
  EXPECT_GE(low, -1.0);
  EXPECT_LE(high, 3.0);
  EXPECT_NEAR(low, -1.0, 1e-3);
  EXPECT_NEAR(high, 3.0, 1e-3);
  EXPECT_NEAR(log_sum / n, lognormal.mean(), 4 * 0.25 / std::sqrt(double(n)));
  EXPECT_NEAR(correlation / n / 0.25, 0.0, 4 / std::sqrt(double(n)));
  // the same seed, sample and variable give the same number; another seed another
  EXPECT_EQ(normal.draw(7, 123, 0), normal.draw(7, 123, 0));
  EXPECT_NE(normal.draw(7, 123, 0), normal.draw(8, 123, 0));
}

TEST(EnsembleShares, TwoSharesHoldTheSamplesOfTheWholeEnsemble) {
  const eomgen_model_abi* m = generated_model("pendulum").abi;
  runtime::EnsembleSetup setup;
  setup.base = {m, std::vector<double>(m->default_parameters, m->default_parameters + m->num_parameters), {}};
  setup.initial_state.assign(m->default_state, m->default_state + m->num_states);
  setup.settings.t_end = 2;
  setup.settings.dt_out = 0.05;
  setup.settings.integrator = "cvode-bdf";
  setup.variations.push_back({runtime::Variation::Target::parameter, 1, "l", {runtime::Distribution::Kind::normal, 1.0, 0.1}});
  setup.variations.push_back({runtime::Variation::Target::state, 0, "phi", {runtime::Distribution::Kind::uniform, 0.2, 0.4}});
  setup.signals = {"phi"};
  setup.measures = {{runtime::MeasureKind::maximum, "phi"}};
  ASSERT_STREQ(m->parameter_names[1], "l");
  std::atomic<bool> stop{false};
  runtime::EnsembleShare whole = runtime::simulate_ensemble(setup, 9, {}, 3, nullptr, stop);
  runtime::EnsembleShare first = runtime::simulate_ensemble(setup, 9, {0, 4}, 1, nullptr, stop);
  runtime::EnsembleShare second = runtime::simulate_ensemble(setup, 9, {4, 9}, 2, nullptr, stop);
  ASSERT_EQ(whole.samples.size(), 9u);
  ASSERT_EQ(first.samples.size() + second.samples.size(), 9u);
  EXPECT_EQ(whole.times.size(), 41u);
  for (std::size_t k = 0; k < 9; ++k) {
    const runtime::SampleRun& part = k < 4 ? first.samples[k] : second.samples[k - 4];
    ASSERT_FALSE(whole.samples[k].failed) << whole.samples[k].failure;
    EXPECT_EQ(part.drawn, whole.samples[k].drawn);
    EXPECT_EQ(part.signals, whole.samples[k].signals);
    // the largest swing is the drawn initial angle: the pendulum starts at rest
    EXPECT_NEAR(whole.samples[k].measures[0], whole.samples[k].drawn[1], 1e-7);
    EXPECT_EQ(whole.samples[k].signals[0].front(), whole.samples[k].drawn[1]);
  }
}

}  // namespace
}  // namespace eomgen::test
