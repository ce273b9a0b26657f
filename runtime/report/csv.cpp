#include <fmt/format.h>

#include "report/reports.hpp"

namespace eomgen::runtime {

std::string trajectory_csv_header(const eomgen_model_abi& m) {
  std::string out = "t";
  for (std::size_t i = 0; i < m.num_states; ++i) out += fmt::format(",{}", m.state_names[i]);
  out += ",energy";
  for (std::size_t i = 0; i < m.num_outputs; ++i) out += fmt::format(",{}", m.output_names[i]);
  if (m.num_constraints > 0) {
    for (std::size_t i = 0; i < m.num_multipliers; ++i) out += fmt::format(",{}", m.multiplier_names[i]);
    out += ",position_residual,velocity_residual";
  }
  for (std::size_t i = 0; i < m.num_first_integrals; ++i) out += fmt::format(",I[{}]", m.first_integral_names[i]);
  return out + "\n";
}

std::string trajectory_csv_rows(const eomgen_model_abi& m, const Trajectory& trajectory) {
  std::string out;
  bool constrained = m.num_constraints > 0;
  for (std::size_t k = 0; k < trajectory.times.size(); ++k) {
    out += fmt::format("{:.17g}", trajectory.times[k]);
    for (double v : trajectory.states[k]) out += fmt::format(",{:.17g}", v);
    out += fmt::format(",{:.17g}", trajectory.energies[k]);
    for (double v : trajectory.outputs[k]) out += fmt::format(",{:.17g}", v);
    if (constrained) {
      for (double v : trajectory.multipliers[k]) out += fmt::format(",{:.17g}", v);
      out += fmt::format(",{:.17g},{:.17g}", trajectory.position_residuals[k], trajectory.velocity_residuals[k]);
    }
    for (double v : trajectory.first_integrals[k]) out += fmt::format(",{:.17g}", v);
    out += "\n";
  }
  return out;
}

}  // namespace eomgen::runtime
