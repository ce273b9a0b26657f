/// @file Inputs that vary in time for `simulate`: `--input 'tau=0.5*sin(2*t)'` (an
/// expression in t and the parameters) and `--input-file u.csv` (a table t, names...,
/// linearly interpolated, its end values held outside its range).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "studies/loaded_problem.hpp"

namespace eomgen::studies {

/// Sets loaded.problem.input_signal from the flags (nothing when both are empty); prints a
/// mistake and returns exit status 2. `table_end` receives the last time of the table.
std::optional<int> set_input_signal(LoadedProblem& loaded, const std::vector<std::string>& expressions,
                                    const std::string& table_file, double& table_end);

}  // namespace eomgen::studies
