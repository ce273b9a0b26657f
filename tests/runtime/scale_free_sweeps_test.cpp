// Sweeps and ensembles that do not depend on the units or the time scale of the numbers:
// the pendulum with pivot damping d, λ² + d/(m l²) λ + g/l = 0, scaled in time by s (g·s², d·s)
// and in its unit of mass by u (m·u, d·u), s and u from 1e-12 to 1e12. Its eigenvalues cross
// the imaginary axis at d = 0 exactly, as the pair ±i·√(g/l)·s; the stable interval starts
// there. An ensemble over its amplitude measures periods of 4·√(l/g)·K(sin(φ0/2))/s, with no
// sample left out.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include <fmt/format.h>

#include "analyse/eigenvalue_sweep.hpp"
#include "analyse/ensemble.hpp"
#include "analyse/signal_measures.hpp"
#include "generated/header_registry.hpp"

namespace eomgen::test {
namespace {

using runtime::Problem;

int parameter_index(const eomgen_model_abi& m, const std::string& name) {
  for (std::size_t i = 0; i < m.num_parameters; ++i)
    if (name == m.parameter_names[i]) return int(i);
  ADD_FAILURE() << "no parameter " << name;
  return 0;
}

// the pendulum, time scaled by s and mass by u
Problem scaled_pendulum(double s, double u, double d) {
  const eomgen_model_abi* m = generated_model("pendulum").abi;
  Problem p{m, std::vector<double>(m->default_parameters, m->default_parameters + m->num_parameters),
            std::vector<double>(m->num_inputs, 0.0)};
  p.parameters[std::size_t(parameter_index(*m, "g"))] *= s * s;
  p.parameters[std::size_t(parameter_index(*m, "m"))] *= u;
  p.parameters[std::size_t(parameter_index(*m, "d"))] = d * s * u;
  return p;
}

// √(g/l) of the pendulum at its default parameters: its small oscillations' frequency
double natural_frequency() {
  const eomgen_model_abi& m = *generated_model("pendulum").abi;
  return std::sqrt(m.default_parameters[parameter_index(m, "g")] / m.default_parameters[parameter_index(m, "l")]);
}

const std::vector<double>& scales() {
  static const std::vector<double> all{1e-12, 1e-6, 1, 1e6, 1e12};
  return all;
}

TEST(ScaleFreeSweeps, TheCrossingOfThePendulumsDampingIsFoundAtEveryScale) {
  for (double s : scales())
    for (double u : scales()) {
      Problem base = scaled_pendulum(s, u, 0.0);
      const eomgen_model_abi& m = *base.model;
      // d from −s·u to 2·s·u in 8 points: 0 is not among them
      runtime::SweepAxis axis{parameter_index(m, "d"), -s * u, 2 * s * u, 8};
      runtime::StartState hanging = [](const std::vector<double>&) { return std::optional<std::vector<double>>({0.0, 0.0}); };
      std::atomic<bool> stop{false};
      runtime::EigenvalueSweep sweep =
          runtime::sweep_eigenvalues(base, hanging, true, axis, 1e-10, 1, [](long, long) {}, stop);
      std::string at = fmt::format("s = {:g}, u = {:g}", s, u);
      EXPECT_DOUBLE_EQ(sweep.resolution, 3e-10 * s * u) << at;
      ASSERT_EQ(sweep.crossings.size(), 1u) << at;
      const runtime::AxisCrossing& c = sweep.crossings[0];
      EXPECT_LE(std::abs(c.parameter), sweep.resolution) << at;
      EXPECT_TRUE(c.oscillatory) << at;
      EXPECT_FALSE(c.destabilizing) << at << ": more damping stabilizes";
      EXPECT_NEAR(c.eigenvalue.imag() / s, natural_frequency(), 1e-6) << at;
      ASSERT_EQ(sweep.stable.size(), 1u) << at;
      EXPECT_EQ(sweep.stable[0].low, c.parameter) << at << ": the stable interval starts at the crossing";
      EXPECT_DOUBLE_EQ(sweep.stable[0].high, 2 * s * u) << at;
      EXPECT_TRUE(sweep.stable[0].open_high) << at;
      for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(sweep.verdicts[k], "unstable") << at << ", point " << k;
    }
}

// K(k) by the arithmetic-geometric mean: π / (2 AGM(1, √(1 − k²)))
double complete_elliptic_k(double k) {
  double a = 1, b = std::sqrt(1 - k * k);
  for (int i = 0; i < 40 && std::abs(a - b) > 1e-16 * a; ++i) {
    double next = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = next;
  }
  return M_PI / (2 * a);
}

TEST(ScaleFreeSweeps, AnEnsemblesPeriodsScaleWithTimeAndNoSampleIsLost) {
  for (double s : scales()) {
    runtime::EnsembleSetup setup;
    setup.base = scaled_pendulum(s, 1.0, 0.0);
    const eomgen_model_abi& m = *setup.base.model;
    setup.initial_state = {0.5, 0.0};
    setup.settings.t_end = 12 / s;
    setup.settings.dt_out = 0.002 / s;
    setup.settings.rtol = 1e-11;
    // the velocities are of the order of s: the absolute tolerance follows them
    setup.settings.atol = 1e-13 * std::min(1.0, s);
    setup.settings.integrator = "cvode-adams";
    runtime::Variation amplitude;
    amplitude.target = runtime::Variation::Target::state;
    amplitude.index = 0;
    amplitude.name = m.state_names[0];
    amplitude.distribution = {runtime::Distribution::Kind::uniform, 0.2, 2.0};
    setup.variations = {amplitude};
    runtime::Measure period;
    period.kind = runtime::MeasureKind::period;
    period.signal = m.state_names[0];
    setup.measures = {period};
    std::atomic<bool> stop{false};
    runtime::EnsembleShare share = runtime::simulate_ensemble(setup, 12, {}, 1, [](long, long) {}, stop);
    ASSERT_EQ(share.samples.size(), 12u) << "s = " << s;
    for (const runtime::SampleRun& run : share.samples) {
      ASSERT_FALSE(run.failed) << "s = " << s << ": " << run.failure;
      double phi0 = run.drawn[0];
      double exact = 4 / natural_frequency() * complete_elliptic_k(std::sin(phi0 / 2));
      ASSERT_TRUE(std::isfinite(run.measures[0])) << "s = " << s << ", φ0 = " << phi0;
      EXPECT_NEAR(run.measures[0] * s / exact, 1.0, 1e-8) << "s = " << s << ", φ0 = " << phi0;
    }
  }
}

}  // namespace
}  // namespace eomgen::test
