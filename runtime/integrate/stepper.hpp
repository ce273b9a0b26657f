/// @file What every integrator offers the simulation loop: advance to the next
/// output time, report statistics, and say why it stopped.
#pragma once

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "integrate/projection.hpp"
#include "simulation.hpp"

namespace eomgen::runtime {

/// The right-hand side with the checks every integrator needs: a non-finite
/// value is reported as a recoverable failure (return 1), and remembered.
class RightHandSide {
 public:
  /// alpha, beta: Baumgarte's gains, used by Lagrange I models only.
  RightHandSide(const Problem& problem, double alpha = 0, double beta = 0) : p_(problem), alpha_(alpha), beta_(beta) {}
  int operator()(double t, const double* x, double* xdot);
  int jacobian(double t, const double* x, double* J);  // row-major num_states²
  std::size_t size() const { return p_.model->num_states; }
  long evaluations() const { return evaluations_; }
  bool saw_non_finite() const { return non_finite_; }
  double non_finite_time() const { return non_finite_time_; }
  const std::vector<double>& non_finite_state() const { return non_finite_state_; }
  const Problem& problem() const { return p_; }
  /// Set when the state is to be projected onto the constraints after every step.
  ConstraintProjection* projection = nullptr;

 private:
  const Problem& p_;
  double alpha_, beta_;
  long evaluations_ = 0;
  bool non_finite_ = false;
  double non_finite_time_ = 0;
  std::vector<double> non_finite_state_;
  std::vector<double> inputs_;  // u(t) when the inputs vary in time
};

/// SUNDIALS' own messages are dropped: a failure is reported once, by the simulation.
void quiet_sundials_messages(int error_code, const char* module, const char* function, char* message, void* data);

class Stepper {
 public:
  virtual ~Stepper() = default;
  /// Advances to t_out; x then holds the state there. On failure returns false,
  /// with x the state at the time reached, and failure_time/flag/reason set.
  virtual bool advance(double t_out, std::vector<double>& x) = 0;
  virtual SolverStatistics statistics() const = 0;
  /// The integrator's own estimate of its global error (the reference integrator only).
  virtual double error_estimate() const { return NAN; }
  virtual double reference_step() const { return 0; }
  /// Whether RightHandSide::projection, when set, is applied after every step (not by CVODE's
  /// Adams, which has no projection of its own, nor by the reference integrator); the simulation
  /// normalizes the quaternions of the rows it records in any case.
  virtual bool projects_after_every_step() const { return true; }

  double failure_time = 0;
  int flag = 0;
  std::string reason;
  /// the step the integrator was about to try when it failed (0 where it does not say)
  double failure_step = 0;
};

std::unique_ptr<Stepper> make_cvode(RightHandSide& f, const std::vector<double>& x0, const SimulationSettings& s, bool adams);
/// Explicit Runge–Kutta: `table` is an ARKODE ERK table id.
std::unique_ptr<Stepper> make_arkode_explicit(RightHandSide& f, const std::vector<double>& x0, const SimulationSettings& s, int table);
/// Diagonally implicit Runge–Kutta with the generated Jacobian.
std::unique_ptr<Stepper> make_arkode_dirk(RightHandSide& f, const std::vector<double>& x0, const SimulationSettings& s);
/// IDA on the stabilized index-2 form of Gear, Gupta and Leimkuhler (Lagrange I models).
std::unique_ptr<Stepper> make_ida(RightHandSide& f, const std::vector<double>& x0, const SimulationSettings& s);
/// Extrapolation in a wide scalar with its own error estimate (Problem::reference).
std::unique_ptr<Stepper> make_reference(RightHandSide& f, const std::vector<double>& x0, const SimulationSettings& s);
/// The fixed-step integrator s.integrator names: rk4, verlet (canonical for Hamilton's
/// equations) or gauss-legendre.
std::unique_ptr<Stepper> make_fixed_step(RightHandSide& f, const std::vector<double>& x0, const SimulationSettings& s);

}  // namespace eomgen::runtime
