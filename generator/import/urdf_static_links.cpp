#include "import/urdf_static_links.hpp"

#include <algorithm>
#include <cctype>

namespace eomgen {

namespace {

// where the first element of this name opens, outside comments and declarations (npos: none)
std::size_t element_start(const std::string& text, const std::string& name) {
  for (std::size_t at = text.find('<'); at != std::string::npos; at = text.find('<', at + 1)) {
    if (text.compare(at, 4, "<!--") == 0) {
      at = text.find("-->", at);
      if (at == std::string::npos) return at;
      continue;
    }
    std::size_t end = at + 1 + name.size();
    if (text.compare(at + 1, name.size(), name) == 0 && end < text.size() &&
        (std::isspace(static_cast<unsigned char>(text[end])) || text[end] == '>' || text[end] == '/'))
      return at;
  }
  return std::string::npos;
}

// just past the '>' that closes the tag opening at `start`
std::size_t past_tag(const std::string& text, std::size_t start) {
  std::size_t end = text.find('>', start);
  return end == std::string::npos ? end : end + 1;
}

}  // namespace

bool is_urdf_path(const std::string& path) {
  if (path.size() < 5) return false;
  std::string tail = path.substr(path.size() - 5);
  std::transform(tail.begin(), tail.end(), tail.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return tail == ".urdf";
}

std::string with_static_links_kept(const std::string& urdf) {
  std::string text = urdf;
  std::size_t robot = element_start(text, "robot");
  if (robot == std::string::npos || text.find("fusestatic") != std::string::npos) return text;
  std::size_t mujoco = element_start(text, "mujoco");
  if (mujoco == std::string::npos) {
    std::size_t inside = past_tag(text, robot);
    if (inside != std::string::npos && text[inside - 2] != '/')
      text.insert(inside, "<mujoco><compiler fusestatic=\"false\"/></mujoco>");
    return text;
  }
  std::size_t compiler = element_start(text.substr(0, text.find("</mujoco", mujoco)), "compiler");
  if (compiler != std::string::npos && compiler > mujoco) {
    text.insert(compiler + 9, " fusestatic=\"false\"");
    return text;
  }
  std::size_t inside = past_tag(text, mujoco);
  if (inside != std::string::npos && text[inside - 2] != '/') text.insert(inside, "<compiler fusestatic=\"false\"/>");
  return text;
}

}  // namespace eomgen
