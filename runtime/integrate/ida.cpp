/// @file IDA on Lagrange's equations of the first kind in the stabilized index-2 form
/// of Gear, Gupta and Leimkuhler (1985), with y = [q; v; λ; μ]:
///   q' = v − Cₕᵀ μ,   M v' = f + Cᵀ λ,   C v + b = 0,   g(q) = 0,
/// where Cₕ are the rows of the holonomic constraints. μ vanishes on the exact solution
/// and keeps q on g = 0, so both the position and velocity constraints hold to the
/// Newton tolerance without drift. λ and μ are algebraic and left out of the error test.
#include <ida/ida.h>
#include <ida/ida_ls.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "integrate/stepper.hpp"
#include "integrate/sundials_callbacks.hpp"

namespace eomgen::runtime {
namespace {

class Ida : public Stepper {
 public:
  Ida(RightHandSide& f, const std::vector<double>& x0, const SimulationSettings& s) : f_(f) {
    const eomgen_model_abi& m = *f.problem().model;
    n_ = m.num_coordinates;
    mc_ = m.num_constraints;
    for (std::size_t i = 0; i < mc_; ++i)
      if (m.constraint_is_holonomic[i]) holonomic_.push_back(i);
    std::size_t size = 2 * n_ + mc_ + holonomic_.size();
    SUNContext_Create(nullptr, &context_);
    y_ = N_VNew_Serial(static_cast<sunindextype>(size), context_);
    yp_ = N_VClone(y_);
    consistent_start(x0, s.t_start);
    N_Vector id = N_VClone(y_);
    double* kind = N_VGetArrayPointer(id);
    for (std::size_t i = 0; i < size; ++i) kind[i] = i < 2 * n_ ? 1.0 : 0.0;
    memory_ = IDACreate(context_);
    IDAInit(memory_, residual, s.t_start, y_, yp_);
    // λ and μ enter only the Newton convergence test (their error test is suppressed). μ ≈ 0,
    // so an absolute tolerance as tight as the coordinates' asks Newton for corrections near
    // roundoff and fails at the first step below rtol ≈ 1e-8; 1e-2 of their own scales
    // (algebraic_tolerances) converged from rtol 1e-6 to 1e-12 and leaves |g| near the
    // coordinates' own tolerance (√rtol did not)
    N_Vector tolerance = N_VClone(y_);
    double* atol = N_VGetArrayPointer(tolerance);
    bool each = s.state_atol.size() == 2 * n_;
    for (std::size_t i = 0; i < 2 * n_; ++i) atol[i] = each ? s.state_atol[i] : s.atol;
    algebraic_tolerances(x0, s, atol + 2 * n_);
    IDASVtolerances(memory_, s.rtol, tolerance);
    N_VDestroy(tolerance);
    IDASetUserData(memory_, this);
    IDASetErrHandlerFn(memory_, quiet_sundials_messages, nullptr);
    IDASetMaxNumSteps(memory_, s.max_steps);
    IDASetStopTime(memory_, s.t_end);
    IDASetId(memory_, id);
    IDASetSuppressAlg(memory_, SUNTRUE);
    IDASetInitStep(memory_, initial_step(s));
    N_VDestroy(id);
    matrix_ = SUNDenseMatrix(static_cast<sunindextype>(size), static_cast<sunindextype>(size), context_);
    linear_ = SUNLinSol_Dense(y_, matrix_, context_);
    IDASetLinearSolver(memory_, linear_, matrix_);
    started_ = std::chrono::steady_clock::now();
  }

  ~Ida() override {
    IDAFree(&memory_);
    SUNLinSolFree(linear_);
    SUNMatDestroy(matrix_);
    N_VDestroy(y_);
    N_VDestroy(yp_);
    SUNContext_Free(&context_);
  }

  bool advance(double t_out, std::vector<double>& x) override {
    realtype reached = 0;
    int status = IDASolve(memory_, t_out, &reached, y_, yp_, IDA_NORMAL);
    const double* y = N_VGetArrayPointer(y_);
    x.assign(y, y + 2 * n_);
    if (status >= 0) return true;
    failure_time = reached;
    flag = status;
    IDAGetCurrentStep(memory_, &failure_step);
    reason = fmt::format("IDA stopped with {} ({})", take_flag_name(IDAGetReturnFlagName(status)), status);
    return false;
  }

