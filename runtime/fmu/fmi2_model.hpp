// The FMI 2.0 functions of an eomgen FMU, over the generated header of the model named by
// EOMGEN_FMU_MODEL (included after that header). Value references, as modelDescription.xml
// lists them: the states x = [q; q'] first (0 … S−1), then their derivatives x' (S … 2S−1),
// the parameters, the inputs and the outputs. Model Exchange hands x' to the importer's
// integrator; Co-Simulation steps with CVODE (BDF, the analytic Jacobian, rtol from
// fmi2SetupExperiment or 1e-8, absolute tolerances in each state's size, restarted when a
// state, a parameter or an input is set from outside, and otherwise continued across
// communication points; the quaternions of ball and free joints projected back to unit length
// after every step and at every communication point). There are no events, integers, booleans or
// strings.
// CVODE is compiled in only for Co-Simulation (EOMGEN_FMU_CO_SIMULATION): a Model Exchange FMU
// needs no SUNDIALS on the importer's machine.
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <new>
#include <string>

#ifdef EOMGEN_FMU_CO_SIMULATION
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#endif

#include "fmi2.h"

namespace eomgen::fmu {

namespace model = eomgen::models::EOMGEN_FMU_MODEL;
constexpr std::size_t S = model::num_states, P = model::num_parameters, U = model::num_inputs, Y = model::num_outputs;
constexpr std::size_t derivatives_from = S, parameters_from = 2 * S, inputs_from = parameters_from + P,
                      outputs_from = inputs_from + U, references = outputs_from + Y;

struct Instance {
  std::string name;
  fmi2Type kind = fmi2ModelExchange;
  fmi2CallbackLogger logger = nullptr;
  fmi2ComponentEnvironment environment = nullptr;
  double t = 0, tolerance = 1e-8;
  std::array<double, S> x = model::default_state;
  std::array<double, P> p = model::default_parameters;
  std::array<double, U> u = model::default_inputs;
  bool cvode_current = false;  // false after a change of x, p or u from outside
#ifdef EOMGEN_FMU_CO_SIMULATION
  // Co-Simulation: CVODE, made at the first step and after a change of x or p from outside
  SUNContext context = nullptr;
  void* cvode = nullptr;
  N_Vector y = nullptr;
  SUNMatrix matrix = nullptr;
  SUNLinearSolver solver = nullptr;
#endif

