/// @file UTF-8 validation with the place of the first bad byte, so that a
/// file saved in another encoding is named precisely.
#pragma once

#include <optional>
#include <string>

namespace eomgen {

struct TextPosition {
  int line;
  int column;
};

/// The position of the first byte that is not valid UTF-8, if any.
std::optional<TextPosition> first_invalid_utf8(const std::string& text);

}  // namespace eomgen
