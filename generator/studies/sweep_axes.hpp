/// @file The swept parameters of `eomgen sweep` (NAME=LOW:HIGH:COUNT[:log]) and the symbolic
/// stability margin drawn over its map.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analyse/stability_map.hpp"
#include "studies/loaded_problem.hpp"

namespace eomgen::studies {

/// "NAME=LOW:HIGH:COUNT" read against the model's parameters: every character of each
/// field, 2 <= COUNT <= 100000, LOW < HIGH; with ":log" after COUNT, points a constant ratio
/// apart (0 < LOW). Prints the mistake and returns nothing when wrong; `name` gets the
/// parameter's name.
std::optional<runtime::SweepAxis> parse_axis(const eomgen_model_abi& m, const std::string& text, std::string& name);

/// At each point of the map: the smallest of the symbolic Hurwitz conditions in the two swept
/// parameters (> 0 where all hold; 0 everywhere when one vanishes identically: at best marginal).
/// `state` is the equilibrium used where the map has none of its own.
std::vector<double> symbolic_margin(const LoadedProblem& loaded, const runtime::StabilityMap& map,
                                    const std::string& x_name, const std::string& y_name, const std::vector<double>& state);

}  // namespace eomgen::studies
