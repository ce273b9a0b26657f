/// @file The lengths of the quaternions of ball and free joints in a state. The generated
/// rotations are those of q/|q| and the exact motion keeps |q|, so a drift of |q| does not
/// change the mechanics; an integrator still drifts it, and what the trajectory hands on
/// (MuJoCo's qpos, an animation, another tool) expects unit quaternions.
#pragma once

#include <cstddef>

#include "model_abi.h"

namespace eomgen::runtime {

/// |q| of quaternion k of x.
double quaternion_length(const eomgen_model_abi& m, const double* x, std::size_t k);

/// max over the quaternions of x of | |q| − 1 | (0 without quaternions).
double quaternion_norm_error(const eomgen_model_abi& m, const double* x);

/// Divides each quaternion of x by its length and returns the largest | |q| − 1 | it had. A
/// quaternion of length 0 names no orientation and is left as it is (the result is then 1).
double normalize_quaternions(const eomgen_model_abi& m, double* x);

/// The first of x's quaternions of length 0 (no orientation), or −1.
int zero_quaternion(const eomgen_model_abi& m, const double* x);

}  // namespace eomgen::runtime
