/// @file `eomgen stability --at p_q=VALUE`: a steady motion with the momentum of a
/// cyclic coordinate given is analysed on Routh's reduced system (Hiller §3.8.4),
/// where it is an equilibrium of the remaining coordinates.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "studies/loaded_problem.hpp"

namespace eomgen::studies {

struct RouthRequest {
  std::vector<std::string> eliminated;     // the cyclic coordinates whose momenta are given
  std::vector<std::string> momentum_sets;  // p_q=VALUE, as --set of the reduced model
  std::vector<std::string> at;             // the other --at values
};

/// Splits --at into momenta p_q of coordinates q whose momentum is not part of the state
/// and everything else; `eliminated` is empty when there are none.
RouthRequest routh_request(const eomgen_model_abi& full_model, const std::vector<std::string>& at);

/// Loads the reduced model for `request` with `sets` applied; returns an exit status on failure.
std::optional<int> load_reduced_problem(const std::string& model, const std::vector<std::string>& sets,
                                        const RouthRequest& request, LoadedProblem& out);

/// One paragraph (text) or one JSON member ("routh": {...}) naming what was eliminated.
std::string routh_text(const Equations& reduced, const RouthRequest& request);
std::string routh_json(const Equations& reduced, const RouthRequest& request);

}  // namespace eomgen::studies