  void error(const std::string& message) const {
    if (logger) logger(environment, name.c_str(), fmi2Error, "error", "%s", message.c_str());
  }
  const double* inputs() const { return U ? u.data() : nullptr; }
#ifdef EOMGEN_FMU_CO_SIMULATION
  void free_cvode() {
    if (cvode) CVodeFree(&cvode);
    if (solver) SUNLinSolFree(solver);
    if (matrix) SUNMatDestroy(matrix);
    if (y) N_VDestroy(y);
    if (context) SUNContext_Free(&context);
    cvode = nullptr, solver = nullptr, matrix = nullptr, y = nullptr, context = nullptr, cvode_current = false;
  }
#else
  void free_cvode() {}
#endif
};

Instance* as_instance(fmi2Component c) { return static_cast<Instance*>(c); }

// Each state's size, as `simulate` takes it for its absolute tolerances (its value, or its
// default where that is zero), but for a velocity der(q_k) with q_k's own rate at this state,
// √|∂q''_k/∂q_k| + |∂q''_k/∂q'_k|, where `simulate` balances the whole Jacobian: at least q_k's
// size times that (an oscillator of amplitude a and frequency ω has speeds of a ω). 0 where
// nothing says. Without it, a MEMS oscillator of 1e-9 m had an
// absolute tolerance of 1e-10 m in Co-Simulation, and a nominal of 1 m in Model Exchange.
std::array<double, S> state_sizes(const Instance& in) {
  std::array<double, S> size{};
  for (std::size_t i = 0; i < S; ++i) {
    double value = std::abs(in.x[i]), usual = std::abs(model::default_state[i]);
    size[i] = std::isfinite(value) && value > 0 ? value : std::isfinite(usual) ? usual : 0.0;
  }
  constexpr std::size_t nq = model::num_coordinates;
  if constexpr (nq == model::num_velocities && nq > 0) {
    std::array<double, S * S> J;
    model::jacobian_state(in.t, in.x.data(), in.inputs(), in.p.data(), J.data());
    for (std::size_t k = 0; k < nq; ++k) {
      if (std::string(model::velocity_names[k]) != "der(" + std::string(model::coordinate_names[k]) + ")") continue;
      double rate = std::sqrt(std::abs(J[(nq + k) * S + k])) + std::abs(J[(nq + k) * S + nq + k]);
      if (std::isfinite(rate)) size[nq + k] = std::max(size[nq + k], rate * size[k]);
    }
  }
  return size;
}

// The quaternions of ball and free joints divided by their lengths: the rotation is that of q/|q|,
// so this changes no motion, and an importer reads unit quaternions. False where one has length
// zero (or is not finite).
bool normalize_quaternions(double* x) {
  if constexpr (model::num_quaternions > 0) {
    for (std::size_t k = 0; k < model::num_quaternions; ++k) {
      const std::size_t* q = model::quaternion_coordinates.data() + 4 * k;
      double length = std::sqrt(x[q[0]] * x[q[0]] + x[q[1]] * x[q[1]] + x[q[2]] * x[q[2]] + x[q[3]] * x[q[3]]);
      if (!(length > 0) || !std::isfinite(length)) return false;
      for (std::size_t j = 0; j < 4; ++j) x[q[j]] /= length;
    }
  }
  (void)x;
  return true;
}

#ifdef EOMGEN_FMU_CO_SIMULATION
// CVODE's projection after every step (BDF): the quaternions back onto the unit sphere, as
// `eomgen simulate` keeps them; without it a tumbling body's |q| drifted by 6e-6 over 1000 s
extern "C" int cvode_projection(sunrealtype, N_Vector y, N_Vector correction, sunrealtype, N_Vector, void*) {
  const double* now = N_VGetArrayPointer(y);
  std::array<double, S> projected;
  std::copy(now, now + S, projected.begin());
  if (!normalize_quaternions(projected.data())) return -1;
  for (std::size_t i = 0; i < S; ++i) N_VGetArrayPointer(correction)[i] = projected[i] - now[i];
  return 0;
}

extern "C" int cvode_rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* data) {
  const Instance& in = *static_cast<const Instance*>(data);
  model::rhs(t, N_VGetArrayPointer(y), in.inputs(), in.p.data(), N_VGetArrayPointer(ydot));
  for (std::size_t k = 0; k < S; ++k)
    if (!std::isfinite(N_VGetArrayPointer(ydot)[k])) return 1;
  return 0;
}

extern "C" int cvode_jacobian(sunrealtype t, N_Vector y, N_Vector, SUNMatrix J, void* data, N_Vector, N_Vector, N_Vector) {
  const Instance& in = *static_cast<const Instance*>(data);
  std::array<double, S * S> row_major;
  model::jacobian_state(t, N_VGetArrayPointer(y), in.inputs(), in.p.data(), row_major.data());
  for (std::size_t i = 0; i < S; ++i)
    for (std::size_t j = 0; j < S; ++j) SM_ELEMENT_D(J, sunindextype(i), sunindextype(j)) = row_major[i * S + j];
  return 0;
}

extern "C" void cvode_quiet(int, const char*, const char*, char*, void*) {}

bool start_cvode(Instance& in) {
  in.free_cvode();
  if (!normalize_quaternions(in.x.data())) return false;
  if (SUNContext_Create(nullptr, &in.context) != 0) return false;
  in.y = N_VNew_Serial(sunindextype(S), in.context);
  std::memcpy(N_VGetArrayPointer(in.y), in.x.data(), S * sizeof(double));
  in.cvode = CVodeCreate(CV_BDF, in.context);
  if (!in.cvode || CVodeInit(in.cvode, cvode_rhs, in.t, in.y) != 0) return false;
  // 1e-2 rtol in each state's size, and 1e-2 rtol where it has none or is larger than one
  std::array<double, S> size = state_sizes(in);
  N_Vector absolute = N_VNew_Serial(sunindextype(S), in.context);
  for (std::size_t i = 0; i < S; ++i)
    N_VGetArrayPointer(absolute)[i] = in.tolerance * 1e-2 * (size[i] > 0 ? std::min(1.0, size[i]) : 1.0);
  CVodeSVtolerances(in.cvode, in.tolerance, absolute);
  N_VDestroy(absolute);
  CVodeSetUserData(in.cvode, &in);
  CVodeSetErrHandlerFn(in.cvode, cvode_quiet, nullptr);
  CVodeSetMaxNumSteps(in.cvode, 1000000);
  in.matrix = SUNDenseMatrix(sunindextype(S), sunindextype(S), in.context);
  in.solver = SUNLinSol_Dense(in.y, in.matrix, in.context);
  CVodeSetLinearSolver(in.cvode, in.solver, in.matrix);
  CVodeSetJacFn(in.cvode, cvode_jacobian);
  if (model::num_quaternions > 0 && CVodeSetProjFn(in.cvode, cvode_projection) != CV_SUCCESS) return false;
  in.cvode_current = true;
  return true;
}
#endif

