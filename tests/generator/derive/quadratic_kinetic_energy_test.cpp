// When the header may compute T as ½ vᵀ M v: a joint tree's T (in the recursion's quantities) is
// that form, the same T with a term linear in a velocity added is not, and a top's T in the
// model's symbols alone stays the formula it is; the flag is the pipeline's.
#include <gtest/gtest.h>

#include "derive/quadratic_kinetic_energy.hpp"
#include "derive/state_values.hpp"
#include "pipeline.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

TEST(QuadraticKineticEnergy, AJointTreesTIsHalfItsVelocitiesThroughM) {
  Derivation d = derive_model_file(std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/models/seven_joint_arm.toml");
  ASSERT_TRUE(d.equations) << d.diagnostics.format();
  Equations e = *d.equations;
  EXPECT_TRUE(kinetic_energy_is_quadratic_form(e));
  EXPECT_TRUE(e.kinetic_energy_from_mass_matrix);
  // a gyroscopic term, linear in a velocity, as a rotor's or a moving frame's would add
  e.kinetic_energy += GiNaC::numeric(3, 10) * e.symbols.velocities[2];
  EXPECT_FALSE(kinetic_energy_is_quadratic_form(e));
}

TEST(QuadraticKineticEnergy, ATInTheModelsSymbolsStaysAFormula) {
  Equations top = derive_model("ball_joint_top");
  EXPECT_FALSE(top.kinetic_energy_from_mass_matrix);
  EXPECT_FALSE(derive_model("double_pendulum").kinetic_energy_from_mass_matrix);
  EXPECT_TRUE(derive_model("tumbling_body").kinetic_energy_from_mass_matrix) << "a free body's T through its rotation";
}

}  // namespace
}  // namespace eomgen::test
