/// @file The callbacks CVODE and ARKODE share: the right-hand side and the
/// generated Jacobian, copied from row-major into SUNDIALS' column-major dense matrix.
#pragma once

#include <string>

#include <nvector/nvector_serial.h>
#include <sunmatrix/sunmatrix_dense.h>

namespace eomgen::runtime {

/// `data` is the RightHandSide.
int sundials_rhs(realtype t, N_Vector x, N_Vector xdot, void* data);
/// ARKODE's step post-processing and CVODE's projection: onto the constraints.
int sundials_project_in_place(realtype t, N_Vector x, void* data);
int sundials_projection_correction(realtype t, N_Vector x, N_Vector correction, realtype tolerance, N_Vector error, void* data);
/// The text of a SUNDIALS *GetReturnFlagName result, which the caller must free.
std::string take_flag_name(char* name);

/// A new vector of the run's absolute tolerances, one per state (SimulationSettings::state_atol),
/// shaped like x; null when the run has one for all or the stepper's state is not the model's.
/// The caller destroys it once the integrator has copied it.
N_Vector absolute_tolerances(const struct SimulationSettings& settings, N_Vector x);

int sundials_dense_jacobian(realtype t, N_Vector x, N_Vector fx, SUNMatrix J, void* data, N_Vector, N_Vector, N_Vector);

}  // namespace eomgen::runtime
