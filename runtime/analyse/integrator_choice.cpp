#include "analyse/integrator_choice.hpp"

#include <cmath>

#include <fmt/format.h>

#include "analyse/work_precision.hpp"

namespace eomgen::runtime {

IntegratorChoice choose_integrator(const Problem& problem, const std::vector<double>& x0, double t0) {
  const eomgen_model_abi& m = *problem.model;
  if (m.num_constraints)
    return {"cvode-bdf", fmt::format("the model has constraints ({}): BDF with projection onto them after every step",
                                     m.num_multipliers ? "Lagrange I" : "Appell's equations")};
  double ratio = stiffness_ratio(problem, x0, t0);
  if (ratio > 1e3)
    return {"cvode-bdf", fmt::format("the model is stiff (fastest decay rate {:.2g} times its slowest rate at the start): "
                                     "an implicit method is not limited by stability", ratio)};
  bool conservative = m.conserves_energy_without_inputs;
  return {"arkode-dp5", fmt::format("the model is not stiff{}: an explicit method of order 5 (Dormand–Prince) is more "
                                    "accurate per evaluation than BDF{}",
                                    std::isfinite(ratio) ? "" : " as far as its Jacobian at the start shows",
                                    conservative ? " and keeps the energy error of this conservative model small" : "")};
}

}  // namespace eomgen::runtime
