#include "support/expanded_oracle.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "parse/model_file.hpp"
#include "spatial/joint_tree_dynamics.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {

using GiNaC::ex;

Model built(const std::string& text) {
  Diagnostics d;
  ModelFile file = parse_model_text(text, "tree.toml", d);
  Model m = build_model(file, d);
  EXPECT_TRUE(d.empty()) << d.format();
  return m;
}

std::map<std::string, double> random_point(const Equations& e, std::mt19937& random) {
  std::uniform_real_distribution<double> angle(-2, 2), rate(-3, 3), scale(0.5, 2);
  std::map<std::string, double> values;
  for (const std::string& p : e.symbols.parameter_names) values[p] = scale(random);
  for (const std::string& q : e.symbols.coordinate_names) values[q] = angle(random), values["der(" + q + ")"] = rate(random);
  for (std::size_t k = 0; k < e.symbols.coordinate_names.size(); ++k) values[fmt::format("ddq{}", k)] = rate(random);
  return values;
}

void expect_expanded_equations(const std::string& tree_text, unsigned n) {
  Model model = built(tree_text);
  ASSERT_FALSE(why_not_a_joint_tree(model)) << *why_not_a_joint_tree(model);
  Equations recursive = derive_text(tree_text), expanded = derive_text(tree_text, "model.toml", model_written_out());
  ASSERT_TRUE(recursive.newton_euler());
  ASSERT_EQ(recursive.newton_euler()->inverse_dynamics.size(), n);
  std::mt19937 random(5);
  for (int point = 0; point < 10; ++point) {
    std::map<std::string, double> values = random_point(recursive, random);
    GiNaC::exmap at = point_by_name(recursive, values), full = point_by_name(expanded, values);
    auto near = [](double x, double y, const std::string& what) {
      EXPECT_NEAR(x, y, 1e-11 * std::max({1.0, std::abs(x), std::abs(y)})) << what;
    };
    for (unsigned j = 0; j < n; ++j) {
      double f = value_at(recursive.forcing[j], at);
      near(f, value_at(expanded.forcing[j], full), fmt::format("f[{}]", j));
      double Mddq = 0;
      for (unsigned k = 0; k < n; ++k) {
        double M = value_at(recursive.mass_matrix(j, k), at);
        near(M, value_at(expanded.mass_matrix(j, k), full), fmt::format("M[{}][{}]", j, k));
        Mddq += M * values.at(fmt::format("ddq{}", k));
      }
      near(value_at(recursive.newton_euler()->inverse_dynamics[j], at), Mddq - f, fmt::format("tau[{}] = (M q'' - f)[{}]", j, j));
    }
    near(value_at(recursive.kinetic_energy, at), value_at(expanded.kinetic_energy, full), "T");
  }
}

void expect_expanded_derivatives(const std::string& tree_text, unsigned n) {
  Equations recursive = derive_text(tree_text), expanded = derive_text(tree_text, "model.toml", model_written_out());
  ASSERT_TRUE(recursive.newton_euler() && recursive.newton_euler()->bodies_gradient);
  const BodiesGradient& bodies = *recursive.newton_euler()->bodies_gradient;
  ASSERT_EQ(bodies.applied_inverse_dynamics.size(), n);
  const InverseDynamicsGradient* closed_form = bodies.expressions();
  ASSERT_TRUE(closed_form);
  std::vector<ex> tau(n);
  std::vector<GiNaC::symbol> ddq(n);
  for (unsigned j = 0; j < n; ++j) {
    tau[j] = -expanded.forcing[j];
    for (unsigned k = 0; k < n; ++k) tau[j] += expanded.mass_matrix(j, k) * ddq[k];
  }
  // each derivative taken once, then evaluated at the points
  GiNaC::matrix closed_q(n, n), closed_rate(n, n), expected_q(n, n), expected_rate(n, n);
  for (unsigned j = 0; j < n; ++j)
    for (unsigned c = 0; c < n; ++c) {
      closed_q(j, c) = closed_form->coordinates(j, c) + bodies.applied_inverse_dynamics[j].diff(recursive.symbols.coordinates[c]);
      closed_rate(j, c) = closed_form->velocities(j, c) + bodies.applied_inverse_dynamics[j].diff(recursive.symbols.velocities[c]);
      expected_q(j, c) = tau[j].diff(expanded.symbols.coordinates[c]);
      expected_rate(j, c) = tau[j].diff(expanded.symbols.velocities[c]);
    }
  std::mt19937 random(11);
  for (int point = 0; point < 6; ++point) {
    std::map<std::string, double> values = random_point(recursive, random);
    GiNaC::exmap at = point_by_name(recursive, values), full = point_by_name(expanded, values);
    for (unsigned k = 0; k < n; ++k) full[ddq[k]] = values.at(fmt::format("ddq{}", k));
    for (unsigned j = 0; j < n; ++j)
      for (unsigned c = 0; c < n; ++c) {
        double by_q = value_at(closed_q(j, c), at), by_rate = value_at(closed_rate(j, c), at);
        double want_q = value_at(expected_q(j, c), full), want_rate = value_at(expected_rate(j, c), full);
        EXPECT_NEAR(by_q, want_q, 1e-11 * std::max(1.0, std::abs(want_q))) << "dtau" << j << "/dq" << c << " at " << point;
        EXPECT_NEAR(by_rate, want_rate, 1e-11 * std::max(1.0, std::abs(want_rate))) << "dtau" << j << "/dq'" << c;
      }
  }
}

}  // namespace eomgen::test
