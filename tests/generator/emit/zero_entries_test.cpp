// An output array's many zero entries become one fill loop at the top, and nothing else changes:
// few zeros stay lines (a small model reads as its matrix), and a loop, a pointer or an entry
// written twice before the last zero keeps them all, since filling first could overwrite a value.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "emit/zero_entries.hpp"

namespace eomgen::test {
namespace {

const char* signature = "void jacobian_input(T t, const T* x, const T* p, T* B)";

// `zeros` entries B[0..) = 0, then B[zeros] = x[0] and a local array's zeros
std::string body(std::size_t zeros, const std::string& before = "") {
  std::string b = "  (void)t; (void)x; (void)p; (void)B;\n  T M[4];\n" + before;
  for (std::size_t i = 0; i < zeros; ++i) b += fmt::format("  B[{}] = T(0);\n", i);
  for (std::size_t i = 0; i < 40; ++i) b += fmt::format("  M[{}] = T(0);\n", i % 4);
  return b + fmt::format("  B[{}] = x[0];\n", zeros);
}

TEST(ZeroEntries, ManyZerosOfAnOutputBecomeOneFillFirst) {
  std::string out = with_zero_fills(signature, body(40));
  EXPECT_EQ(out.find("  (void)t; (void)x; (void)p; (void)B;\n  for (std::size_t i = 0; i < 41; ++i) B[i] = T(0);\n"), 0u) << out;
  EXPECT_EQ(out.find("B[3] = T(0)"), std::string::npos);
  EXPECT_NE(out.find("  B[40] = x[0];\n"), std::string::npos);
  EXPECT_NE(out.find("  M[3] = T(0);\n"), std::string::npos) << "a local array is not the function's output";
}

TEST(ZeroEntries, FewZerosStayTheMatrixTheyAre) {
  EXPECT_EQ(with_zero_fills(signature, body(entries_by_lines_up_to)), body(entries_by_lines_up_to));
}

TEST(ZeroEntries, AWriteBeforeTheZerosKeepsThem) {
  std::string loop = "  for (std::size_t i = 0; i < 3; ++i) B[i] = x[i];\n";
  EXPECT_EQ(with_zero_fills(signature, body(40, loop)), body(40, loop));
  std::string twice = "  B[7] = x[1];\n";
  EXPECT_EQ(with_zero_fills(signature, body(40, twice)), body(40, twice));
}

}  // namespace
}  // namespace eomgen::test