fmi2Status get_real(const Instance& in, fmi2ValueReference r, double& value) {
  if (r < derivatives_from) value = in.x[r];
  else if (r < parameters_from) {
    std::array<double, S> xdot;
    model::rhs(in.t, in.x.data(), in.inputs(), in.p.data(), xdot.data());
    value = xdot[r - derivatives_from];
  } else if (r < inputs_from) value = in.p[r - parameters_from];
  else if (r < outputs_from) value = in.u[r - inputs_from];
  else if (r < references) {
    std::array<double, Y> y;
    model::outputs(in.t, in.x.data(), in.inputs(), in.p.data(), y.data());
    value = y[r - outputs_from];
  } else {
    in.error("no variable has value reference " + std::to_string(r));
    return fmi2Error;
  }
  return fmi2OK;
}

fmi2Status set_real(Instance& in, fmi2ValueReference r, double value) {
  if (r < derivatives_from) in.x[r] = value, in.cvode_current = false;
  else if (r >= parameters_from && r < inputs_from) in.p[r - parameters_from] = value, in.cvode_current = false;
  else if (r >= inputs_from && r < outputs_from) {
    // a new input value is a jump of the right-hand side: CVODE starts afresh at the next step
    if (in.u[r - inputs_from] != value) in.cvode_current = false;
    in.u[r - inputs_from] = value;
  }
  else {
    in.error("value reference " + std::to_string(r) + " cannot be set (a derivative, an output, or none)");
    return fmi2Error;
  }
  return fmi2OK;
}

// d(unknown)/d(known) · dv by a complex step through the generated functions (exact to rounding):
// the direction in the states, parameters and inputs enters as their imaginary parts
fmi2Status directional_derivative(const Instance& in, const fmi2ValueReference* unknowns, std::size_t n_unknowns,
                                  const fmi2ValueReference* knowns, std::size_t n_knowns, const double* dv, double* out) {
  using C = std::complex<double>;
  const double h = 1e-30;
  std::array<C, S> x;
  std::array<C, P> p;
  std::array<C, U> u;
  for (std::size_t k = 0; k < S; ++k) x[k] = in.x[k];
  for (std::size_t k = 0; k < P; ++k) p[k] = in.p[k];
  for (std::size_t k = 0; k < U; ++k) u[k] = in.u[k];
  for (std::size_t k = 0; k < n_knowns; ++k) {
    fmi2ValueReference r = knowns[k];
    if (r < derivatives_from) x[r] += C(0, h * dv[k]);
    else if (r >= parameters_from && r < inputs_from) p[r - parameters_from] += C(0, h * dv[k]);
    else if (r >= inputs_from && r < outputs_from) u[r - inputs_from] += C(0, h * dv[k]);
    else {
      in.error("value reference " + std::to_string(r) + " is not a state, a parameter or an input");
      return fmi2Error;
    }
  }
  std::array<C, S> xdot;
  std::array<C, Y> y;
  model::rhs(C(in.t), x.data(), U ? u.data() : nullptr, p.data(), xdot.data());
  model::outputs(C(in.t), x.data(), U ? u.data() : nullptr, p.data(), y.data());
  for (std::size_t k = 0; k < n_unknowns; ++k) {
    fmi2ValueReference r = unknowns[k];
    if (r >= derivatives_from && r < parameters_from) out[k] = xdot[r - derivatives_from].imag() / h;
    else if (r >= outputs_from && r < references) out[k] = y[r - outputs_from].imag() / h;
    else {
      in.error("no directional derivative of value reference " + std::to_string(r) + ": not a derivative or an output");
      return fmi2Error;
    }
  }
  return fmi2OK;
}

}  // namespace eomgen::fmu

using namespace eomgen::fmu;

