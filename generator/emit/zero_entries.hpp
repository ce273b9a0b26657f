/// @file The zero entries of a generated function's output arrays as one fill loop: a robot's
/// jacobian_input, linearization and drawn shapes wrote dozens of `B[12] = T(0);` lines each.
#pragma once

#include <string>

namespace eomgen {

/// `body` with the lines `  X[k] = T(0);` of each output array X of `signature` (a `T* X`
/// parameter) replaced by `for (std::size_t i = 0; i < N; ++i) X[i] = T(0);` at the top, when there
/// are more than `entries_by_lines_up_to` of them and every line that mentions X before the last of
/// them assigns one entry of it, each entry once (so that filling first changes nothing).
std::string with_zero_fills(const std::string& signature, const std::string& body);

/// The number of zero entries of an array written line by line, as the matrix they are, before
/// they become a loop.
inline constexpr std::size_t entries_by_lines_up_to = 36;

}  // namespace eomgen
