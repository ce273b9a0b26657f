/// @file Whether two sets of equations of motion give the same motion although their
/// entries differ: M and f scaled or combined row by row, or written in other
/// velocities (Appell's pseudo-velocities against q'). At random states both give the
/// accelerations q''; for pseudo-velocities s' = M⁻¹f and q'' = d/dt(W(q) s + w),
/// i.e. Σ ∂r/∂q q' + Σ ∂r/∂s s' + ∂r/∂t with r the kinematic equations.
#pragma once

#include <string>
#include <vector>

#include <ginac/ginac.h>

namespace eomgen {

/// `e` with the symbols of `values` put in (every key a symbol, each looked up: GiNaC's subs would
/// try every key as a pattern on every node, and scan the map for products at every sum; a
/// 21-joint tree's two copies took 53 s to compare so, 2.8 s now).
GiNaC::ex substituted(const GiNaC::ex& e, const GiNaC::exmap& values);

/// One side's equations in the symbols both sides share.
struct MotionForm {
  std::vector<GiNaC::ex> coordinates, coordinate_rates;  // q and the symbols of q'
  std::vector<GiNaC::ex> velocities;                     // of the state: q', or pseudo-velocities s
  GiNaC::matrix mass_matrix;
  std::vector<GiNaC::ex> forcing;
  std::vector<GiNaC::ex> kinematics;   // Appell: q' = r(q, s, t); empty when the velocities are q'
  std::vector<GiNaC::ex> definitions;  // Appell: s = Y q' + y
  GiNaC::ex time;
};

struct MotionComparison {
  bool same = false;
  double max_rel_difference = 0;
  int states = 0;  // at which both gave accelerations
};

/// Compares the accelerations at the states of `a_points` (values for every symbol, and for a's
/// intermediates) and `b_points` (the same values, and b's intermediates').
MotionComparison compare_accelerations(const MotionForm& a, const MotionForm& b, const std::vector<GiNaC::exmap>& a_points,
                                       const std::vector<GiNaC::exmap>& b_points, double tolerance);

}  // namespace eomgen
