/// @file The charts of `eomgen linear --plot FILE.png`: the mode shapes (each mode's
/// mass-normalized shape by coordinate) and a Bode chart per --bode pair.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "studies/linear_report.hpp"

namespace eomgen::studies {

/// Draws FILE_modes.png (when the report has modes) and FILE_bode_U_Y.png for each pair
/// in `bode` (a transfer function of the report); says on standard error what was drawn.
void draw_linear_charts(const eomgen_model_abi& m, const LinearReport& r, const std::string& png,
                        const std::vector<std::pair<std::string, std::string>>& bode);

}  // namespace eomgen::studies
