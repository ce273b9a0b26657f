#include "import/keyframe_text.hpp"

#include <algorithm>
#include <cctype>

#include "import/xml_text.hpp"

namespace eomgen {

bool refuses_keyframe_length(const std::string& mujoco_error) {
  return mujoco_error.find("key ") != std::string::npos && mujoco_error.find("size, expected length") != std::string::npos;
}

std::string with_keyframe_values_trimmed(const std::string& mjcf) {
  std::string text = mjcf;
  for (std::size_t at = element_start(text, "key"); at != std::string::npos; at = element_start(text, "key", at + 1)) {
    std::size_t end = past_tag(text, at);
    if (end == std::string::npos) break;
    // each quoted value of the tag: its trailing white space moved behind the closing quote
    for (std::size_t open = text.find_first_of("\"'", at); open != std::string::npos && open < end;
         open = text.find_first_of("\"'", open + 1)) {
      std::size_t close = text.find(text[open], open + 1);
      if (close == std::string::npos || close >= end) break;
      std::size_t last = close;
      while (last > open + 1 && std::isspace(static_cast<unsigned char>(text[last - 1]))) --last;
      std::string space = text.substr(last, close - last);
      std::string breaks(std::size_t(std::count(space.begin(), space.end(), '\n')), '\n');
      text.replace(last, close + 1 - last, std::string(1, text[open]) + (breaks.empty() ? "" : breaks));
      end -= space.size() - breaks.size();
      open = last + breaks.size();
    }
  }
  return text;
}

}  // namespace eomgen
