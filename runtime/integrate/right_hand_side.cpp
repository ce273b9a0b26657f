#include <cmath>

#include "integrate/stepper.hpp"

namespace eomgen::runtime {

int RightHandSide::operator()(double t, const double* x, double* xdot) {
  ++evaluations_;
  const eomgen_model_abi& m = *p_.model;
  p_.model->rhs_stabilized(t, x, p_.inputs_at(t, inputs_), p_.parameters.data(), alpha_, beta_, xdot);
  for (std::size_t i = 0; i < m.num_states; ++i)
    if (!std::isfinite(xdot[i])) {
      if (!non_finite_) {
        non_finite_ = true;
        non_finite_time_ = t;
        non_finite_state_.assign(x, x + m.num_states);
      }
      return 1;  // recoverable: the solver retries with a smaller step
    }
  return 0;
}

void quiet_sundials_messages(int, const char*, const char*, char*, void*) {}

int RightHandSide::jacobian(double t, const double* x, double* J) {
  const eomgen_model_abi& m = *p_.model;
  m.jacobian_state_stabilized(t, x, p_.inputs_at(t, inputs_), p_.parameters.data(), alpha_, beta_, J);
  for (std::size_t i = 0; i < m.num_states * m.num_states; ++i)
    if (!std::isfinite(J[i])) return 1;
  return 0;
}

}  // namespace eomgen::runtime
