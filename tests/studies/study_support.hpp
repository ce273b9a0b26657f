/// @file Running a study (generator/studies/) in the test process: what it prints on
/// standard output and error is captured, its models are compiled into the tests'
/// shared compile cache, and no executable is started.
#pragma once

#include <cstdlib>
#include <fstream>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "studies/exit_status.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {

struct StudyOutput {
  int status;
  std::string out, err;
};

/// Calls `study` with stdout and stderr captured; returns its exit status and what it printed.
inline StudyOutput run_study(const std::function<int()>& study) {
  ::setenv("EOMGEN_CACHE_DIR", EOMGEN_BINARY_DIR "/test-cache", 1);
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  int status = study();
  std::string out = ::testing::internal::GetCapturedStdout();
  std::string err = ::testing::internal::GetCapturedStderr();
  return {status, out, err};
}

/// Writes a model file into a fresh folder; its path.
inline std::string write_study_model(const std::string& name, const std::string& text) {
  std::string path = temporary_directory() + "/" + name + ".toml";
  std::ofstream(path) << text;
  return path;
}

}  // namespace eomgen::test
