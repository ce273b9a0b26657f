/// @file What `eomgen ensemble` reads from its flags: --vary NAME=DISTRIBUTION(A,B),
/// --measure KIND(SIGNAL), the signals to record, the quantiles. Mistakes are printed with
/// what the user can write instead.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analyse/ensemble.hpp"
#include "model_abi.h"

namespace eomgen::studies {

/// "m2=normal(1,0.05)", "phi1=uniform(0.4,0.6)", "k=lognormal(0,0.1)": a parameter, an
/// input, a coordinate's initial value or der(q)'s.
std::optional<runtime::Variation> parse_variation(const eomgen_model_abi& m, const std::string& text);

/// "period(phi)", "final(tip_x)", "max(...)", "min(...)", "mean(...)".
std::optional<runtime::Measure> parse_measure(const eomgen_model_abi& m, const std::string& text);

/// The names a trajectory can be recorded by: the states, the outputs and energy.
std::vector<std::string> recordable_signals(const eomgen_model_abi& m);

/// Whether `name` is one of them; prints the mistake when not.
bool check_signal(const eomgen_model_abi& m, const std::string& name, const char* flag);

/// "0.05,0.5,0.95": each in [0, 1].
std::optional<std::vector<double>> parse_probabilities(const std::string& text);

}  // namespace eomgen::studies
