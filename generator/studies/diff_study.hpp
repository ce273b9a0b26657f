/// @file `eomgen diff OLD NEW`: the derived equations of two versions of a model (model
/// files or derived-equations JSON) compared entry by entry; and `--self OLD_EOMGEN`,
/// what another eomgen executable derives from the same models against this one.
#pragma once

#include <vector>

#include "compare/diff_report.hpp"

namespace eomgen::studies {

struct ComparisonOptions {
  std::vector<std::string> inputs, renames;
  std::string self;
  DiffOptions options;
  bool json = false;
  bool region_is_enough = false;  // --region
};

/// Exit status like diff and cmp: 0 the same, 1 different, 2 a mistake in an input,
/// 4 an internal error (1 is taken by "different").
int diff(ComparisonOptions options);

}  // namespace eomgen::studies
