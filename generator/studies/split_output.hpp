/// @file Writing `eomgen generate --split`'s files next to the header: all of them or none, and the
/// units of an earlier split that the new one no longer has removed (only files eomgen wrote).
#pragma once

#include <string>
#include <vector>

#include "emit/split_units.hpp"

namespace eomgen::studies {

/// Writes `files` into `folder`; on a failure removes those it wrote and returns what went wrong.
/// Then removes NAME_split.hpp and NAME_*.cpp files of an earlier split of `model_name` that are not
/// among `files` (recognized by the line eomgen writes into them and their #include of `header_name`).
/// Empty on success.
std::string write_split_files(const std::string& folder, const std::string& model_name, const std::string& header_name,
                              const std::vector<GeneratedFile>& files);

}  // namespace eomgen::studies
