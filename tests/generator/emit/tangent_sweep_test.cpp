// The tangent sweep against symbolic differentiation: the derivatives it gives of the
// mass matrix and forcing of several models, with its tangents and the common
// subexpressions substituted back, equal the gradients of the entries at random points.
#include <gtest/gtest.h>

#include <random>

#include "emit/tangent_sweep.hpp"
#include "support/test_support.hpp"
#include "symbolic/evaluate.hpp"
#include "symbolic/gradient.hpp"

namespace eomgen::test {
namespace {

// back in the model's symbols: tangents, then temporaries, latest first
GiNaC::ex expanded(GiNaC::ex e, const std::vector<Temporary>& tangents, const std::vector<Temporary>& temporaries) {
  for (auto t = tangents.rbegin(); t != tangents.rend(); ++t) e = e.subs(t->name == t->definition);
  for (auto t = temporaries.rbegin(); t != temporaries.rend(); ++t) e = e.subs(t->name == t->definition);
  return e;
}

class SweptModel : public ::testing::TestWithParam<std::string> {};

TEST_P(SweptModel, DerivativesEqualTheGradientsOfMassMatrixAndForcing) {
  Equations e = derive_model(GetParam());
  const Symbols& s = e.symbols;
  std::size_t n = e.num_velocities();
  std::vector<GiNaC::ex> entries = upper_triangle(e.mass_matrix, n);
  entries.insert(entries.end(), e.forcing.begin(), e.forcing.end());
  std::vector<GiNaC::ex> directions(s.coordinates.begin(), s.coordinates.end());
  directions.insert(directions.end(), s.velocities.begin(), s.velocities.end());
  directions.insert(directions.end(), s.inputs.begin(), s.inputs.end());

  BodyWriter writer(e);
  CseBatch batch = writer.reduced_batch(entries);
  TangentSweep sweep(writer, directions);
  sweep.follow(batch);
  ASSERT_FALSE(batch.temporaries.empty()) << "the sweep is exercised through temporaries";

  std::mt19937 random(17);
  std::uniform_real_distribution<double> value(0.3, 1.2);
  for (int point = 0; point < 3; ++point) {
    std::map<std::string, double> at;
    auto value_of = [&](const GiNaC::symbol& x) {
      auto [it, fresh] = at.emplace(x.get_name(), 0.0);
      if (fresh) it->second = value(random);
      return it->second;
    };
    for (std::size_t k = 0; k < entries.size(); ++k) {
      std::vector<GiNaC::ex> swept = sweep.derivatives(batch.outputs[k]);
      std::vector<GiNaC::ex> exact = gradient(entries[k], directions);
      for (std::size_t j = 0; j < directions.size(); ++j) {
        double a = evaluate(expanded(swept[j], sweep.tangents_written(), batch.temporaries), value_of);
        double b = evaluate(exact[j], value_of);
        EXPECT_NEAR(a, b, 1e-12 * (1 + std::abs(b))) << GetParam() << " entry " << k << " along " << directions[j];
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Models, SweptModel,
                         ::testing::Values("double_pendulum", "cart_pendulum", "slider_crank", "heavy_symmetric_top",
                                           "rolling_disk"));

}  // namespace
}  // namespace eomgen::test
