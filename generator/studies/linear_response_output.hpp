/// @file `eomgen linear --response`: the response of the linearized system to an
/// initial deviation, a unit impulse, a unit step or sin(ωt) in one input, written as
/// CSV (deviations from the equilibrium) and charted.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "studies/linear_report.hpp"

namespace eomgen::studies {

struct ResponseOptions {
  std::string response;               // initial | impulse:U | step:U | harmonic:U:OMEGA; empty: none
  std::string input;                  // or NAME=EXPR: A*step(T0), A*impulse(T0), A*sin(W*t), A*cos(W*t)
  std::vector<std::string> initials;  // NAME=VALUE deviations
  double t_end = 10, dt_out = 0.01;
  bool t_end_given = false, dt_out_given = false;  // without them, a warning where the defaults miss the motion
  std::string csv, plot;
};

/// Whether a response is asked for (--response or --input).
inline bool wants_response(const ResponseOptions& o) { return !o.response.empty() || !o.input.empty(); }

/// Computes and writes the response asked for; prints mistakes and returns their exit status.
std::optional<int> write_linear_response(const eomgen_model_abi& m, const LinearReport& r, const ResponseOptions& o);

}  // namespace eomgen::studies
