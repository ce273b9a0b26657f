/// @file Printing the stability analysis of an equilibrium: text or one JSON object.
#pragma once

#include <optional>
#include <string>

#include "analyse/critical_case.hpp"
#include "analyse/equilibrium.hpp"
#include "analyse/linear_stability.hpp"
#include "symbolic_analysis/stability_conditions.hpp"

namespace eomgen::studies {

void print_stability_text(const eomgen_model_abi& m, const runtime::Equilibrium& eq, const runtime::StabilityReport& r,
                          const std::optional<StabilityConditions>& conditions);
/// Lyapunov's critical case, when the first approximation is inconclusive (text only).
void print_critical_case(const runtime::CriticalCase& c);
/// `extra`: further members of the object, each starting with ", ".
void print_stability_json(const eomgen_model_abi& m, const runtime::Equilibrium& eq, const runtime::StabilityReport& r,
                          const std::optional<StabilityConditions>& conditions, const runtime::CriticalCase& critical,
                          const std::string& extra = "");

}  // namespace eomgen::studies
