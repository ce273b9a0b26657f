#include "analyse/conservation.hpp"

#include <cmath>

namespace eomgen::runtime {

std::vector<FirstIntegralDrift> first_integral_drift(const eomgen_model_abi& m, const RunSummary& run) {
  std::vector<FirstIntegralDrift> drift;
  if (run.first_integrals.size() != m.num_first_integrals) return drift;
  for (std::size_t i = 0; i < m.num_first_integrals; ++i) {
    FirstIntegralDrift d;
    d.name = m.first_integral_names[i];
    d.initial = run.first_integrals[i];
    d.largest_change = run.largest_integral_changes[i];
    d.relative_change = d.initial != 0 ? d.largest_change / std::abs(d.initial) : NAN;
    drift.push_back(d);
  }
  return drift;
}

}  // namespace eomgen::runtime
