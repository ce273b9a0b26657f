/// @file CVODE: variable-order BDF with the generated dense Jacobian (stiff), or
/// Adams–Moulton with fixed-point iteration (non-stiff).
#include <cvode/cvode.h>
#include <cvode/cvode_proj.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <chrono>

#include <fmt/format.h>

#include "integrate/stepper.hpp"
#include "integrate/sundials_callbacks.hpp"

namespace eomgen::runtime {
namespace {

class Cvode : public Stepper {
 public:
  Cvode(RightHandSide& f, const std::vector<double>& x0, const SimulationSettings& s, bool adams) : adams_(adams) {
    SUNContext_Create(nullptr, &context_);
    x_ = N_VNew_Serial(static_cast<sunindextype>(f.size()), context_);
    std::copy(x0.begin(), x0.end(), N_VGetArrayPointer(x_));
    memory_ = CVodeCreate(adams ? CV_ADAMS : CV_BDF, context_);
    CVodeInit(memory_, sundials_rhs, s.t_start, x_);
    if (N_Vector each = absolute_tolerances(s, x_)) CVodeSVtolerances(memory_, s.rtol, each), N_VDestroy(each);
    else CVodeSStolerances(memory_, s.rtol, s.atol);
    CVodeSetUserData(memory_, &f);
    CVodeSetErrHandlerFn(memory_, quiet_sundials_messages, nullptr);
    CVodeSetMaxNumSteps(memory_, s.max_steps);
    CVodeSetStopTime(memory_, s.t_end);
    if (adams) {
      nonlinear_ = SUNNonlinSol_FixedPoint(x_, 0, context_);
      CVodeSetNonlinearSolver(memory_, nonlinear_);
      CVodeSetMaxOrd(memory_, 12);
    } else {
      matrix_ = SUNDenseMatrix(static_cast<sunindextype>(f.size()), static_cast<sunindextype>(f.size()), context_);
      linear_ = SUNLinSol_Dense(x_, matrix_, context_);
      CVodeSetLinearSolver(memory_, linear_, matrix_);
      CVodeSetJacFn(memory_, sundials_dense_jacobian);
    }
    // CVODE projects after every step with BDF only; Adams is projected at the output times
    if (f.projection && !adams) CVodeSetProjFn(memory_, sundials_projection_correction);
    f_ = &f;
    started_ = std::chrono::steady_clock::now();
  }

  ~Cvode() override {
    CVodeFree(&memory_);
    if (linear_) SUNLinSolFree(linear_);
    if (matrix_) SUNMatDestroy(matrix_);
    if (nonlinear_) SUNNonlinSolFree(nonlinear_);
    N_VDestroy(x_);
    SUNContext_Free(&context_);
  }

  bool advance(double t_out, std::vector<double>& x) override {
    realtype reached = 0;
    int status = CVode(memory_, t_out, x_, &reached, CV_NORMAL);
    double* data = N_VGetArrayPointer(x_);
    bool projection_failed = false;
    // Adams restarts from the projected state; quaternions alone need no restart (the rotation is
    // that of q/|q|), and the simulation normalizes the rows it records
    if (status >= 0 && adams_ && f_->projection && f_->problem().model->num_constraints) {
      if (f_->projection->project(reached, data)) carried_ = counters(), CVodeReInit(memory_, reached, x_);
      else projection_failed = true;
    }
    x.assign(data, data + x.size());
    if (status >= 0 && !projection_failed) return true;
    failure_time = reached;
    flag = status;
    CVodeGetCurrentStep(memory_, &failure_step);
    reason = projection_failed ? std::string("the projection onto the constraints failed (Newton's method did not converge)")
                               : fmt::format("CVODE {} stopped with {} ({})", adams_ ? "Adams" : "BDF",
                                             take_flag_name(CVodeGetReturnFlagName(status)), status);
    return false;
  }

  bool projects_after_every_step() const override { return !adams_; }

  SolverStatistics statistics() const override {
    SolverStatistics s = counters();
    s.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    return s;
  }

 private:
  // the counters since the start: CVodeReInit sets CVODE's own to zero
  SolverStatistics counters() const {
    SolverStatistics s = carried_;
    long value = 0;
    CVodeGetNumSteps(memory_, &value), s.steps += value;
    CVodeGetNumRhsEvals(memory_, &value), s.rhs_evaluations += value;
    if (!adams_) CVodeGetNumJacEvals(memory_, &value), s.jacobian_evaluations += value;
    CVodeGetNumErrTestFails(memory_, &value), s.error_test_failures += value;
    CVodeGetNumNonlinSolvConvFails(memory_, &value), s.convergence_failures += value;
    return s;
  }

  bool adams_;
  SolverStatistics carried_;
  RightHandSide* f_ = nullptr;
  SUNContext context_ = nullptr;
  N_Vector x_ = nullptr;
  void* memory_ = nullptr;
  SUNMatrix matrix_ = nullptr;
  SUNLinearSolver linear_ = nullptr;
  SUNNonlinearSolver nonlinear_ = nullptr;
  std::chrono::steady_clock::time_point started_;
};

}  // namespace

std::unique_ptr<Stepper> make_cvode(RightHandSide& f, const std::vector<double>& x0, const SimulationSettings& s, bool adams) {
  return std::make_unique<Cvode>(f, x0, s, adams);
}

}  // namespace eomgen::runtime
