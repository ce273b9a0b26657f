/// @file Ctrl-C (SIGINT) and SIGTERM during long work: while a StopOnSignal lives, either
/// signal sets a flag instead of ending the process, so the command can finish the step in
/// hand, keep what it computed, say that it is partial and exit 3.
#pragma once

#include <atomic>
#include <csignal>

namespace eomgen {

class StopOnSignal {
 public:
  StopOnSignal();
  ~StopOnSignal();
  StopOnSignal(const StopOnSignal&) = delete;
  StopOnSignal& operator=(const StopOnSignal&) = delete;

  /// The flag the signals set, for SimulationSettings::stop and the sweeps.
  static std::atomic<bool>& flag();
  bool requested() const { return flag().load(); }

 private:
  using Handler = void (*)(int);
  Handler previous_interrupt_, previous_terminate_;
};

}  // namespace eomgen
