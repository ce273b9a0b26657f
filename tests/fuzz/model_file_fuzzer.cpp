// libFuzzer target over the whole front end: model-file text → parse → build → derive →
// emit the header. A crash, a sanitizer report or an exception that escapes is a finding;
// a located diagnostic is the expected answer to a broken file. Small models only, so
// that each input runs in milliseconds and the fuzzer reaches the derivation often.
//
//   cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DEOMGEN_FUZZ=ON
//   cmake --build build-fuzz --target model_file_fuzzer
//   build-fuzz/tests/model_file_fuzzer -dict=tests/fuzz/model_file.dict -max_len=4096 \
//       -timeout=10 -max_total_time=600 corpus tests/fuzz/seeds
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/deadline.hpp"
#include "emit/cpp_header.hpp"
#include "pipeline.hpp"

namespace {

// a rough bound on the model's size before deriving it: more sections, longer derivations
bool small_enough(const std::string& text) {
  std::size_t bodies = 0;
  for (std::size_t at = text.find("[["); at != std::string::npos; at = text.find("[[", at + 2)) ++bodies;
  return bodies <= 6 && text.size() <= 4096;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // libFuzzer's -timeout and -rss_limit_mb find slow and swelling inputs; the watchdog would end the fuzzer itself
  eomgen::set_derivation_time_limit(0);
  eomgen::set_derivation_memory_limit(0);
  std::string text(reinterpret_cast<const char*>(data), size);
  if (!small_enough(text)) return -1;  // not added to the corpus
  eomgen::Derivation d = eomgen::derive_model_text(text, "fuzz.toml");
  if (!d.diagnostics.empty()) {
    (void)d.diagnostics.format();
    return 0;
  }
  (void)eomgen::emit_cpp_header(*d.equations);
  return 0;
}
