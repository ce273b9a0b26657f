#include "common/stop_signal.hpp"

namespace eomgen {

namespace {
// constant-initialized, so the handler never meets it half made
std::atomic<bool> stop_requested{false};
extern "C" void on_stop_signal(int) { stop_requested = true; }
}  // namespace

std::atomic<bool>& StopOnSignal::flag() { return stop_requested; }

StopOnSignal::StopOnSignal() {
  flag() = false;
  previous_interrupt_ = std::signal(SIGINT, on_stop_signal);
  previous_terminate_ = std::signal(SIGTERM, on_stop_signal);
}

StopOnSignal::~StopOnSignal() {
  std::signal(SIGINT, previous_interrupt_);
  std::signal(SIGTERM, previous_terminate_);
}

}  // namespace eomgen
