// Appell's equations against Lagrange's equations of the first kind, derived
// independently from the same model file: at 20 random consistent states of every
// nonholonomic model both give the same accelerations q''. Also the known closed
// forms of the Chaplygin sleigh and the kinematic equations of the rolling disk.
#include <gtest/gtest.h>

#include <random>

#include "kinematics/mechanics.hpp"
#include "pipeline.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

Equations derive_with_method(const std::string& name, const std::string& method) {
  std::string text = read_file(model_path(name));
  std::size_t at = text.find("method = \"appell\"");
  if (at == std::string::npos) at = text.find("method ");
  text.replace(at, text.find('\n', at) - at, "method = \"" + method + "\"");
  std::size_t section = text.find("[pseudo_velocities]");
  if (method != "appell" && section != std::string::npos) text.erase(section);
  Derivation d = derive_model_text(text, model_path(name));
  EXPECT_TRUE(d.diagnostics.empty()) << name;
  return d.equations.value_or(Equations{});
}

double number(const GiNaC::ex& e) { return GiNaC::ex_to<GiNaC::numeric>(e.evalf()).to_double(); }

class NonholonomicModel : public ::testing::TestWithParam<std::string> {};

TEST_P(NonholonomicModel, AppellAndLagrangeOneGiveTheSameAccelerations) {
  Equations appell = derive_model(GetParam());
  Equations lagrange1 = derive_with_method(GetParam(), "lagrange1");
  ASSERT_EQ(appell.method, "appell");
  ASSERT_EQ(lagrange1.method, "lagrange1");
  const Symbols& s = appell.symbols;
  std::size_t n = s.num_coordinates(), k = appell.num_velocities(), m = lagrange1.constraints.size();
  std::mt19937 random(2024);
  std::uniform_real_distribution<double> coordinate(0.2, 1.3), velocity(-2, 2), scale(0.7, 1.3);
  GiNaC::Digits = 30;
  for (int trial = 0; trial < 20; ++trial) {
    // a consistent state: any q and pseudo-velocities s, then q' = W s + w
    GiNaC::exmap point{{s.time, GiNaC::numeric(0.4)}};
    for (std::size_t i = 0; i < n; ++i) point[s.coordinates[i]] = GiNaC::numeric(coordinate(random));
    for (std::size_t i = 0; i < s.parameters.size(); ++i)
      point[s.parameters[i]] = GiNaC::numeric(s.parameter_defaults[i] * scale(random));
    for (std::size_t i = 0; i < k; ++i) point[s.velocities[i]] = GiNaC::numeric(velocity(random));
    // the Lagrange I derivation has its own symbols: the same values, by position
    const Symbols& l = lagrange1.symbols;
    GiNaC::exmap lagrange_point{{l.time, point[s.time]}};
    for (std::size_t i = 0; i < s.parameters.size(); ++i) lagrange_point[l.parameters[i]] = point[s.parameters[i]];
    for (std::size_t i = 0; i < n; ++i) {
      point[appell.coordinate_velocities[i]] = appell.coordinate_rates[i].subs(point).evalf();
      lagrange_point[l.coordinates[i]] = point[s.coordinates[i]];
      lagrange_point[l.velocities[i]] = point[appell.coordinate_velocities[i]];
    }
    // Appell: s' = M_s⁻¹ f_s, then q'' = d/dt (W s + w) = Σ ∂r/∂q q' + Σ ∂r/∂s s' + ∂r/∂t
    GiNaC::matrix Ms(k, k), fs(k, 1), unknown(k, 1);
    for (unsigned i = 0; i < k; ++i) {
      fs(i, 0) = appell.forcing[i].subs(point).evalf();
      unknown(i, 0) = GiNaC::symbol("a" + std::to_string(i));
      for (unsigned j = 0; j < k; ++j) Ms(i, j) = appell.mass_matrix(i, j).subs(point).evalf();
    }
    GiNaC::matrix sdot = Ms.solve(unknown, fs);
    // Lagrange I: [M −Cᵀ; C 0][q''; λ] = [f; −γ]
    GiNaC::matrix K(n + m, n + m), right(n + m, 1), all(n + m, 1);
    for (unsigned i = 0; i < n; ++i) {
      right(i, 0) = lagrange1.forcing[i].subs(lagrange_point).evalf();
      for (unsigned j = 0; j < n; ++j) K(i, j) = lagrange1.mass_matrix(i, j).subs(lagrange_point).evalf();
    }
    for (unsigned r = 0; r < m; ++r) {
      for (unsigned j = 0; j < n; ++j) {
        K(n + r, j) = lagrange1.constraints.jacobian(r, j).subs(lagrange_point).evalf();
        K(j, n + r) = -K(n + r, j);
      }
      right(n + r, 0) = (-lagrange1.constraints.acceleration_bias[r]).subs(lagrange_point).evalf();
    }
    for (unsigned i = 0; i < n + m; ++i) all(i, 0) = GiNaC::symbol("b" + std::to_string(i));
    GiNaC::matrix solution = K.solve(all, right);
    for (unsigned j = 0; j < n; ++j) {
      GiNaC::ex r = appell.coordinate_rates[j];
      GiNaC::ex qdd = r.diff(s.time);
      for (unsigned i = 0; i < n; ++i) qdd += r.diff(s.coordinates[i]) * appell.coordinate_velocities[i];
      for (unsigned c = 0; c < k; ++c) qdd += r.diff(s.velocities[c]) * sdot(c, 0);
      double from_appell = number(qdd.subs(point)), from_lagrange = number(solution(j, 0));
      EXPECT_NEAR(from_appell, from_lagrange, 1e-12 * std::max(1.0, std::abs(from_lagrange)))
          << GetParam() << " q''[" << j << "] at trial " << trial;
    }
  }
  GiNaC::Digits = 17;
}

