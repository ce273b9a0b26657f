// The header's form of dynamics, chosen once per model (emit/dynamics_form): each form on a model
// of models/ that must take it, and the header of each written in that form.
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "emit/cpp_header.hpp"
#include "emit/dynamics_form.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

void expect_form(const std::string& model, DynamicsForm form, const char* mark) {
  Equations e = derive_model(model);
  EXPECT_EQ(dynamics_form(e), form) << model;
  EXPECT_NE(emit_cpp_header(e).find(mark), std::string::npos) << model << " lacks " << mark;
}

TEST(DynamicsForm, EachModelTakesItsForm) {
  expect_form("double_pendulum", DynamicsForm::mass_matrix, "detail::ldlt_factor(M, L, D);");
  expect_form("n_link_pendulum_4_hamilton", DynamicsForm::momentum, "der(q) solves");
  expect_form("spatial_double_pendulum", DynamicsForm::newton_euler,
              "detail::tree_acceleration_gradient(t, x, u, p, static_cast<const T*>(nullptr), L, D, rows);");
  expect_form("tumbling_body", DynamicsForm::newton_euler, "detail::factored_accelerations(t, x, u, p, ddq, L, D);");
  expect_form("lumped_rope", DynamicsForm::particle_tree, "articulated-body recursion");
  expect_form("crane_hook_tree", DynamicsForm::mass_matrix, "detail::ldlt_factor(M, L, D);");
}

// Lagrange I's multipliers come on top of the form: a four-bar of joints keeps the tree's M and
// f and solves its rhs with the constraints
TEST(DynamicsForm, ConstraintsComeOnTopOfTheForm) {
  Equations e = derive_model("four_bar_linkage");
  ASSERT_TRUE(e.has_multipliers);
  EXPECT_EQ(dynamics_form(e), DynamicsForm::newton_euler);
  std::string header = emit_cpp_header(e);
  EXPECT_NE(header.find("detail::mass_matrix_and_forcing(t, x,"), std::string::npos);
  EXPECT_NE(header.find("lambda"), std::string::npos);
}

// M's entries below the diagonal take the values of those above, never a load from the entries
// just stored in the same straight-line block: g++ 12's SLP vectorizer read such copies before the
// stores (a floating humanoid's M had zeros below its diagonal at -O2)
TEST(DynamicsForm, TheMassMatrixsLowerTriangleIsNotCopiedFromItsUpper) {
  for (const char* model : {"double_pendulum", "spatial_double_pendulum", "four_bar_linkage"}) {
    std::string header = emit_cpp_header(derive_model(model));
    EXPECT_NE(header.find("M[1] = "), std::string::npos) << model;
    EXPECT_FALSE(std::regex_search(header, std::regex(R"(\n  M\[\d+\] = M\[\d+\];)"))) << model;
  }
  std::string header = emit_cpp_header(derive_model("double_pendulum"));
  EXPECT_NE(header.find("M[1] = sym_M1;\n  M[2] = sym_M1;"), std::string::npos) << header.substr(0, 4000);
}

}  // namespace
}  // namespace eomgen::test
