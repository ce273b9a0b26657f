/// @file The states' nominal values of a built FMU binary, for modelDescription.xml: importers
/// that take a state's scale from its `nominal` attribute and never call
/// fmi2GetNominalsOfContinuousStates would otherwise assume 1 (a metre, a radian per second) for
/// a MEMS oscillator of 1e-9 m.
#pragma once

#include <string>
#include <vector>

namespace eomgen::runtime {

/// Loads `library_path`, instantiates it for Model Exchange at its default values and returns
/// fmi2GetNominalsOfContinuousStates for its `states` states (fmu/fmi2_model.hpp's state sizes,
/// 1 where nothing gives one); empty, with `failure` said, where it cannot.
std::vector<double> fmu_state_nominals(const std::string& library_path, const std::string& guid, std::size_t states,
                                       std::string& failure);

}  // namespace eomgen::runtime