  SolverStatistics statistics() const override {
    SolverStatistics s;
    long value = 0;
    IDAGetNumSteps(memory_, &value), s.steps = value;
    IDAGetNumResEvals(memory_, &value), s.rhs_evaluations = value;
    IDAGetNumJacEvals(memory_, &value), s.jacobian_evaluations = value;
    IDAGetNumErrTestFails(memory_, &value), s.error_test_failures = value;
    IDAGetNumNonlinSolvConvFails(memory_, &value), s.convergence_failures = value;
    s.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    return s;
  }

 private:
  // x0 is on the constraint manifold (the simulation projected it): λ and q'' from
  // the augmented system without Baumgarte terms, μ = 0
  void consistent_start(const std::vector<double>& x0, double t) {
    const Problem& p = f_.problem();
    const eomgen_model_abi& m = *p.model;
    double* y = N_VGetArrayPointer(y_);
    double* yp = N_VGetArrayPointer(yp_);
    N_VConst(0.0, y_);
    N_VConst(0.0, yp_);
    std::copy(x0.begin(), x0.end(), y);
    std::vector<double> xdot(2 * n_);
    std::vector<double> scratch;
    const double* u = p.inputs_at(t, scratch);
    m.rhs_stabilized(t, x0.data(), u, p.parameters.data(), 0, 0, xdot.data());
    std::copy(xdot.begin(), xdot.end(), yp);
    m.multipliers(t, x0.data(), u, p.parameters.data(), y + 2 * n_);
  }

  // 1e-2 of each multiplier's scale: λ_i ~ F/|C_i| (C_i λ_i is a force, F the larger of |f| and
  // |M q''| at the start) and μ_h ~ V/|C_h| (C_hᵀ μ is a rate, V the larger of |q'| and |q''|·dt_out),
  // so that the Newton test asks the same of a model in seconds or in microseconds, in meters or
  // in millimeters (a fixed 1e-2 failed on the four-bar with time in µs: λ ~ 1e12 there)
  void algebraic_tolerances(const std::vector<double>& x0, const SimulationSettings& s, double* atol) {
    const Problem& p = f_.problem();
    const eomgen_model_abi& m = *p.model;
    std::vector<double> scratch, jacobian(mc_ * n_), mass(n_ * n_), forcing(n_);
    const double* u = p.inputs_at(s.t_start, scratch);
    const double* yp = N_VGetArrayPointer(yp_);
    m.constraint_jacobian(s.t_start, x0.data(), p.parameters.data(), jacobian.data());
    m.mass_matrix(s.t_start, x0.data(), p.parameters.data(), mass.data());
    m.forcing(s.t_start, x0.data(), u, p.parameters.data(), forcing.data());
    double force = 0, rate = 0;
    for (std::size_t j = 0; j < n_; ++j) {
      double inertial = 0;
      for (std::size_t k = 0; k < n_; ++k) inertial += mass[j * n_ + k] * yp[n_ + k];
      force = std::max({force, std::abs(forcing[j]), std::abs(inertial)});
      rate = std::max({rate, std::abs(x0[n_ + j]), std::abs(yp[n_ + j]) * std::abs(s.dt_out)});
    }
    auto row_size = [&](std::size_t i) {
      double size = 0;
      for (std::size_t j = 0; j < n_; ++j) size = std::max(size, std::abs(jacobian[i * n_ + j]));
      return size;
    };
    // a model at rest in equilibrium has no scale of its own: its multipliers stay put anyway
    auto scaled = [](double numerator, double size) { return numerator > 0 && size > 0 ? 1e-2 * numerator / size : 1e-2; };
    for (std::size_t i = 0; i < mc_; ++i) atol[i] = scaled(force, row_size(i));
    for (std::size_t h = 0; h < holonomic_.size(); ++h) atol[mc_ + h] = scaled(rate, row_size(holonomic_[h]));
  }

