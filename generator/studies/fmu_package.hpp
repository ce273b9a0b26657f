/// @file An FMU (FMI 2.0) of derived equations: modelDescription.xml (emit/fmu_description),
/// the binary (runtime/fmu/fmu_binary) at binaries/linux64/NAME.so, zipped into NAME.fmu.
#pragma once

#include <string>

#include "derive/equations.hpp"
#include "emit/fmu_description.hpp"

namespace eomgen::studies {

/// Writes DIRECTORY/NAME.fmu whole or not at all; returns what went wrong, or empty.
/// Lagrange I models are refused: their multipliers need the solver of `simulate`.
std::string write_fmu(const Equations& equations, const std::string& directory, FmuKinds kinds, std::string& path);

}  // namespace eomgen::studies
