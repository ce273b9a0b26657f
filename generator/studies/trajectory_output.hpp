/// @file Where `simulate` puts its rows as they are computed, so memory stays bounded
/// whatever --t-end: the CSV, written into a temporary file beside its path and moved into
/// place at the end (a write that fails, a full disk, leaves no file), and a thinned copy of
/// at most about 20,000 rows for the charts.
#pragma once

#include <cstdio>
#include <string>

#include "simulation.hpp"

namespace eomgen::studies {

class TrajectoryOutput {
 public:
  /// `csv`: the CSV's path, or empty for none.
  TrajectoryOutput(const eomgen_model_abi& model, std::string csv);
  ~TrajectoryOutput();
  TrajectoryOutput(const TrajectoryOutput&) = delete;
  TrajectoryOutput& operator=(const TrajectoryOutput&) = delete;

  /// SimulationSettings::stream: false once the CSV cannot be written (see failure()).
  bool take(const runtime::Trajectory& rows);
  /// Moves the CSV into place; false (and no file) when it could not be written.
  bool finish();
  const std::string& failure() const { return failure_; }
  /// Every k-th row, k doubling as the run grows, and the last row.
  runtime::Trajectory chart_rows() const;

 private:
  bool write(const std::string& text);
  const eomgen_model_abi& model_;
  std::string csv_, temporary_, failure_;
  std::FILE* file_ = nullptr;
  runtime::Trajectory sample_, last_;
  std::size_t every_ = 1, seen_ = 0;
};

/// A progress line on standard error for runs longer than two seconds: updated in place on a
/// terminal, a line every ten seconds otherwise. Call with each row's time.
class RunProgress {
 public:
  RunProgress(std::string label, double t_start, double t_end);
  ~RunProgress();
  void operator()(double t);

 private:
  std::string label_;
  double t_start_, t_end_, started_, shown_ = 0;
  bool terminal_, drawn_ = false;
};

}  // namespace eomgen::studies
