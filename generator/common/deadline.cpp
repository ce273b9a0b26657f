#include "common/deadline.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <thread>

#include <fmt/format.h>

namespace eomgen {

namespace {

std::atomic<double> limit_seconds{default_derivation_seconds};
std::atomic<const char*> stage{"reading the model"};
thread_local int depth = 0;

struct Watchdog {
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  std::thread thread;
};

std::unique_ptr<Watchdog> active;

void expire(const std::string& model, double seconds) {
  std::string message = fmt::format(
      "eomgen: error: {}: the derivation ran past its limit of {:g} s while forming {}: its expressions grow too "
      "large\n  hint: simplify the model (fewer nested functions; absolute angles for long chains), or raise the "
      "limit with --max-seconds (0: none); nothing was written\n",
      model, seconds, stage.load());
  std::fputs(message.c_str(), stderr);
  std::fflush(stderr);
  std::_Exit(2);
}

}  // namespace

void set_derivation_time_limit(double seconds) { limit_seconds = seconds; }

void derivation_stage(const char* now) { stage = now; }

DerivationDeadline::DerivationDeadline(const std::string& model) : outermost_(depth++ == 0) {
  double seconds = limit_seconds;
  if (!outermost_ || !(seconds > 0)) return;
  stage = "the model";
  active = std::make_unique<Watchdog>();
  Watchdog* w = active.get();
  w->thread = std::thread([w, model, seconds] {
    std::unique_lock<std::mutex> lock(w->mutex);
    if (!w->finished.wait_for(lock, std::chrono::duration<double>(seconds), [w] { return w->done; })) expire(model, seconds);
  });
}

DerivationDeadline::~DerivationDeadline() {
  --depth;
  if (!outermost_ || !active) return;
  {
    std::lock_guard<std::mutex> lock(active->mutex);
    active->done = true;
  }
  active->finished.notify_one();
  active->thread.join();
  active.reset();
}

}  // namespace eomgen