INSTANTIATE_TEST_SUITE_P(Models, NonholonomicModel,
                         ::testing::Values("knife_edge", "chaplygin_sleigh", "rolling_disk", "rolling_ball"));

TEST(RollingBall, AppellEquationsAreAsSimpleAsTheTruth) {
  // inertial angular velocities as pseudo-velocities: M = diag(7/5, 7/5, 2/5) m R², f = 0,
  // exactly, although the Cardan rates bring 1/cos(beta)³ into the transformation
  Equations e = derive_model("rolling_ball");
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = 0; j < 3; ++j)
      EXPECT_TRUE((e.mass_matrix(i, j) - (i != j ? closed_form(e, "0") : closed_form(e, i < 2 ? "7*m*R^2/5" : "2*m*R^2/5")))
                      .expand()
                      .is_zero())
          << "M[" << i << "][" << j << "] = " << e.mass_matrix(i, j);
    EXPECT_TRUE(e.forcing[i].is_zero()) << "f[" << i << "] = " << e.forcing[i];
  }
}

TEST(Appell, ChaplyginSleighHasItsClassicalEquations) {
  Equations e = derive_model("chaplygin_sleigh");
  auto points = random_points(e.symbols, 10);
  // m v' = m a w², (J + m a²) w' = −m a v w
  EXPECT_TRUE(agree_at_points(e.mass_matrix(0, 0), closed_form(e, "m"), points));
  EXPECT_TRUE(agree_at_points(e.mass_matrix(1, 1), closed_form(e, "J + m*a^2"), points));
  EXPECT_TRUE(agree_at_points(e.mass_matrix(0, 1), 0, points));
  GiNaC::symbol v("v"), w("w");
  GiNaC::ex f0 = e.forcing[0].subs(GiNaC::lst{e.symbols.velocities[0], e.symbols.velocities[1]}, GiNaC::lst{v, w});
  GiNaC::ex f1 = e.forcing[1].subs(GiNaC::lst{e.symbols.velocities[0], e.symbols.velocities[1]}, GiNaC::lst{v, w});
  GiNaC::ex a = e.symbols.parameters[2], m = e.symbols.parameters[0];
  EXPECT_TRUE((f0 - m * a * w * w).expand().is_zero()) << f0;
  EXPECT_TRUE((f1 + m * a * v * w).expand().is_zero()) << f1;
}

TEST(Appell, RollingDiskContactPointIsAtRest) {
  // the disk's material point at the contact, v_c + ω × (P − c), with q' = W s: zero
  Equations e = derive_model("rolling_disk");
  const Symbols& s = e.symbols;
  GiNaC::exmap rates;
  for (std::size_t i = 0; i < s.num_coordinates(); ++i) rates[e.coordinate_velocities[i]] = e.coordinate_rates[i];
  GiNaC::ex R = s.parameters[1], psi = s.coordinates[2], theta = s.coordinates[3], phi = s.coordinates[4];
  GiNaC::ex dpsi = e.coordinate_velocities[2], dtheta = e.coordinate_velocities[3], dphi = e.coordinate_velocities[4];
  GiNaC::ex x = s.coordinates[0], y = s.coordinates[1];
  // centre c = (x, y, 0) + R e, e = (−sin ψ cos θ, cos ψ cos θ, sin θ); inertial ω of the 3-1-3 angles
  GiNaC::ex c[3] = {x - R * sin(psi) * cos(theta), y + R * cos(psi) * cos(theta), R * sin(theta)};
  GiNaC::ex omega[3] = {dtheta * cos(psi) + dphi * sin(psi) * sin(theta), dtheta * sin(psi) - dphi * cos(psi) * sin(theta),
                        dpsi + dphi * cos(theta)};
  GiNaC::ex r[3] = {R * sin(psi) * cos(theta), -R * cos(psi) * cos(theta), -R * sin(theta)};  // P − c
  std::vector<GiNaC::ex> q(s.coordinates.begin(), s.coordinates.end());
  for (int a = 0; a < 3; ++a) {
    GiNaC::ex vc = 0;
    for (std::size_t i = 0; i < q.size(); ++i) vc += c[a].diff(GiNaC::ex_to<GiNaC::symbol>(q[i])) * e.coordinate_velocities[i];
    int b = (a + 1) % 3, d = (a + 2) % 3;
    GiNaC::ex contact = vc + omega[b] * r[d] - omega[d] * r[b];
    GiNaC::ex w = GiNaC::wild();
    GiNaC::ex value = contact.subs(rates).expand().subs(GiNaC::pow(GiNaC::cos(w), 2) == 1 - GiNaC::pow(GiNaC::sin(w), 2),
                                                        GiNaC::subs_options::algebraic);
    EXPECT_TRUE(value.expand().is_zero()) << a << ": " << value.expand();
  }
}

}  // namespace
}  // namespace eomgen::test
