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

// GiNaC's hashes involve addresses, which change from process to process (ASLR),
// so its internal order does; every model is derived in two processes for each output and
// once more in this one (and regression.generated_is_in_sync compares a fourth process's
// header with the committed one, written on another machine).
TEST(Determinism, SameBytesInSeveralProcesses) {
  std::string scratch = temporary_directory();
  for (const auto& entry : std::filesystem::directory_iterator(std::string(EOMGEN_SOURCE_DIR) + "/models")) {
    std::string model = entry.path().stem().string();
    std::string first;
    for (int run = 0; run < 2; ++run) {
      std::string out = scratch + "/" + model + std::to_string(run) + ".json";
      ASSERT_EQ(run_command("'" + std::string(EOMGEN_EXECUTABLE) + "' derive '" + entry.path().string() +
                            "' --format json -o '" + out + "' 2>/dev/null"),
                0);
      if (run == 0) first = read_file(out);
      else EXPECT_EQ(first, read_file(out)) << model << " run " << run;
    }
    // and this process, which derived other models first, agrees with a fresh one
    EXPECT_EQ(first, emit_json(derive_model(model))) << model;
    std::string header;
    for (int run = 0; run < 2; ++run) {
      std::string dir = scratch + "/" + model + "_h" + std::to_string(run);
      ASSERT_EQ(run_command("'" + std::string(EOMGEN_EXECUTABLE) + "' generate '" + entry.path().string() + "' -o '" +
                            dir + "' 2>/dev/null"),
                0);
      if (run == 0) header = read_file(dir + "/" + model + ".hpp");
      else EXPECT_EQ(header, read_file(dir + "/" + model + ".hpp")) << model << ".hpp run " << run;
    }
    EXPECT_EQ(header, emit_cpp_header(derive_model(model))) << model << ".hpp";
  }
}

}  // namespace
}  // namespace eomgen::test
