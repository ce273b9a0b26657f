/// @file The progress line of work counted in items (points of a sweep, samples of an
/// ensemble): at most twice a second, on stderr, with the time left.
#pragma once

#include <functional>
#include <string>

namespace eomgen {

/// "eomgen COMMAND:  40% (160/400 UNIT), about 2.1 s left"; called with (done, total).
std::function<void(long, long)> count_progress(const std::string& command, const std::string& unit);

}  // namespace eomgen
