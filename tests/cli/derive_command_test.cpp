// `eomgen derive` on the command line: the equations as eomgen derives them (a tree of joints keeps
// the recursion's quantities), the same written out in q with --written-out, and the refusal of a
// ball joint's quaternion, which is not written out.
#include <gtest/gtest.h>

#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

TEST(DeriveCommand, WrittenOutMultipliesATreeOfJointsOut) {
  const std::string arm = model_path("measured_arm");
  CommandOutput tree = run_eomgen("derive '" + arm + "'");
  ASSERT_EQ(tree.status, 0) << tree.err;
  EXPECT_NE(tree.out.find("# recursive kinematics"), std::string::npos) << tree.out;
  CommandOutput written = run_eomgen("derive --written-out '" + arm + "'");
  ASSERT_EQ(written.status, 0) << written.err;
  EXPECT_EQ(written.out.find("# recursive kinematics"), std::string::npos) << written.out;
  std::size_t m00 = written.out.find("M[0][0] = ");
  ASSERT_NE(m00, std::string::npos) << written.out;
  EXPECT_NE(written.out.substr(m00, written.out.find('\n', m00) - m00).find("cos(q2)"), std::string::npos)
      << "M[0][0] of the arm written out depends on the second joint's angle";
  CommandOutput ball = run_eomgen("derive --written-out '" + model_path("ball_joint_top") + "'");
  EXPECT_EQ(ball.status, 2) << ball.err;
  EXPECT_NE(ball.err.find("--written-out: a ball or free joint's quaternion is not written out in q"), std::string::npos)
      << ball.err;
}

}  // namespace
}  // namespace eomgen::test
