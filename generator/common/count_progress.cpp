#include "common/count_progress.hpp"

#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>

#include <fmt/format.h>

namespace eomgen {

std::function<void(long, long)> count_progress(const std::string& command, const std::string& unit) {
  struct State {
    std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now(), last_print = started - std::chrono::seconds(1);
    bool finished = false;
  };
  auto state = std::make_shared<State>();
  return [state, command, unit](long done, long total) {
    auto now = std::chrono::steady_clock::now();
    if (state->finished || (now - state->last_print < std::chrono::milliseconds(500) && done < total)) return;
    state->finished = done == total;
    state->last_print = now;
    double elapsed = std::chrono::duration<double>(now - state->started).count();
    double left = done > 0 ? elapsed * double(total - done) / double(done) : 0;
    std::cerr << fmt::format("\reomgen {}: {:3.0f}% ({}/{} {}), about {:.1f} s left   ", command,
                             total > 0 ? std::floor(100.0 * double(done) / double(total)) : 100.0, done, total, unit, left)
              << (done == total ? "\n" : "") << std::flush;
  };
}

}  // namespace eomgen
