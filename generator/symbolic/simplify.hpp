/// @file Keeping derived expressions compact without a blanket expand or
/// normal: each sum is expanded term by term, trigonometric products are
/// recognized (cos a cos b + sin a sin b = cos(a-b), sin²a + cos²a = 1), and
/// terms are collected by the part that depends on the motion.
#pragma once

#include <vector>

#include <ginac/ginac.h>

namespace eomgen {

/// The symbols that change during a motion (coordinates, velocities, time,
/// inputs); everything else in an expression is a parameter.
struct MotionSymbols {
  GiNaC::exset symbols;
  bool depends(const GiNaC::ex& e) const;
};

/// sin²a·X + cos²a·X → X, repeatedly (Pythagoras), on an expanded sum.
GiNaC::ex apply_pythagoras(const GiNaC::ex& expanded);

/// Pairs of products of sines and cosines with a common cofactor folded into
/// sines and cosines of sums and differences, where that gives fewer terms.
GiNaC::ex combine_trig_products(const GiNaC::ex& expanded);

/// Terms grouped by their motion-dependent part, parameter coefficients summed:
/// m1·l²·cos(φ) + m2·l²·cos(φ) → (m1 + m2)·l²·cos(φ).
GiNaC::ex collect_by_motion(const GiNaC::ex& expanded, const MotionSymbols& motion);

/// expand → Pythagoras → trig products → collect.
GiNaC::ex tidy(const GiNaC::ex& e, const MotionSymbols& motion);

}  // namespace eomgen