  // IDA's own first step, h = min(dt_out/1000, 0.5/‖y'‖) in its weighted norm over q and v, but
  // not below 1e-6 dt_out: the iteration matrix's rows of q and v grow as 1/h while the constraint
  // rows stay O(1): at rtol 1e-12 and atol 1e-14 that h was 1.3e-14 on the four-bar (dt_out
  // 0.01), where the matrix is singular in double, and Newton failed there and at every shorter
  // step. A first step too long for the tolerances is shortened by the error test instead.
  double initial_step(const SimulationSettings& s) const {
    const double* y = N_VGetArrayPointer(y_);
    const double* yp = N_VGetArrayPointer(yp_);
    double sum = 0;
    for (std::size_t i = 0; i < 2 * n_; ++i) {
      double weighted = yp[i] / (s.rtol * std::abs(y[i]) + s.atol);
      sum += weighted * weighted;
    }
    double norm = std::sqrt(sum / double(2 * n_)), longest = std::abs(s.dt_out) / 1000;
    double step = norm > 0.5 / longest ? 0.5 / norm : longest;
    return std::max(step, 1e-6 * std::abs(s.dt_out));
  }

  static int residual(realtype t, N_Vector yy, N_Vector yyp, N_Vector rr, void* data) {
    return static_cast<Ida*>(data)->residual(t, N_VGetArrayPointer(yy), N_VGetArrayPointer(yyp), N_VGetArrayPointer(rr));
  }

  int residual(double t, const double* y, const double* yp, double* r) {
    const Problem& p = f_.problem();
    const eomgen_model_abi& m = *p.model;
    std::vector<double> scratch;
    const double* u = p.inputs_at(t, scratch);
    const double *lambda = y + 2 * n_, *mu = lambda + mc_;
    mass_.resize(n_ * n_);
    forcing_.resize(n_);
    jacobian_.resize(mc_ * n_);
    position_.resize(mc_);
    velocity_.resize(mc_);
    m.mass_matrix(t, y, p.parameters.data(), mass_.data());
    m.forcing(t, y, u, p.parameters.data(), forcing_.data());
    m.constraint_jacobian(t, y, p.parameters.data(), jacobian_.data());
    m.constraint_residuals(t, y, p.parameters.data(), position_.data(), velocity_.data());
    for (std::size_t j = 0; j < n_; ++j) {
      double rq = yp[j] - y[n_ + j], rv = -forcing_[j];
      for (std::size_t h = 0; h < holonomic_.size(); ++h) rq += jacobian_[holonomic_[h] * n_ + j] * mu[h];
      for (std::size_t k = 0; k < n_; ++k) rv += mass_[j * n_ + k] * yp[n_ + k];
      for (std::size_t i = 0; i < mc_; ++i) rv -= jacobian_[i * n_ + j] * lambda[i];
      r[j] = rq;
      r[n_ + j] = rv;
    }
    for (std::size_t i = 0; i < mc_; ++i) r[2 * n_ + i] = velocity_[i];
    for (std::size_t h = 0; h < holonomic_.size(); ++h) r[2 * n_ + mc_ + h] = position_[holonomic_[h]];
    for (std::size_t i = 0; i < 2 * n_ + mc_ + holonomic_.size(); ++i)
      if (!std::isfinite(r[i])) return 1;
    return 0;
  }

  RightHandSide& f_;
  std::size_t n_ = 0, mc_ = 0;
  std::vector<std::size_t> holonomic_;
  std::vector<double> mass_, forcing_, jacobian_, position_, velocity_;
  SUNContext context_ = nullptr;
  N_Vector y_ = nullptr, yp_ = nullptr;
  void* memory_ = nullptr;
  SUNMatrix matrix_ = nullptr;
  SUNLinearSolver linear_ = nullptr;
  std::chrono::steady_clock::time_point started_;
};

}  // namespace

std::unique_ptr<Stepper> make_ida(RightHandSide& f, const std::vector<double>& x0, const SimulationSettings& s) {
  return std::make_unique<Ida>(f, x0, s);
}

}  // namespace eomgen::runtime
