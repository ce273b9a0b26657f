/// @file The error of a trajectory against a reference: the largest difference over
/// the output times, each state component relative to its own scale.
#pragma once

#include <vector>

namespace eomgen::runtime {

/// max over k and i of |x_i(t_k) − r_i(t_k)| / s_i, where s_i is the largest |r_i| over
/// the run, but at least 1e-3 of the largest |r| of any component (so that a component
/// that stays near zero does not turn roundoff into a large relative error). Rows are
/// compared up to the shorter of the two; NaN when a value is not finite.
double trajectory_error(const std::vector<std::vector<double>>& states, const std::vector<std::vector<double>>& reference);

/// The scales s_i of trajectory_error, from the reference's rows.
std::vector<double> state_scales(const std::vector<std::vector<double>>& reference);

/// max over i of |x_i − r_i| / s_i for one row; NaN when a value is not finite.
double row_error(const std::vector<double>& x, const std::vector<double>& r, const std::vector<double>& scales);

}  // namespace eomgen::runtime
