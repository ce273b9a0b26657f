// The self-contained HTML page of an animation: three.js and its orbit controls from Debian's
// libjs-three, the recorded poses (base64 of float32, relative to the scene's centre, so that a
// satellite 7e6 m out still moves smoothly), and the player (animation_page.html, embedded).
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "report/animation.hpp"

namespace eomgen::runtime {

extern const char* const animation_page_text;

namespace {

std::string base64(const void* data, std::size_t bytes) {
  static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const auto* in = static_cast<const unsigned char*>(data);
  std::string out;
  out.reserve((bytes + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes; i += 3) {
    std::uint32_t v = std::uint32_t(in[i]) << 16;
    if (i + 1 < bytes) v |= std::uint32_t(in[i + 1]) << 8;
    if (i + 2 < bytes) v |= in[i + 2];
    out += digits[(v >> 18) & 63], out += digits[(v >> 12) & 63];
    out += i + 1 < bytes ? digits[(v >> 6) & 63] : '=';
    out += i + 2 < bytes ? digits[v & 63] : '=';
  }
  return out;
}

// a JSON string that is also safe inside <script>: no "</" can close it
std::string json_text(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\', out += c;
    else if (c == '<') out += "\\u003c";
    else if (static_cast<unsigned char>(c) < 0x20) out += fmt::format("\\u{:04x}", int(c));
    else out += c;
  }
  return out + "\"";
}

std::string json_numbers(const double* v, std::size_t n) {
  std::string out = "[";
  for (std::size_t i = 0; i < n; ++i) out += fmt::format("{}{:.9g}", i ? "," : "", std::isfinite(v[i]) ? v[i] + 0.0 : 0.0);
  return out + "]";
}

const char* kind_name(int kind) {
  static const char* const names[] = {"frame", "particle", "rigid_body", "point"};
  return kind >= 0 && kind < 4 ? names[kind] : "frame";
}

std::string bodies_json(const eomgen_model_abi& m, const std::vector<double>& p) {
  static const char* const types[] = {"sphere", "box", "capsule", "cylinder", "ellipsoid"};
  std::vector<double> shapes(18 * m.num_drawn_shapes);
  if (m.num_drawn_shapes) m.drawn_shapes(p.data(), shapes.data());
  std::string out = "[";
  for (std::size_t b = 0; b < m.num_drawn_bodies; ++b) {
    std::string list;
    for (std::size_t k = 0; k < m.num_drawn_shapes; ++k) {
      if (m.drawn_shape_bodies[k] != int(b)) continue;
      const double* s = &shapes[18 * k];
      int type = m.drawn_shape_types[k];
      list += fmt::format("{}{{\"type\":\"{}\",\"size\":{},\"offset\":{},\"axis\":{},\"rotation\":{}}}", list.empty() ? "" : ",",
                          types[type >= 0 && type < 5 ? type : 0], json_numbers(s, 3), json_numbers(s + 3, 3), json_numbers(s + 6, 3),
                          json_numbers(s + 9, 9));
    }
    out += fmt::format("{}{{\"name\":{},\"kind\":\"{}\",\"shapes\":[{}]}}", b ? "," : "", json_text(m.drawn_body_names[b]),
                       kind_name(m.drawn_body_kinds[b]), list);
  }
  return out + "]";
}

// each frame's bodies: x, y, z (from the centre), then the quaternion as three.js orders it (x, y, z, w)
std::string poses_base64(const AnimationRecorder& r, const AnimationScene& scene, std::string& error) {
  std::size_t nb = r.model().num_drawn_bodies;
  std::vector<float> out;
  out.reserve(r.frames() * nb * 7);
  for (std::size_t f = 0; f < r.frames(); ++f)
    for (std::size_t b = 0; b < nb; ++b) {
      const double* pose = r.pose(f, b);
      for (int i = 0; i < 12; ++i)
        if (!std::isfinite(pose[i]) && error.empty())
          error = fmt::format("the pose of {} is not finite at t = {:g}", r.model().drawn_body_names[b], r.times()[f]);
      auto q = rotation_quaternion(pose + 3);
      for (int i = 0; i < 3; ++i) out.push_back(float(pose[i] - scene.center[std::size_t(i)]));
      out.push_back(float(q[1])), out.push_back(float(q[2])), out.push_back(float(q[3])), out.push_back(float(q[0]));
    }
  return base64(out.data(), out.size() * sizeof(float));
}

std::string read_whole(const char* path, std::string& error) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in || text.str().empty())
    error = fmt::format("cannot read {}: the animation inlines three.js from Debian's libjs-three (apt-get install libjs-three)", path);
  return text.str();
}

