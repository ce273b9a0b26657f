#include "analyse/conservation.hpp"

#include <cmath>

namespace eomgen::runtime {

std::vector<FirstIntegralDrift> first_integral_drift(const eomgen_model_abi& m, const Trajectory& tr) {
  std::vector<FirstIntegralDrift> drift;
  if (tr.first_integrals.empty()) return drift;
  for (std::size_t i = 0; i < m.num_first_integrals; ++i) {
    FirstIntegralDrift d;
    d.name = m.first_integral_names[i];
    d.initial = tr.first_integrals.front()[i];
    for (const auto& row : tr.first_integrals)
      d.largest_change = std::isfinite(row[i]) ? std::max(d.largest_change, std::abs(row[i] - d.initial)) : INFINITY;
    d.relative_change = d.initial != 0 ? d.largest_change / std::abs(d.initial) : NAN;
    drift.push_back(d);
  }
  return drift;
}

}  // namespace eomgen::runtime
