#include <fmt/format.h>

#include "report/reports.hpp"

namespace eomgen::runtime {

std::string trajectory_csv(const eomgen_model_abi& m, const Trajectory& trajectory) {
  std::string out = "t";
  for (std::size_t i = 0; i < m.num_states; ++i) out += fmt::format(",{}", m.state_names[i]);
  out += ",energy";
  for (std::size_t i = 0; i < m.num_outputs; ++i) out += fmt::format(",{}", m.output_names[i]);
  out += "\n";
  for (std::size_t k = 0; k < trajectory.times.size(); ++k) {
    out += fmt::format("{:.17g}", trajectory.times[k]);
    for (double v : trajectory.states[k]) out += fmt::format(",{:.17g}", v);
    out += fmt::format(",{:.17g}", trajectory.energies[k]);
    for (double v : trajectory.outputs[k]) out += fmt::format(",{:.17g}", v);
    out += "\n";
  }
  return out;
}

}  // namespace eomgen::runtime
