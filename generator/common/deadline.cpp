#include "common/deadline.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include <unistd.h>

#include <fmt/format.h>

namespace eomgen {

namespace {

std::atomic<double> limit_seconds{default_derivation_seconds};
std::atomic<double> limit_gigabytes{-1};  // below zero: the default, found when first needed
std::atomic<const char*> stage{"reading the model"};
thread_local int depth = 0;

struct Watchdog {
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  std::thread thread;
};

// a derivation's progress on a terminal, from its second second on, once a second: overwritten in
// place, and wiped when it ends or before a message (a log or a pipe gets none)
constexpr double progress_after_seconds = 2;
std::atomic<std::size_t> progress_width{0};  // of the line on the terminal, 0: none

void wipe_progress() {
  if (std::size_t width = progress_width.exchange(0); width > 0) std::fputs(("\r" + std::string(width, ' ') + "\r").c_str(), stderr);
}

std::unique_ptr<Watchdog> active;

// the resident set, from /proc/self/statm (its second field, in pages)
double resident_gigabytes() {
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  if (!f) return 0;
  unsigned long size = 0, resident = 0;
  int read = std::fscanf(f, "%lu %lu", &size, &resident);
  std::fclose(f);
  return read == 2 ? double(resident) * double(::sysconf(_SC_PAGESIZE)) / 1e9 : 0;
}

void overgrown(const std::string& model, double limit, double resident) {
  std::string message = fmt::format(
      "eomgen: error: {}: the derivation grew past its memory limit of {:.3g} GB ({:.3g} GB resident) while forming {}: "
      "its expressions grow too large\n  hint: simplify the model (fewer nested functions; frames with joints "
      "or absolute angles for long chains), or raise the limit with --max-memory GB (0: none); nothing "
      "was written\n",
      model, limit, resident, stage.load());
  wipe_progress();
  std::fputs(message.c_str(), stderr);
  std::fflush(stderr);
  std::_Exit(2);
}

void expire(const std::string& model, double seconds) {
  std::string message = fmt::format(
      "eomgen: error: {}: the derivation ran past its limit of {:g} s while forming {}: its expressions grow too "
      "large\n  hint: simplify the model (fewer nested functions; frames with joints or absolute "
      "angles for long chains), or raise the limit with --max-seconds (0: none); nothing was written\n",
      model, seconds, stage.load());
  wipe_progress();
  std::fputs(message.c_str(), stderr);
  std::fflush(stderr);
  std::_Exit(2);
}

}  // namespace

std::string derivation_progress_line(const std::string& model, const std::string& stage, double elapsed, double limit) {
  std::string line = fmt::format("eomgen: {}: forming {}, {:.0f} s", model, stage, std::floor(elapsed));
  if (limit > 0) line += fmt::format(" (limit {:g} s, --max-seconds)", limit);
  return line;
}

void set_derivation_time_limit(double seconds) { limit_seconds = seconds; }

void set_derivation_memory_limit(double gigabytes) { limit_gigabytes = gigabytes; }

double default_derivation_gigabytes() {
  double machine = double(::sysconf(_SC_PHYS_PAGES)) * double(::sysconf(_SC_PAGESIZE)) / 1e9;
  return machine > 0 ? std::min(8.0, 0.75 * machine) : 8.0;
}

namespace {
std::atomic<bool> timing{false};
std::mutex timings_mutex;
std::vector<std::pair<std::string, std::chrono::steady_clock::time_point>> timings;
}  // namespace

void derivation_stage(const char* now) {
  stage = now;
  if (!timing) return;
  std::lock_guard<std::mutex> lock(timings_mutex);
  timings.push_back({now, std::chrono::steady_clock::now()});
}

void keep_stage_timings() { timing = true; }

std::string stage_timings() {
  std::lock_guard<std::mutex> lock(timings_mutex);
  std::string out;
  for (std::size_t k = 0; k < timings.size(); ++k) {
    auto end = k + 1 < timings.size() ? timings[k + 1].second : std::chrono::steady_clock::now();
    out += fmt::format("  {:<55} {:8.3f} s\n", timings[k].first, std::chrono::duration<double>(end - timings[k].second).count());
  }
  return out;
}

DerivationDeadline::DerivationDeadline(const std::string& model, bool limited) : outermost_(depth++ == 0) {
  double seconds = limited ? limit_seconds.load() : 0;
  double gigabytes = !limited ? 0 : limit_gigabytes < 0 ? default_derivation_gigabytes() : limit_gigabytes.load();
  bool terminal = ::isatty(STDERR_FILENO) == 1;
  if (!outermost_ || (!(seconds > 0) && !(gigabytes > 0) && !terminal)) return;
  if (limited) stage = "the model";
  active = std::make_unique<Watchdog>();
  Watchdog* w = active.get();
  // a look every 50 ms: time and memory
  w->thread = std::thread([w, model, seconds, gigabytes, terminal] {
    auto started = std::chrono::steady_clock::now();
    double shown_at = 0;
    std::unique_lock<std::mutex> lock(w->mutex);
    while (!w->finished.wait_for(lock, std::chrono::milliseconds(50), [w] { return w->done; })) {
      double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      if (seconds > 0 && elapsed > seconds) expire(model, seconds);
      if (gigabytes > 0)
        if (double resident = resident_gigabytes(); resident > gigabytes) overgrown(model, gigabytes, resident);
      if (terminal && elapsed >= progress_after_seconds && elapsed - shown_at >= 1) {
        std::string line = derivation_progress_line(std::filesystem::path(model).filename().string(), stage.load(), elapsed, seconds);
        std::size_t width = std::max(line.size(), progress_width.load());
        std::fputs(("\r" + line + std::string(width - line.size(), ' ')).c_str(), stderr);
        std::fflush(stderr);
        progress_width = width, shown_at = elapsed;
      }
    }
    wipe_progress();
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
