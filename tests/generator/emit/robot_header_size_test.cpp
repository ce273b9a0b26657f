// Issue 38's limits on a robot's header: the 7-joint arm (a Panda's layout, full inertias, armature,
// damping, motors) in at most 200 KB, the 21-joint tree of oblique hinges in at most 600 KB, as
// tests/benchmarks/tree_benchmark.py measures them (the header as `eomgen generate` writes it,
// 1 KB = 1000 bytes). The tree's gradient is loops (spatial/joint_tree_derivatives.hpp), the
// arm's straight-line code.
#include <gtest/gtest.h>

#include "emit/cpp_header.hpp"
#include "pipeline.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

// the header of a robot of tests/crosscheck/models/ within `limit` bytes, its gradient in loops or not
void expect_header_within(const std::string& robot, std::size_t limit, bool loops) {
  Derivation d = derive_model_file(std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/models/" + robot + ".toml");
  ASSERT_TRUE(d.equations) << d.diagnostics.format();
  std::size_t bytes = emit_cpp_header(*d.equations).size();
  std::printf("%s.hpp: %zu bytes\n", robot.c_str(), bytes);
  EXPECT_LE(bytes, limit);
  EXPECT_EQ(d.equations->gradient_loops() != nullptr, loops) << robot;
}

TEST(RobotHeaders, TheSevenJointArmsHeaderIsAtMost200KB) { expect_header_within("seven_joint_arm", 200000, false); }

TEST(RobotHeaders, TheTwentyOneJointTreesHeaderIsAtMost600KB) { expect_header_within("branched_tree", 600000, true); }

}  // namespace
}  // namespace eomgen::test
