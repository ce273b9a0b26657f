/// @file The binary of an FMU (FMI 2.0): the generated header compiled with the fmi2
/// functions of fmu/fmi2_model.hpp into one shared object, linked with SUNDIALS' CVODE
/// when it is for Co-Simulation (a Model Exchange binary needs no SUNDIALS).
#pragma once

#include <string>

namespace eomgen::runtime {

/// Compiles `header_text` (the model `name`) into `library_path`; `guid` must match the
/// modelDescription.xml's; `co_simulation`: with CVODE and fmi2DoStep. Returns what went wrong
/// (the compiler's first lines), or empty.
std::string build_fmu_binary(const std::string& header_text, const std::string& name, const std::string& guid,
                             const std::string& library_path, bool co_simulation);

}  // namespace eomgen::runtime
