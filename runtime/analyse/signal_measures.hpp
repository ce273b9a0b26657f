/// @file Scalar measures of one signal over a run, the quantities of interest of an
/// ensemble: its final value, extremes, time mean, and period.
#pragma once

#include <string>
#include <vector>

namespace eomgen::runtime {

enum class MeasureKind { final_value, maximum, minimum, mean, period };

struct Measure {
  MeasureKind kind = MeasureKind::final_value;
  std::string signal;  // a coordinate, a velocity, an output or energy
  /// "final(x)", "max(x)", "min(x)", "mean(x)", "period(x)"
  std::string text() const;
};

/// The kind named `name` (final, max, min, mean, period); false when there is none.
bool measure_kind(const std::string& name, MeasureKind& kind);

/// The measure of `values` sampled at increasing `times`. mean: the time average by the
/// trapezoidal rule. period: the mean time between upward crossings of the midrange
/// (max + min)/2, each crossing located on the cubic through the four samples about it.
/// NaN when undefined: no samples, or fewer than two crossings for a period.
double measure_signal(MeasureKind kind, const std::vector<double>& times, const std::vector<double>& values);

}  // namespace eomgen::runtime
