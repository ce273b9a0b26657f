/// @file The answer of `eomgen scene`: text and JSON on standard output, and with -o DIR
/// report.md, candidates.csv, error_vs_work.png, the chosen model's header and chosen.csv.
#pragma once

#include <string>

#include "studies/scene_analysis.hpp"

namespace eomgen::studies {

void print_scene_text(const SceneAnalysis& a);
void print_scene_json(const SceneAnalysis& a);

/// Writes the files into `directory`; returns what failed, or empty.
std::string write_scene_files(const SceneAnalysis& a, const std::string& directory);

}  // namespace eomgen::studies
