#include "integrate/sundials_callbacks.hpp"

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "integrate/stepper.hpp"

namespace eomgen::runtime {

std::string take_flag_name(char* name) {
  std::string text = name ? name : "an unknown flag";
  std::free(name);
  return text;
}

N_Vector absolute_tolerances(const SimulationSettings& settings, N_Vector x) {
  if (settings.state_atol.empty() || settings.state_atol.size() != static_cast<std::size_t>(N_VGetLength(x))) return nullptr;
  N_Vector each = N_VClone(x);
  std::copy(settings.state_atol.begin(), settings.state_atol.end(), N_VGetArrayPointer(each));
  return each;
}

int sundials_rhs(realtype t, N_Vector x, N_Vector xdot, void* data) {
  return (*static_cast<RightHandSide*>(data))(t, N_VGetArrayPointer(x), N_VGetArrayPointer(xdot));
}

int sundials_project_in_place(realtype t, N_Vector x, void* data) {
  auto& f = *static_cast<RightHandSide*>(data);
  return f.projection && !f.projection->project(t, N_VGetArrayPointer(x)) ? 1 : 0;
}

int sundials_projection_correction(realtype t, N_Vector x, N_Vector correction, realtype, N_Vector, void* data) {
  auto& f = *static_cast<RightHandSide*>(data);
  const double* now = N_VGetArrayPointer(x);
  std::vector<double> projected(now, now + f.size());
  if (!f.projection->project(t, projected.data())) return 1;  // recoverable: CVODE retries with a smaller step
  double* c = N_VGetArrayPointer(correction);
  for (std::size_t i = 0; i < f.size(); ++i) c[i] = projected[i] - now[i];
  return 0;
}

int sundials_dense_jacobian(realtype t, N_Vector x, N_Vector, SUNMatrix J, void* data, N_Vector, N_Vector, N_Vector) {
  auto& f = *static_cast<RightHandSide*>(data);
  std::vector<double> rows(f.size() * f.size());
  if (int status = f.jacobian(t, N_VGetArrayPointer(x), rows.data())) return status;
  for (std::size_t i = 0; i < f.size(); ++i)
    for (std::size_t j = 0; j < f.size(); ++j) SM_ELEMENT_D(J, i, j) = rows[i * f.size() + j];
  return 0;
}

}  // namespace eomgen::runtime
