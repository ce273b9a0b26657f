/// @file Whether a run's output times can follow the motion it records. The default interval,
/// 0.01 s, is a choice in seconds: it follows a pendulum and skips a MEMS resonator's 1e5 rad/s
/// 160 periods at a time, so that the rows look like a slow motion that is not there (aliasing).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "simulation.hpp"

namespace eomgen::runtime {

/// The period of the fastest oscillation at (t, x): 2π over the largest imaginary part of the
/// rhs's Jacobian's eigenvalues (balanced; imaginary parts within rounding of the real axis left
/// out); infinite when nothing oscillates.
double fastest_period(const Problem& problem, double t, const std::vector<double>& x);

/// The same for x' = A x: 2π over the largest imaginary part of A's eigenvalues.
double fastest_period(const Eigen::MatrixXd& A);

/// A warning when dt_out is longer than half that period (below two rows a period, no output can
/// show the oscillation), with the interval that gives twenty rows a period; nothing otherwise.
std::optional<std::string> aliasing_warning(const Problem& problem, double t, const std::vector<double>& x, double dt_out);
/// The same for a given period, that of `what` ("the fastest mode", "the forcing").
std::optional<std::string> aliasing_warning(double period, double dt_out, const std::string& what);

/// The time constant of the slowest motion of x' = A x: 1/|λ| for the smallest nonzero |λ| of A's
/// eigenvalues (those within rounding of zero, a free body's drift, left out); 0 when none.
double slowest_time(const Eigen::MatrixXd& A);

/// A warning when a response that ends at t_end stops before one time constant of the slowest
/// motion (10 s of a system whose slowest mode takes 1e5 s shows nothing of it), with the end
/// that shows ten of them, and an interval for a thousand rows where dt_out would give more
/// than 1e5; nothing otherwise. For a linear system's response alone: at a state that moves, the
/// Jacobian's small eigenvalues are no slow modes (a free body tumbling has them), and a
/// nonlinear run's end would be warned of wrongly.
std::optional<std::string> span_warning(double slowest, double t_end, double dt_out);

}  // namespace eomgen::runtime