void put(std::string& page, const std::string& placeholder, const std::string& text) {
  std::size_t at = page.find(placeholder);
  if (at != std::string::npos) page.replace(at, placeholder.size(), text);
}

}  // namespace

std::string animation_page(const AnimationRecorder& r, const AnimationSettings& settings, std::string& error) {
  const eomgen_model_abi& m = r.model();
  if (m.num_drawn_bodies == 0)
    return error = fmt::format("{} has no frames, particles or rigid bodies to draw", m.name), "";
  if (r.frames() == 0) return error = "the run has no output rows to animate", "";
  std::string trace;
  for (const std::string& name : settings.trace) {
    std::size_t b = 0;
    while (b < m.num_drawn_bodies && name != m.drawn_body_names[b]) ++b;
    if (b == m.num_drawn_bodies) {
      std::string names;
      for (std::size_t k = 0; k < m.num_drawn_bodies; ++k) names += (k ? ", " : "") + std::string(m.drawn_body_names[k]);
      return error = fmt::format("--trace {}: the model draws no such body or point (it draws {})", name, names), "";
    }
    trace += (trace.empty() ? "" : ",") + std::to_string(b);
  }
  AnimationScene scene = animation_scene(r);
  std::string poses = poses_base64(r, scene, error);
  std::string three = read_whole(EOMGEN_THREE_JS, error), orbit = read_whole(EOMGEN_ORBIT_CONTROLS_JS, error);
  if (!error.empty()) return "";
  std::string rods;
  for (const auto& rod : scene.rods) rods += fmt::format("{}[{},{}]", rods.empty() ? "" : ",", rod[0], rod[1]);
  double ground[3] = {-scene.center[0], -scene.center[1], -scene.center[2]};
  std::string data = fmt::format(
      "{{\"title\":{},\"model\":{},\"bodies\":{},\"rods\":[{}],\"center\":{},\"ground\":{},\"radius\":{:.9g},"
      "\"view\":{},\"up\":{},\"gravity\":{},\"grid\":{},\"follow\":{},\"extent\":{:.9g},\"floor\":{:.9g},"
      "\"trace\":[{}],\"axes\":{},\"times\":\"{}\",\"poses\":\"{}\"}}",
      json_text(settings.title), json_text(m.name), bodies_json(m, r.parameters()), rods, json_numbers(scene.center.data(), 3),
      json_numbers(ground, 3), scene.radius, json_numbers(scene.view.data(), 3), json_numbers(scene.up.data(), 3),
      json_numbers(scene.gravity.data(), 3), !scene.planar && std::hypot(scene.gravity[0], scene.gravity[1], scene.gravity[2]) > 0,
      scene.follow, scene.extent, scene.floor, trace, settings.axes, base64(r.times().data(), r.times().size() * sizeof(double)), poses);
  std::string page = animation_page_text;
  std::string title = settings.title;
  for (auto [from, to] : {std::pair<char, const char*>{'&', "&amp;"}, {'<', "&lt;"}, {'>', "&gt;"}})
    for (std::size_t at = title.find(from); at != std::string::npos; at = title.find(from, at + std::strlen(to)))
      title.replace(at, 1, to);
  put(page, "%%EOMGEN_TITLE%%", title);
  put(page, "%%EOMGEN_DATA%%", data);
  put(page, "%%EOMGEN_ORBIT_CONTROLS%%", orbit);
  put(page, "%%EOMGEN_THREE%%", three);
  return page;
}

}  // namespace eomgen::runtime
