// `eomgen derive` on the command line: the equations as eomgen derives them (a tree of joints keeps
// the recursion's quantities), the same written out in q with --written-out, and the refusal of a
// ball joint's quaternion, which is not written out; and the equations written into /dev/null by
// a user who cannot write /dev itself.
#include <gtest/gtest.h>

#include <filesystem>

#include <unistd.h>

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

// -o /dev/null is a device that any user may write: its folder's permissions do not matter
TEST(DeriveCommand, AnyUserWritesIntoDevNull) {
  if (::geteuid() != 0 || run_command("command -v setpriv > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "needs root and setpriv(1) to run eomgen as the user nobody";
  namespace fs = std::filesystem;
  std::string folder = temporary_directory(), model = folder + "/pendulum.toml";
  fs::copy_file(model_path("pendulum"), model);
  fs::permissions(folder, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec | fs::perms::others_read |
                              fs::perms::others_exec);
  std::string as_nobody = "setpriv --reuid=65534 --regid=65534 --clear-groups '" + std::string(EOMGEN_EXECUTABLE) + "' ";
  if (run_command(as_nobody + "--version > /dev/null 2>&1") != 0) GTEST_SKIP() << "the user nobody cannot run eomgen here";
  std::string err = folder + "/err.txt";
  EXPECT_EQ(run_command(as_nobody + "derive '" + model + "' -o /dev/null 2> '" + err + "'"), 0) << read_file(err);
  EXPECT_EQ(read_file(err).find("is not writable"), std::string::npos) << read_file(err);
  EXPECT_TRUE(fs::is_character_file("/dev/null")) << "written into, not replaced";
}

}  // namespace
}  // namespace eomgen::test
