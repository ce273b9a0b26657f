/// @file modelDescription.xml of an FMU (FMI 2.0, chapter 2.2): the model's states, their
/// derivatives, parameters, inputs and outputs as ScalarVariables, and the ModelStructure
/// with each derivative's and output's dependencies on the states and inputs, read from which
/// symbols the equations contain. Value references follow fmu/fmi2_model.hpp: the states x
/// (0 … S−1), their derivatives x' (S … 2S−1), the parameters, the inputs, the outputs.
#pragma once

#include <string>
#include <vector>

#include "derive/equations.hpp"

namespace eomgen {

struct FmuKinds {
  bool model_exchange = true, co_simulation = true;
};

/// A GUID from the header's text (FNV-1a), so the same model gives the same FMU.
std::string fmu_guid(const std::string& header_text);

/// The XML; `version` names the generation tool; `nominals`, one per state or none, the states'
/// `nominal` attributes (fmu/fmu_nominals.hpp), written to three digits: a scale, and the same
/// text wherever the binary's last bits differ.
std::string fmi2_model_description(const Equations& equations, const std::string& guid, FmuKinds kinds,
                                   const std::string& version, const std::vector<double>& nominals);

}  // namespace eomgen
