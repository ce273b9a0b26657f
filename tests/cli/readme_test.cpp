// The README's opening says what eomgen does now: what the models in models/ already
// use is not listed as still to come.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

// the paragraph of the README's opening that starts with "Still to come", or ""
std::string still_to_come() {
  std::string readme = read_file(std::string(EOMGEN_SOURCE_DIR) + "/README.md");
  std::string opening = readme.substr(0, readme.find("\n## "));
  std::size_t at = opening.find("Still to come");
  if (at == std::string::npos) return "";
  return opening.substr(at, opening.find("\n\n", at) - at);
}

TEST(Readme, WhatTheModelsUseIsNotStillToCome) {
  // a feature, the text of a model file that uses it, and words the README would use for it
  const std::vector<std::tuple<std::string, std::string, std::vector<std::string>>> features = {
      {"frames", "[[frames]]", {"frames"}},
      {"points", "[[points]]", {"points"}},
      {"rolling contact", "rolling", {"rolling"}},
      {"trees of frames turned by products of rotations (read as joints)", "rotation = \"rot_z(a1)*rot_x(b1)\"", {"recursive", "O(n)"}},
      {"joints about any axis", "joint    = { type = \"revolute\"", {"any axis"}},
      {"shapes to animate", "shape    =", {"animation"}},
  };
  std::string later = still_to_come();
  for (const auto& [feature, marker, words] : features) {
    bool used = false;
    for (const auto& file : std::filesystem::directory_iterator(std::string(EOMGEN_SOURCE_DIR) + "/models"))
      used = used || read_file(file.path().string()).find(marker) != std::string::npos;
    ASSERT_TRUE(used) << feature << ": no model uses it any more; update this test";
    for (const std::string& word : words)
      EXPECT_EQ(later.find(word), std::string::npos) << "the README's opening lists " << feature
                                                     << " as still to come, but models/ use it:\n" << later;
  }
}

}  // namespace
}  // namespace eomgen::test
