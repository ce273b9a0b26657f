/// @file Limits on derivation time and memory. Symbolic work on hostile or oversized models
/// can grow without bound inside a single GiNaC call, where no check can run; a watchdog
/// thread ends the process instead, before the system's out-of-memory killer would, with a
/// message naming the model, the limit and the stage that was running, and exit status 2.
/// Nothing has been written then: every output file is written whole, after the derivation.
/// The same thread shows the progress of a long derivation on a terminal.
#pragma once

#include <string>

namespace eomgen {

/// The limit for every derivation that follows, in seconds; 0: none. The default is
/// `default_derivation_seconds`.
void set_derivation_time_limit(double seconds);
inline constexpr double default_derivation_seconds = 300;

/// The limit on the process's resident memory during a derivation, in GB (1e9 bytes); 0: none.
/// The default is the smaller of 8 GB and three quarters of the machine's memory.
void set_derivation_memory_limit(double gigabytes);
double default_derivation_gigabytes();

/// While one lives (the outermost, when they nest), the derivation of `model` is timed; with
/// `limited` false (the header's writing) it only shows its progress.
class DerivationDeadline {
 public:
  explicit DerivationDeadline(const std::string& model, bool limited = true);
  ~DerivationDeadline();
  DerivationDeadline(const DerivationDeadline&) = delete;
  DerivationDeadline& operator=(const DerivationDeadline&) = delete;

 private:
  bool outermost_;
};

/// The progress line a derivation shows on a terminal from its second second on:
/// "eomgen: MODEL: forming STAGE, 12 s (limit 300 s, --max-seconds)"; no limit when `limit` is 0.
std::string derivation_progress_line(const std::string& model, const std::string& stage, double elapsed, double limit);

/// What the derivation is doing now ("kinematics", "Lagrange's equations"), for the message.
void derivation_stage(const char* stage);

/// `--timings`: from now on, the wall time of every stage is kept, for `stage_timings()`.
void keep_stage_timings();
/// One line per stage in the order run, with its seconds (the last one up to now); empty
/// unless keep_stage_timings() was called.
std::string stage_timings();

}  // namespace eomgen
