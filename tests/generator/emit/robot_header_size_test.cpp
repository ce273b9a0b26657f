// Issue 38's limit on a robot's header: the 7-joint arm (a Panda's layout, full inertias, armature,
// damping, motors) in at most 200 KB, as tests/benchmarks/tree_benchmark.py measures it (the
// header as `eomgen generate` writes it, 1 KB = 1000 bytes).
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
}

}  // namespace
}  // namespace eomgen::test
