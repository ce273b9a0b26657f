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

TEST(RobotHeaders, TheSevenJointArmsHeaderIsAtMost200KB) {
  Derivation d = derive_model_file(std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/models/seven_joint_arm.toml");
  ASSERT_TRUE(d.equations) << d.diagnostics.format();
  std::size_t bytes = emit_cpp_header(*d.equations).size();
  std::printf("seven_joint_arm.hpp: %zu bytes\n", bytes);
  EXPECT_LE(bytes, 200000u);
  EXPECT_FALSE(d.equations->bodies_gradient_loops);
}

TEST(RobotHeaders, TheTwentyOneJointTreesHeaderIsAtMost600KB) {
  Derivation d = derive_model_file(std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/models/branched_tree.toml");
  ASSERT_TRUE(d.equations) << d.diagnostics.format();
  std::size_t bytes = emit_cpp_header(*d.equations).size();
  std::printf("branched_tree.hpp: %zu bytes\n", bytes);
  EXPECT_LE(bytes, 600000u);
  EXPECT_TRUE(d.equations->bodies_gradient_loops);
}

}  // namespace
}  // namespace eomgen::test