extern "C" {

const char* fmi2GetTypesPlatform(void) { return "default"; }
const char* fmi2GetVersion(void) { return "2.0"; }
fmi2Status fmi2SetDebugLogging(fmi2Component, fmi2Boolean, size_t, const fmi2String[]) { return fmi2OK; }

fmi2Component fmi2Instantiate(fmi2String name, fmi2Type kind, fmi2String guid, fmi2String, const fmi2CallbackFunctions* functions,
                              fmi2Boolean, fmi2Boolean) {
  if (!guid || std::strcmp(guid, EOMGEN_FMU_GUID) != 0) {
    if (functions && functions->logger)
      functions->logger(functions->componentEnvironment, name, fmi2Error, "error",
                        "the GUID %s is not this FMU's (%s): modelDescription.xml and the binary differ", guid ? guid : "(none)",
                        EOMGEN_FMU_GUID);
    return nullptr;
  }
#ifndef EOMGEN_FMU_CO_SIMULATION
  if (kind == fmi2CoSimulation) {
    if (functions && functions->logger)
      functions->logger(functions->componentEnvironment, name, fmi2Error, "error",
                        "this FMU is for Model Exchange only: it was built without Co-Simulation's solver");
    return nullptr;
  }
#endif
  Instance* in = new (std::nothrow) Instance;
  if (!in) return nullptr;
  in->name = name ? name : "";
  in->kind = kind;
  if (functions) in->logger = functions->logger, in->environment = functions->componentEnvironment;
  return in;
}

void fmi2FreeInstance(fmi2Component c) {
  if (!c) return;
  as_instance(c)->free_cvode();
  delete as_instance(c);
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean tolerance_defined, fmi2Real tolerance, fmi2Real start, fmi2Boolean,
                               fmi2Real) {
  Instance& in = *as_instance(c);
  in.t = start;
  if (tolerance_defined && tolerance > 0) in.tolerance = tolerance;
  in.cvode_current = false;
  return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component) { return fmi2OK; }
fmi2Status fmi2ExitInitializationMode(fmi2Component) { return fmi2OK; }
fmi2Status fmi2Terminate(fmi2Component c) {
  as_instance(c)->free_cvode();
  return fmi2OK;
}
fmi2Status fmi2Reset(fmi2Component c) {
  Instance& in = *as_instance(c);
  in.free_cvode();
  in.t = 0, in.x = model::default_state, in.p = model::default_parameters, in.u = model::default_inputs;
  return fmi2OK;
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference r[], size_t n, fmi2Real v[]) {
  for (size_t k = 0; k < n; ++k)
    if (get_real(*as_instance(c), r[k], v[k]) != fmi2OK) return fmi2Error;
  return fmi2OK;
}
fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference r[], size_t n, const fmi2Real v[]) {
  for (size_t k = 0; k < n; ++k)
    if (set_real(*as_instance(c), r[k], v[k]) != fmi2OK) return fmi2Error;
  return fmi2OK;
}
static fmi2Status none_of_this_kind(fmi2Component c, size_t n) {
  if (n == 0) return fmi2OK;
  as_instance(c)->error("the model has only real variables");
  return fmi2Error;
}
fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference[], size_t n, fmi2Integer[]) { return none_of_this_kind(c, n); }
fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference[], size_t n, fmi2Boolean[]) { return none_of_this_kind(c, n); }
fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference[], size_t n, fmi2String[]) { return none_of_this_kind(c, n); }
fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference[], size_t n, const fmi2Integer[]) { return none_of_this_kind(c, n); }
fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference[], size_t n, const fmi2Boolean[]) { return none_of_this_kind(c, n); }
fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference[], size_t n, const fmi2String[]) { return none_of_this_kind(c, n); }

static fmi2Status no_state_copies(fmi2Component c) {
  as_instance(c)->error("this FMU cannot get or set its state (canGetAndSetFMUstate is false)");
  return fmi2Error;
}
fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate*) { return no_state_copies(c); }
fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate) { return no_state_copies(c); }
fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate*) { return no_state_copies(c); }
fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate, size_t*) { return no_state_copies(c); }
fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate, fmi2Byte[], size_t) { return no_state_copies(c); }
fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte[], size_t, fmi2FMUstate*) { return no_state_copies(c); }

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference unknowns[], size_t n_unknowns,
                                        const fmi2ValueReference knowns[], size_t n_knowns, const fmi2Real dv_known[],
                                        fmi2Real dv_unknown[]) {
  return directional_derivative(*as_instance(c), unknowns, n_unknowns, knowns, n_knowns, dv_known, dv_unknown);
}

