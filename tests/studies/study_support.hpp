/// @file Running a study (generator/studies/) in the test process: what it prints on
/// standard output and error is captured, its models are compiled into the tests'
/// shared compile cache, and no executable is started.
#pragma once

#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "studies/exit_status.hpp"
#include "studies/loaded_problem.hpp"
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

/// The model file at `path` loaded as the commands load it (with `sets` applied); a failure fails the test.
inline studies::LoadedProblem load(const std::string& path, const std::vector<std::string>& sets = {}) {
  studies::LoadedProblem loaded;
  StudyOutput r = run_study([&] { return studies::load_problem(path, sets, loaded).value_or(studies::exit_success); });
  EXPECT_EQ(r.status, studies::exit_success) << r.err;
  return loaded;
}

}  // namespace eomgen::test
