/// @file The sections of `eomgen linear`'s report beyond the spectrum: principal
/// coordinates, controllability and observability, transfer functions, and the
/// §8.1.4 checks, as text and as JSON members.
#pragma once

#include <string>
#include <vector>

#include "studies/linear_report.hpp"

namespace eomgen::studies {

/// The decoupled equations of the principal coordinates, one per line (Hiller §6.3).
std::vector<std::string> principal_equations(const LinearReport& r);

/// Controllability, observability (naming the modes that are lost) and the transfer functions.
void print_reach_text(const eomgen_model_abi& m, const LinearReport& r);

/// The JSON members for the checks, principal coordinates, reach and transfer functions, each after ", ".
std::string reach_json(const eomgen_model_abi& m, const LinearReport& r);

}  // namespace eomgen::studies
