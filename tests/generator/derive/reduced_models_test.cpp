// The reduced models of a scene, against closed forms: the braking car without the coordinates
// its question does not need (x alone for the stopping distance, heave and pitch for the nose
// dive), and the two-mass chain in its first mode, η'' + 2ζ₁ω₁ η' + ω₁² η = φ₁ᵀ B F with
// ω₁² = k/m, ζ₁ = α/(2ω₁) + βω₁/2 and φ₁ = (1, 1)/√(2m) (Hiller §8.1).
#include <gtest/gtest.h>

#include <cmath>

#include "derive/decoupled_coordinates.hpp"
#include "derive/linear_model.hpp"
#include "derive/modal_model.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

TEST(DecoupledCoordinates, TheStoppingDistanceNeedsThePointMassAlone) {
  Equations e = derive_model("car_braking");
  std::vector<std::string> dropped = drop_coordinates_not_fed_back(e, {"x", "der(x)"});
  EXPECT_EQ(dropped, (std::vector<std::string>{"z", "theta"}));
  ASSERT_EQ(e.symbols.num_coordinates(), 1u);
  auto points = random_points(e.symbols, 8);
  EXPECT_TRUE(agree_at_points(e.mass_matrix(0, 0), closed_form(e, "m"), points));
  EXPECT_TRUE(agree_at_points(e.forcing[0], closed_form(e, "F - cw*d_x*abs(d_x)"), points));
  EXPECT_TRUE(agree_at_points(e.kinetic_energy, closed_form(e, "m*d_x^2/2"), points));
  EXPECT_TRUE(agree_at_points(e.potential_energy, closed_form(e, "0"), points)) << "z and theta held at 0";
  EXPECT_TRUE(e.outputs.empty()) << "front_travel reads z and theta";
}

TEST(DecoupledCoordinates, TheNoseDiveNeedsHeaveAndPitchButNotTheDistance) {
  Equations full = derive_model("car_braking");
  for (const std::vector<std::string>& needed : {std::vector<std::string>{"theta"}, {"front_travel"}}) {
    Equations e = full;
    EXPECT_EQ(drop_coordinates_not_fed_back(e, needed), (std::vector<std::string>{"x"}));
    ASSERT_EQ(e.symbols.coordinate_names, (std::vector<std::string>{"z", "theta"}));
    auto points = random_points(e.symbols, 8);
    // the pitch equation from the moments about the centre of mass, written here
    EXPECT_TRUE(agree_at_points(e.forcing[1],
                                closed_form(e, "a*cos(theta)*(kf*(z - a*sin(theta)) + cf*(d_z - a*cos(theta)*d_theta))"
                                               " - b*cos(theta)*(kr*(z + b*sin(theta)) + cr*(d_z + b*cos(theta)*d_theta)) - h*F"),
                                points));
    EXPECT_TRUE(agree_at_points(e.mass_matrix(1, 1), closed_form(e, "Iyy"), points));
  }
}

TEST(DecoupledCoordinates, NothingIsDroppedWhereEveryCoordinateFeedsBack) {
  Equations e = derive_model("double_pendulum");
  EXPECT_TRUE(drop_coordinates_not_fed_back(e, {"phi1"}).empty());
  EXPECT_EQ(e.symbols.num_coordinates(), 2u);
  EXPECT_TRUE(drop_coordinates_not_fed_back(e, {"no_such_output"}).empty());
}

TEST(ModalModel, TheTwoMassChainInItsFirstMode) {
  Equations full = derive_model("two_mass_chain");  // m1 m2 k1 k2 k3 alpha beta = 1 1 100 100 100 0.1 0.001
  std::string refusal;
  Equations linear = linearized_model(full, {0, 0}, refusal);
  ASSERT_TRUE(refusal.empty()) << refusal;
  ModalTruncation mt;
  double s = 1 / std::sqrt(2.0);
  mt.equilibrium = {0, 0}, mt.shapes = {{s, s}}, mt.mode_numbers = {1};
  mt.initial_modal_coordinates = {0.01 / s}, mt.initial_modal_rates = {0};
  mt.parameter_values = {1, 1, 100, 100, 100, 0.1, 0.001};
  Equations modal = modal_model(linear, mt);
  ASSERT_EQ(modal.symbols.coordinate_names, (std::vector<std::string>{"eta1"}));
  EXPECT_EQ(modal.model_name, "two_mass_chain_linear_modal");
  auto points = random_points(modal.symbols, 8);
  double omega = 10, zeta = 0.1 / (2 * omega) + 0.001 * omega / 2;
  EXPECT_TRUE(agree_at_points(modal.mass_matrix(0, 0), 1, points));
  EXPECT_TRUE(agree_at_points(modal.forcing[0],
                              closed_form(modal, "-" + std::to_string(omega * omega) + "*eta1 - " + std::to_string(2 * zeta * omega) +
                                                     "*d_eta1 + F/sqrt(2)"),
                              points, 1e-13));
  // the questions of a scene still apply: x1 = x2 = η/√2, their rates, and the middle spring's force (zero in this mode)
  ASSERT_GE(modal.outputs.size(), 5u);
  EXPECT_EQ(modal.outputs[0].name, "x1");
  EXPECT_EQ(modal.outputs[3].name, "der(x2)");
  EXPECT_TRUE(agree_at_points(modal.outputs[0].expression, closed_form(modal, "eta1/sqrt(2)"), points, 1e-15));
  EXPECT_TRUE(agree_at_points(modal.outputs[3].expression, closed_form(modal, "d_eta1/sqrt(2)"), points, 1e-15));
  EXPECT_EQ(modal.outputs[4].name, "middle_spring_force");
  EXPECT_TRUE(agree_at_points(modal.outputs[4].expression, 0, points, 1e-12));
  EXPECT_NEAR(modal.symbols.initial_coordinates[0], 0.01 * std::sqrt(2.0), 1e-15);
}

}  // namespace
}  // namespace eomgen::test