// Model Exchange: no events
fmi2Status fmi2EnterEventMode(fmi2Component) { return fmi2OK; }
fmi2Status fmi2NewDiscreteStates(fmi2Component, fmi2EventInfo* info) {
  *info = fmi2EventInfo{fmi2False, fmi2False, fmi2False, fmi2False, fmi2False, 0.0};
  return fmi2OK;
}
fmi2Status fmi2EnterContinuousTimeMode(fmi2Component) { return fmi2OK; }
fmi2Status fmi2CompletedIntegratorStep(fmi2Component, fmi2Boolean, fmi2Boolean* enter_event_mode, fmi2Boolean* terminate) {
  *enter_event_mode = fmi2False, *terminate = fmi2False;
  return fmi2OK;
}
fmi2Status fmi2SetTime(fmi2Component c, fmi2Real t) {
  as_instance(c)->t = t;
  return fmi2OK;
}
fmi2Status fmi2SetContinuousStates(fmi2Component c, const fmi2Real x[], size_t n) {
  if (n != S) return fmi2Error;
  std::memcpy(as_instance(c)->x.data(), x, S * sizeof(double));
  as_instance(c)->cvode_current = false;
  return fmi2OK;
}
fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real xdot[], size_t n) {
  const Instance& in = *as_instance(c);
  if (n != S) return fmi2Error;
  model::rhs(in.t, in.x.data(), in.inputs(), in.p.data(), xdot);
  return fmi2OK;
}
fmi2Status fmi2GetEventIndicators(fmi2Component, fmi2Real[], size_t n) { return n == 0 ? fmi2OK : fmi2Error; }
fmi2Status fmi2GetContinuousStates(fmi2Component c, fmi2Real x[], size_t n) {
  if (n != S) return fmi2Error;
  std::memcpy(x, as_instance(c)->x.data(), S * sizeof(double));
  return fmi2OK;
}
fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c, fmi2Real nominal[], size_t n) {
  if (n != S) return fmi2Error;
  std::array<double, S> size = state_sizes(*as_instance(c));
  for (size_t k = 0; k < n; ++k) nominal[k] = size[k] > 0 ? size[k] : 1.0;
  return fmi2OK;
}

// Co-Simulation: CVODE from the current point to the next, the inputs held over the step
fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference[], size_t n, const fmi2Integer[], const fmi2Real[]) {
  if (n == 0) return fmi2OK;
  as_instance(c)->error("input derivatives are not used (canInterpolateInputs is false)");
  return fmi2Error;
}
fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference[], size_t n, const fmi2Integer[], fmi2Real[]) {
  if (n == 0) return fmi2OK;
  as_instance(c)->error("output derivatives are not provided (maxOutputDerivativeOrder is 0)");
  return fmi2Error;
}
fmi2Status fmi2DoStep(fmi2Component c, fmi2Real current, fmi2Real step, fmi2Boolean) {
  Instance& in = *as_instance(c);
#ifndef EOMGEN_FMU_CO_SIMULATION
  (void)current, (void)step;
  in.error("this FMU is for Model Exchange only: it has no solver to step with");
  return fmi2Error;
#else
  if (std::fabs(current - in.t) > 1e-12 * (1 + std::fabs(current))) in.t = current, in.cvode_current = false;
  if (!in.cvode_current && !start_cvode(in)) {
    in.error(normalize_quaternions(in.x.data()) ? "CVODE could not be set up"
                                                : "a quaternion of a ball or free joint has length zero: it is no rotation");
    return fmi2Error;
  }
  double reached = in.t;
  int status = CVode(in.cvode, current + step, in.y, &reached, CV_NORMAL);
  std::memcpy(in.x.data(), N_VGetArrayPointer(in.y), S * sizeof(double));
  // CVODE interpolates between its steps to the communication point: off the unit sphere by up to
  // its local error, so the copy handed out is normalized too (CVODE's own state stays as it is)
  normalize_quaternions(in.x.data());
  in.t = reached;
  if (status < 0) {
    in.error("CVODE failed at t = " + std::to_string(reached) + " (flag " + std::to_string(status) + ")");
    return fmi2Error;
  }
  return fmi2OK;
#endif
}
fmi2Status fmi2CancelStep(fmi2Component) { return fmi2Error; }
fmi2Status fmi2GetStatus(fmi2Component, const fmi2StatusKind, fmi2Status* s) {
  *s = fmi2OK;
  return fmi2OK;
}
fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind kind, fmi2Real* value) {
  if (kind != fmi2LastSuccessfulTime) return fmi2Discard;
  *value = as_instance(c)->t;
  return fmi2OK;
}
fmi2Status fmi2GetIntegerStatus(fmi2Component, const fmi2StatusKind, fmi2Integer*) { return fmi2Discard; }
fmi2Status fmi2GetBooleanStatus(fmi2Component, const fmi2StatusKind, fmi2Boolean* value) {
  *value = fmi2False;
  return fmi2OK;
}
fmi2Status fmi2GetStringStatus(fmi2Component, const fmi2StatusKind, fmi2String*) { return fmi2Discard; }

}  // extern "C"
