#include "import/frame_elements.hpp"

#include <set>
#include <vector>

#include "import/xml_text.hpp"

namespace eomgen {

namespace {

// one tag of the text: its element, where it starts and ends, and whether it opens, closes or is
// both (<x/>)
struct Tag {
  std::string name;
  std::size_t start = 0, end = 0;
  bool closing = false, empty = false;
};

// the text's tags in order, outside comments and <?...?> declarations
std::vector<Tag> tags_of(const std::string& text) {
  std::vector<Tag> tags;
  for (std::size_t at = text.find('<'); at != std::string::npos; at = text.find('<', at + 1)) {
    if (text.compare(at, 4, "<!--") == 0) {
      at = text.find("-->", at);
      if (at == std::string::npos) break;
      continue;
    }
    std::size_t end = past_tag(text, at);
    if (end == std::string::npos) break;
    if (text[at + 1] == '?' || text[at + 1] == '!') continue;
    Tag t;
    t.closing = text[at + 1] == '/';
    std::size_t from = at + (t.closing ? 2 : 1), to = text.find_first_of(" \t\r\n/>", from);
    t.name = text.substr(from, to - from);
    t.start = at, t.end = end, t.empty = !t.closing && text[end - 2] == '/';
    tags.push_back(t);
  }
  return tags;
}

}  // namespace

bool refuses_frame_element(const std::string& mujoco_error) {
  return mujoco_error.find("unrecognized element") != std::string::npos && mujoco_error.find("Element 'frame'") != std::string::npos;
}

int frame_elements(const std::string& mjcf) {
  int n = 0;
  for (const Tag& t : tags_of(mjcf)) n += !t.closing && t.name == "frame";
  return n;
}

std::optional<std::string> with_frames_as_bodies(const std::string& mjcf) {
  std::vector<Tag> tags = tags_of(mjcf);
  bool geoms_always_weigh = false;
  for (const Tag& t : tags)
    if (!t.closing && t.name == "compiler")
      geoms_always_weigh = geoms_always_weigh || attribute(mjcf, t.start, t.end, "inertiafromgeom").value_or("") == "true";
  // the bodies that state their <inertial>, and for each frame the body around it (its tag, or none)
  std::set<std::size_t> stated;
  std::vector<std::size_t> open;  // tags of the open elements
  std::vector<std::pair<std::size_t, long>> frames;  // a frame's tag and the body's around it, or −1
  for (std::size_t k = 0; k < tags.size(); ++k) {
    const Tag& t = tags[k];
    if (t.closing) {
      if (!open.empty()) open.pop_back();
      continue;
    }
    if (!open.empty() && tags[open.back()].name == "frame" &&
        (t.name == "joint" || t.name == "freejoint" || t.name == "inertial"))
      return std::nullopt;
    if (t.name == "inertial" && !open.empty() && tags[open.back()].name == "body") stated.insert(open.back());
    if (t.name == "frame") {
      long around = -1;
      for (auto up = open.rbegin(); up != open.rend(); ++up)
        if (tags[*up].name == "body" || tags[*up].name == "worldbody") {
          around = tags[*up].name == "body" ? long(*up) : -1;
          break;
        }
      frames.emplace_back(k, around);
    }
    if (!t.empty) open.push_back(k);
  }
  if (frames.empty()) return mjcf;
  // the frames whose welded bodies weigh nothing: those in a body that states its <inertial>, or in the world
  std::set<std::size_t> weightless;
  for (const auto& [tag, around] : frames)
    if (!geoms_always_weigh && (around < 0 || stated.count(std::size_t(around)) > 0)) weightless.insert(tag);
  // from the back, so that the tags' places stay valid
  std::string text = mjcf;
  for (std::size_t k = tags.size(); k-- > 0;) {
    const Tag& t = tags[k];
    if (t.name != "frame") continue;
    if (t.closing) {
      text.replace(t.start, t.end - t.start, "</body>");
      continue;
    }
    std::string opening = text.substr(t.start, t.end - t.start);
    if (auto name = attribute_span(opening, 0, opening.size(), "name")) opening.erase(name->first, name->second - name->first);
    opening.replace(1, 5, "body");
    if (weightless.count(k) > 0 && !t.empty) opening += "<inertial pos=\"0 0 0\" mass=\"0\" diaginertia=\"0 0 0\"/>";
    text.replace(t.start, t.end - t.start, opening);
  }
  return text;
}

}  // namespace eomgen
