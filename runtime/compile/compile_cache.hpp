/// @file Compile on demand: a generated header becomes a shared object built
/// with the C++ compiler recorded at configure time, cached by content hash.
#pragma once

#include <memory>
#include <string>

#include "model_abi.h"
#include "simulation.hpp"

namespace eomgen::runtime {

/// A model loaded from a shared object; unloads it when destroyed.
class LoadedModel {
 public:
  LoadedModel(void* library, const eomgen_model_abi* abi, std::string path, bool compiled_now)
      : library_(library), abi_(abi), path_(std::move(path)), compiled_now_(compiled_now) {}
  ~LoadedModel();
  LoadedModel(const LoadedModel&) = delete;
  LoadedModel& operator=(const LoadedModel&) = delete;

  const eomgen_model_abi* abi() const { return abi_; }
  /// The model's reference integrator in a wide scalar (see reference/reference_solution.hpp).
  ReferenceFunction reference = nullptr;
  std::string reference_scalar;
  const std::string& path() const { return path_; }
  bool compiled_now() const { return compiled_now_; }

 private:
  void* library_;
  const eomgen_model_abi* abi_;
  std::string path_;
  bool compiled_now_;
};

/// The C++ compiler for generated code: $EOMGEN_CXX, else the one eomgen was built with.
std::string cxx_compiler();

/// The cache folder: $EOMGEN_CACHE_DIR, else $XDG_CACHE_HOME/eomgen, else ~/.cache/eomgen.
std::string cache_directory();

/// Finds the shared object for this header in the cache, or builds it (atomically:
/// concurrent runs are safe, and a corrupt entry is rebuilt rather than loaded),
/// then loads it, compiling with $EOMGEN_CXX when set, else the compiler found at
/// configure time. On failure returns null and says why in `error`; `compiler_missing`
/// tells a missing compiler (the machine's set-up) from one that failed (a bug).
std::unique_ptr<LoadedModel> load_compiled_model(const std::string& header_text, const std::string& model_name,
                                                 std::string& error, bool* compiler_missing = nullptr);

}  // namespace eomgen::runtime
