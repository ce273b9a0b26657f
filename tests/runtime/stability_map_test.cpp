// The governor's stability map against its symbolic Hurwitz conditions: every
// grid point has the verdict of the conditions, except within one grid cell of
// the boundary; and a map of a model whose equilibrium moves is continuous.
#include <gtest/gtest.h>

#include <cmath>

#include "analyse/equilibrium.hpp"
#include "symbolic_analysis/stability_conditions.hpp"
#include "analyse/stability_map.hpp"
#include "generated/header_registry.hpp"
#include "support/test_support.hpp"
#include "symbolic/evaluate.hpp"

namespace eomgen::test {
namespace {

TEST(StabilityMap, GovernorBoundaryLiesWithinOneCellOfTheSymbolicBoundary) {
  const eomgen_model_abi* m = generated_model("watt_governor").abi;
  runtime::Problem p{m, std::vector<double>(m->default_parameters, m->default_parameters + m->num_parameters), {}};
  auto eq = runtime::find_equilibrium(p, std::vector<double>(m->default_state, m->default_state + m->num_states));
  ASSERT_TRUE(eq.converged);
  runtime::SweepAxis b{4, 0.05, 1.2, 60}, J{3, 0.05, 3.0, 50};  // parameter order m, l, n, J, b, ...
  ASSERT_STREQ(m->parameter_names[4], "b");
  ASSERT_STREQ(m->parameter_names[3], "J");
  std::atomic<bool> stop{false};
  runtime::StabilityMap map = runtime::sweep(p, eq.state, false, b, J, 2, nullptr, stop);
  ASSERT_EQ(map.computed, 60 * 50);
  Equations e = derive_model("watt_governor");
  StabilityConditions c = stability_conditions(e, {"b", "J"}, p.parameters, {}, eq.state);
  auto stable_symbolically = [&](int i, int j) {
    for (const GiNaC::ex& condition : c.conditions) {
      double v = evaluate(condition, [&](const GiNaC::symbol& s) { return s.get_name() == "b" ? b.value(i) : J.value(j); });
      if (!(v > 0)) return false;
    }
    return true;
  };
  int boundary_cells = 0;
  for (int j = 0; j < J.count; ++j)
    for (int i = 0; i < b.count; ++i) {
      bool numeric = map.degree[j * b.count + i] < 0, symbolic = stable_symbolically(i, j);
      if (numeric == symbolic) continue;
      // a disagreement is allowed only next to a change of the symbolic verdict
      bool near_boundary = false;
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          int ii = i + di, jj = j + dj;
          if (ii >= 0 && jj >= 0 && ii < b.count && jj < J.count && stable_symbolically(ii, jj) != symbolic) near_boundary = true;
        }
      EXPECT_TRUE(near_boundary) << "b = " << b.value(i) << ", J = " << J.value(j);
      ++boundary_cells;
    }
  EXPECT_LT(boundary_cells, 60);
  int stable = 0;
  for (double d : map.degree) stable += d < 0;
  EXPECT_GT(stable, 1000);
  EXPECT_LT(stable, 2900);
}

TEST(StabilityMap, StopsWhenAskedAndKeepsWhatItComputed) {
  const eomgen_model_abi* m = generated_model("pendulum").abi;
  runtime::Problem p{m, std::vector<double>(m->default_parameters, m->default_parameters + m->num_parameters), {}};
  std::atomic<bool> stop{true};
  runtime::StabilityMap map = runtime::sweep(p, {0, 0}, false, {3, 0.0, 1.0, 10}, {1, 0.5, 2.0, 10}, 2, nullptr, stop);
  EXPECT_TRUE(map.interrupted);
  EXPECT_EQ(map.computed, 0);
}

}  // namespace
}  // namespace eomgen::test
