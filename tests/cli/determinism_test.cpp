// The generator is deterministic: the same model gives the same bytes when
// derived twice in one process (where GiNaC's symbols get new serial numbers
// and so a different internal order) and in two processes.
#include <gtest/gtest.h>

#include <filesystem>

#include "emit/cpp_header.hpp"
#include "emit/formats.hpp"
#include "pipeline.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

std::string all_formats(const std::string& model) {
  Equations e = derive_model(model);
  return emit_canonical_text(e) + emit_json(e) + emit_latex(e);
}

TEST(Determinism, SameBytesTwiceInOneProcess) {
  for (const char* model : {"double_pendulum", "heavy_symmetric_top", "n_link_pendulum_4", "gimbal_cardan"}) {
    std::string first = all_formats(model);
    all_formats("watt_governor");  // shifts the serial numbers of every later symbol
    EXPECT_EQ(first, all_formats(model)) << model;
  }
}

// GiNaC's hashes involve addresses, which change from process to process (ASLR), so its internal
// order does: every model's JSON and header derived in this process, which derived the other
// models first, are the committed ones of generated/, which another process wrote on another
// machine; regression.generated_is_in_sync compares three more processes' text, JSON and header
// with them, and says which equations changed when they differ
TEST(Determinism, SameBytesInSeveralProcesses) {
  std::string committed = std::string(EOMGEN_SOURCE_DIR) + "/generated/";
  for (const auto& entry : std::filesystem::directory_iterator(std::string(EOMGEN_SOURCE_DIR) + "/models")) {
    std::string model = entry.path().stem().string();
    Equations here = derive_model(model);
    EXPECT_EQ(read_file(committed + model + ".json"), emit_json(here)) << model << ".json";
    EXPECT_EQ(read_file(committed + model + ".hpp"), emit_cpp_header(here)) << model << ".hpp";
  }
}

}  // namespace
}  // namespace eomgen::test
