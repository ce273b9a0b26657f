// The layout of an imported model file: the bodies in tree order, each as a frame per joint (the
// first placed by the body's position and quaternion, each further one by nothing, as MJCF applies
// a body's joints one after the other) and a rigid body in the last; a hinge is a revolute joint,
// a slide a prismatic one, ball and free joints keep their names. Armature, damping and stiffness
// go into [energy] as ½ a q'², ½ d q'² and ½ k (q − q_spring)² (a ball's damping as ½ d |ω|² =
// 2 d |q'|² in its quaternion's rates, its stiffness as ½ k θ² of its turn from the spring's rest);
// a motor is an input whose generalized force is gain × u.
#include "import/model_writer.hpp"

#include "emit/formats.hpp"
#include "import/joint_followers.hpp"
#include "import/model_sections.hpp"
#include "import/transmission_text.hpp"
#include "import/mjcf_reader.hpp"
#include "import/mujoco_loading.hpp"
#include "import/right_angles.hpp"
#include "import/urdf_text.hpp"
#include "import/warning_lines.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <variant>
#include <map>
#include <set>
#include <utility>

#include <fmt/format.h>

namespace eomgen {

namespace {


std::string vector_text(const Triple& v) { return fmt::format("[\"{}\", \"{}\", \"{}\"]", format_number(v[0]), format_number(v[1]), format_number(v[2])); }

// a right angle to the last digit (import/right_angles.hpp) is written exactly, no turn at all left out
bool is_identity(const Quaternion& q) {
  auto turn = right_angle_turn(q);
  return (q[0] == 1 && q[1] == 0 && q[2] == 0 && q[3] == 0) || (turn && *turn == std::array<int, 4>{1, 0, 0, 0});
}

std::string rotation_text(const Quaternion& q) {
  if (auto turn = right_angle_turn(q)) return fmt::format("quat({}, {}, {}, {})", (*turn)[0], (*turn)[1], (*turn)[2], (*turn)[3]);
  return fmt::format("quat({}, {}, {}, {})", format_number(q[0]), format_number(q[1]), format_number(q[2]), format_number(q[3]));
}

JointSymbols symbols_of(const RobotJoint& j, const std::string& base, Names& names) {
  JointSymbols s;
  if (j.type == "free")
    for (const char* c : {"x", "y", "z"}) s.coordinates.push_back(names.take(base + "_" + c));
  if (j.type == "free" || j.type == "ball") {
    for (const char* c : {"qw", "qx", "qy", "qz"}) s.coordinates.push_back(names.take(base + "_" + c));
    for (const char* c : {"wx", "wy", "wz"}) s.angular.push_back(names.take(base + "_" + c));
  } else {
    s.coordinates.push_back(names.take(base));
  }
  return s;
}

std::string names_list(const std::vector<std::string>& names, std::size_t from, std::size_t count) {
  std::string out;
  for (std::size_t i = from; i < from + count; ++i) out += (out.empty() ? "\"" : ", \"") + names[i] + "\"";
  return "[" + out + "]";
}

std::string joint_text(const RobotJoint& j, const JointSymbols& s) {
  if (j.type == "hinge" || j.type == "slide") {
    bool anchored = j.type == "hinge" && (j.anchor[0] != 0 || j.anchor[1] != 0 || j.anchor[2] != 0);
    std::string follows = s.follows() && s.multiplier != 1 ? ", multiplier = " + format_number(s.multiplier) : "";
    if (s.follows() && s.offset != 0) follows += ", offset = " + format_number(s.offset);
    return fmt::format("{{ type = \"{}\", axis = {}{}, coordinate = \"{}\"{} }}", j.type == "hinge" ? "revolute" : "prismatic",
                       vector_text(j.axis), anchored ? ", anchor = " + vector_text(j.anchor) : "",
                       s.follows() ? s.leader : s.coordinates[0], follows);
  }
  bool free = j.type == "free";
  std::size_t q = free ? 3 : 0, v = free ? 3 : 0;
  std::string w0;
  for (std::size_t k = 0; k < 3; ++k) w0 += (k ? ", " : "") + format_number(j.initial_velocity[v + k]);
  return fmt::format("{{ type = \"{}\"{}{}, quaternion = {}, angular_velocity = {}, initial_angular_velocity = [{}] }}", j.type,
                     free ? ", position = " + names_list(s.coordinates, 0, 3) : "",
                     !free && (j.anchor[0] != 0 || j.anchor[1] != 0 || j.anchor[2] != 0) ? ", anchor = " + vector_text(j.anchor) : "",
                     names_list(s.coordinates, q, 4), names_list(s.angular, 0, 3), w0);
}


// the coordinates' lines: initial values, rates of hinges, slides and a free joint's position
void add_coordinates(const RobotJoint& j, const JointSymbols& s, Sections& out) {
  if (s.follows()) return;
  for (std::size_t k = 0; k < s.coordinates.size(); ++k) {
    bool rated = (j.type == "hinge" || j.type == "slide" || (j.type == "free" && k < 3)) && j.initial_velocity[k] != 0;
    std::string line = rated ? fmt::format("{} = {{ initial = {}, rate = {} }}", s.coordinates[k], format_number(j.initial_position[k]),
                                           format_number(j.initial_velocity[k]))
                             : fmt::format("{} = {}", s.coordinates[k], format_number(j.initial_position[k]));
    if (j.limited && s.coordinates.size() == 1)
      line += fmt::format("  # range [{}, {}] in the file: not enforced", format_number(j.range[0]), format_number(j.range[1]));
    out.coordinates += line + "\n";
  }
}

// Σ c_k name_k as text, the terms of a zero coefficient left out ("0" if every one is)
std::string linear_text(const std::array<double, 4>& c, const std::array<std::string, 4>& names) {
  std::string out;
  for (std::size_t k = 0; k < 4; ++k) {
    if (c[k] == 0) continue;
    std::string size = std::abs(c[k]) == 1 ? names[k] : format_number(std::abs(c[k])) + "*" + names[k];
    out += out.empty() ? (c[k] < 0 ? "-" : "") + size : (c[k] < 0 ? " - " : " + ") + size;
  }
  return out.empty() ? "0" : out;
}

Quaternion product(const Quaternion& a, const Quaternion& b);

// MuJoCo's spring on a ball joint or a free joint's turn: ½ k θ² of the turn conj(q_s) ⊗ q from the
// spring's rest q_s to q, in the body's axes (mju_subQuat); θ² is smooth where the turn vanishes
// (symbolic/rotation_angle.hpp), and its force in ω is MuJoCo's −k θ·axis. `q`: w, x, y, z's names.
std::string turn_spring_text(double stiffness, const Quaternion& rest, const std::array<std::string, 4>& q) {
  Quaternion conjugate{rest[0], -rest[1], -rest[2], -rest[3]};
  // the product is linear in q: component r's coefficient of q_k is that of conj(q_s) ⊗ e_k
  std::array<std::array<double, 4>, 4> rows{};
  for (std::size_t k = 0; k < 4; ++k) {
    Quaternion unit{0, 0, 0, 0};
    unit[k] = 1;
    Quaternion column = product(conjugate, unit);
    for (std::size_t r = 0; r < 4; ++r) rows[r][k] = column[r];
  }
  return fmt::format("{}*rotation_angle({}, {}, {}, {})^2", format_number(stiffness), linear_text(rows[0], q),
                     linear_text(rows[1], q), linear_text(rows[2], q), linear_text(rows[3], q));
}

// (name − rest)² as text, name² where the rest is 0
std::string square_from_rest(const std::string& name, double rest) {
  if (rest == 0) return name + "^2";
  return fmt::format("({} {} {})^2", name, rest < 0 ? "+" : "-", format_number(std::abs(rest)));
}

// armature, damping and stiffness of one joint into [energy]
void add_energies(const RobotJoint& j, const JointSymbols& s, Sections& out) {
  const std::vector<std::string>& c = s.coordinates;
  if (j.type == "hinge" || j.type == "slide") {
    if (j.armature != 0) out.kinetic.push_back(fmt::format("{}*{}^2", format_number(j.armature), s.rate()));
    if (j.damping != 0) out.dissipation.push_back(fmt::format("{}*{}^2", format_number(j.damping), s.rate()));
    if (j.stiffness != 0)
      out.potential.push_back(format_number(j.stiffness) + "*" + square_from_rest(s.angle(), j.spring_reference[0]));
    return;
  }
  // MuJoCo's damping d and armature a of each of the joint's velocities: ½ d|v|² and ½ a|v|², where
  // the angular velocity's |ω|² = 4|q'|² for a unit quaternion
  std::size_t q = j.type == "free" ? 3 : 0;
  auto squares = [&](double coefficient, std::vector<std::string>& terms) {
    if (coefficient == 0) return;
    if (q) terms.push_back(fmt::format("{}*(der({})^2 + der({})^2 + der({})^2)", format_number(coefficient), c[0], c[1], c[2]));
    terms.push_back(fmt::format("{}*(der({})^2 + der({})^2 + der({})^2 + der({})^2)", format_number(4 * coefficient), c[q],
                                c[q + 1], c[q + 2], c[q + 3]));
  };
  squares(j.damping, out.dissipation);
  squares(j.armature, out.kinetic);
  if (j.stiffness == 0) return;
  // a free joint's position: ½ k |p − p_s|², as MuJoCo's spring pulls it in the world's axes; a
  // robot that states no rest has its spring slack at the origin and the unturned pose
  std::vector<double> rest = j.spring_reference;
  if (rest.size() < q + 4) rest.assign(q + 4, 0), rest[q] = 1;
  if (q) {
    std::string squares_text;
    for (std::size_t k = 0; k < 3; ++k) squares_text += (k ? " + " : "") + square_from_rest(c[k], rest[k]);
    out.potential.push_back(fmt::format("{}*({})", format_number(j.stiffness), squares_text));
  }
  out.potential.push_back(turn_spring_text(j.stiffness, {rest[q], rest[q + 1], rest[q + 2], rest[q + 3]},
                                           {c[q], c[q + 1], c[q + 2], c[q + 3]}));
}

// v turned by the unit quaternion q (w, x, y, z): v + 2w (u × v) + 2 u × (u × v), u = (x, y, z)
Triple turned(const Quaternion& q, const Triple& v) {
  Triple u{q[1], q[2], q[3]};
  auto cross = [](const Triple& a, const Triple& b) {
    return Triple{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  Triple c = cross(u, v), d = cross(u, c);
  return {v[0] + 2 * (q[0] * c[0] + d[0]), v[1] + 2 * (q[0] * c[1] + d[1]), v[2] + 2 * (q[0] * c[2] + d[2])};
}

// the Hamilton product a ⊗ b: turning by b, then by a
Quaternion product(const Quaternion& a, const Quaternion& b) {
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3], a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1], a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}

// MuJoCo turns a hinge by qpos − qpos0 and moves a slide by it: the placement (origin, rotation)
// at q = 0 is the body's at qpos0 turned back by the reference about the axis through the anchor
// (origin + R(anchor − R_ref anchor), R R_ref, R_ref by −reference), or moved back along the axis
void at_reference(const RobotJoint& j, Triple& origin, Quaternion& rotation) {
  if (j.reference == 0 || (j.type != "hinge" && j.type != "slide")) return;
  if (j.type == "slide") {
    Triple back = turned(rotation, j.axis);
    for (std::size_t a = 0; a < 3; ++a) origin[a] -= j.reference * back[a];
    return;
  }
  double half = -j.reference / 2, s = std::sin(half);
  Quaternion turn{std::cos(half), s * j.axis[0], s * j.axis[1], s * j.axis[2]};
  Triple moved = turned(turn, j.anchor);
  Triple shift = turned(rotation, {j.anchor[0] - moved[0], j.anchor[1] - moved[1], j.anchor[2] - moved[2]});
  for (std::size_t a = 0; a < 3; ++a) origin[a] += shift[a];
  rotation = product(rotation, turn);
}

// the body's geoms as its frame's shapes (MuJoCo's half sizes become radii, lengths and sides, a
// geom's quaternion a capsule's axis or a box's or ellipsoid's rotation); what a shape cannot be is said
std::string shapes_text(const RobotBody& body, Sections& out) {
  std::vector<std::string> shapes;
  for (const RobotGeom& g : body.geoms) {
    std::string offset = g.position == Triple{0, 0, 0} ? "" : ", offset = " + vector_text(g.position);
    std::string turned_by = is_identity(g.orientation) ? "" : ", rotation = \"" + rotation_text(g.orientation) + "\"";
    if (g.type == "sphere") {
      shapes.push_back(fmt::format("{{ type = \"sphere\", size = [\"{}\"]{} }}", format_number(g.size[0]), offset));
    } else if (g.type == "ellipsoid") {
      shapes.push_back(fmt::format("{{ type = \"ellipsoid\", size = {}{}{} }}", vector_text(g.size), offset, turned_by));
    } else if (g.type == "capsule" || g.type == "cylinder") {
      Triple axis = turned(g.orientation, {0, 0, 1});
      std::string along = axis == Triple{0, 0, 1} ? "" : ", axis = " + vector_text(axis);
      shapes.push_back(fmt::format("{{ type = \"{}\", size = [\"{}\", \"{}\"]{}{} }}", g.type, format_number(g.size[0]), format_number(2 * g.size[1]),
                                   offset, along));
    } else if (g.type == "box") {
      shapes.push_back(fmt::format("{{ type = \"box\", size = [\"{}\", \"{}\", \"{}\"]{}{} }}", format_number(2 * g.size[0]),
                                   format_number(2 * g.size[1]), format_number(2 * g.size[2]), offset, turned_by));
    } else {
      out.warnings.push_back(fmt::format("body '{}': a {} geom is not drawn by `eomgen animate`", body.name, g.type));
    }
  }
  if (shapes.empty()) return "";
  if (shapes.size() == 1) return "shape = " + shapes[0] + "\n";
  std::string list;
  for (const std::string& s : shapes) list += (list.empty() ? "" : ",\n         ") + s;
  return "shape = [" + list + "]\n";
}

// every joint's symbols, bodies in order and their joints in order, named after the joints
std::vector<std::vector<JointSymbols>> all_joint_symbols(const Robot& robot, const std::vector<std::string>& frame_of, Names& names) {
  std::vector<std::vector<JointSymbols>> symbols(robot.bodies.size());
  for (std::size_t b = 0; b < robot.bodies.size(); ++b)
    for (std::size_t k = 0; k < robot.bodies[b].joints.size(); ++k) {
      const RobotJoint& j = robot.bodies[b].joints[k];
      symbols[b].push_back(symbols_of(j, j.name.empty() ? fmt::format("{}_q{}", frame_of[b], k + 1) : j.name, names));
    }
  return symbols;
}

// one frame per joint of the body (a body without joints: one fixed frame), its rigid body in the last
void add_body(const Robot& robot, std::size_t b, std::vector<std::string>& frame_of, Sections& out,
              const std::vector<std::vector<JointSymbols>>& joint_symbols) {
  const RobotBody& body = robot.bodies[b];
  std::string frame = frame_of[b], parent = body.parent < 0 ? "" : frame_of[std::size_t(body.parent)];
  std::size_t count = std::max<std::size_t>(1, body.joints.size());
  for (std::size_t k = 0; k < count; ++k) {
    bool last = k + 1 == count;
    std::string name = last ? frame : frame + "_" + identifier_of(body.joints[k].name.empty() ? fmt::format("joint{}", k + 1)
                                                                                              : body.joints[k].name);
    out.frames += "\n[[frames]]\nname = \"" + name + "\"\n";
    if (!parent.empty()) out.frames += "parent = \"" + parent + "\"\n";
    bool free = !body.joints.empty() && body.joints[k].type == "free";  // MuJoCo places a free body by its qpos alone
    Triple origin{0, 0, 0};
    Quaternion rotation{1, 0, 0, 0};
    if (k == 0 && !free) origin = body.position, rotation = body.orientation;
    if (!body.joints.empty()) at_reference(body.joints[k], origin, rotation);
    if (origin != Triple{0, 0, 0}) out.frames += "origin = " + vector_text(origin) + "\n";
    if (!is_identity(rotation)) out.frames += "rotation = \"" + rotation_text(rotation) + "\"\n";
    if (!body.joints.empty()) {
      const RobotJoint& j = body.joints[k];
      std::string base = j.name.empty() ? fmt::format("{}_q{}", frame, k + 1) : j.name;
      const JointSymbols& s = joint_symbols[b][k];
      if (s.follows()) out.frames += fmt::format("# joint '{}' follows the coordinate '{}' (a mimic or linear coupling)\n", base, s.leader);
      out.frames += "joint = " + joint_text(j, s) + "\n";
      add_coordinates(j, s, out);
      add_energies(j, s, out);
    }
    if (last) out.frames += shapes_text(body, out);
    parent = name;
  }
  bool turning_inertia = body.principal_inertia != Triple{0, 0, 0};
  if (body.mass <= 0 && !turning_inertia) return;
  out.bodies += fmt::format("\n[[rigid_bodies]]\nname = \"{}\"\nframe = \"{}\"\nmass = \"{}\"\ncenter = {}\n", frame, frame,
                            format_number(body.mass), vector_text(body.center));
  if (!is_identity(body.inertia_axes)) out.bodies += "rotation = \"" + rotation_text(body.inertia_axes) + "\"\n";
  out.bodies += "inertia = " + vector_text(body.principal_inertia) + "\n";
  // a robot file's inertia that no rigid body has (import/unbalanced_inertias.hpp), kept as it states it
  const Triple& m = body.principal_inertia;
  double largest = std::max({m[0], m[1], m[2]});
  for (std::size_t k = 0; k < 3; ++k)
    if (m[(k + 1) % 3] + m[(k + 2) % 3] - m[k] < -1e-12 * largest || m[k] < 0) {
      out.bodies += "unphysical_inertia = true  # breaks A + B >= C or has a moment below zero, as the robot file states it\n";
      return;
    }
  // a link of mass 0 with a moment of inertia (Bolt's feet): URDF readers keep the moment
  if (body.mass <= 0) out.bodies += "unphysical_inertia = true  # a moment of inertia without mass, as the robot file states it\n";
}

// each keyframe as a scene's initial state: positions and rates, a quaternion's rates from ω,
// q' = ½ q ⊗ (0, ω) (model/quaternion.hpp), since the model's states are named q and der(q)
void add_keyframes(const Robot& robot, const std::vector<std::vector<JointSymbols>>& joint_symbols, Names& names, Sections& out) {
  for (const RobotKeyframe& key : robot.keyframes) {
    std::string initial;
    std::size_t qpos = 0, qvel = 0;
    auto add = [&](const std::string& state, double value) {
      initial += (initial.empty() ? "" : ", ") + fmt::format("\"{}\" = {}", state, format_number(value));
    };
    for (std::size_t b = 0; b < robot.bodies.size(); ++b)
      for (std::size_t k = 0; k < robot.bodies[b].joints.size(); ++k) {
        const std::string& type = robot.bodies[b].joints[k].type;
        const std::vector<std::string>& c = joint_symbols[b][k].coordinates;
        std::size_t moved = type == "free" ? 3 : 0;
        for (std::size_t i = 0; i < moved; ++i) add(c[i], key.positions[qpos + i]), add("der(" + c[i] + ")", key.velocities[qvel + i]);
        if (type == "ball" || type == "free") {
          const double* q = key.positions.data() + qpos + moved;
          const double* w = key.velocities.data() + qvel + moved;
          double rate[4] = {-(q[1] * w[0] + q[2] * w[1] + q[3] * w[2]) / 2, (q[0] * w[0] + q[2] * w[2] - q[3] * w[1]) / 2,
                            (q[0] * w[1] + q[3] * w[0] - q[1] * w[2]) / 2, (q[0] * w[2] + q[1] * w[1] - q[2] * w[0]) / 2};
          for (std::size_t i = 0; i < 4; ++i) add(c[moved + i], q[i]), add("der(" + c[moved + i] + ")", rate[i]);
          qpos += moved + 4, qvel += moved + 3;
        } else if (joint_symbols[b][k].follows()) {
          ++qpos, ++qvel;  // the leader's state sets it
        } else {
          add(c[0], key.positions[qpos++]), add("der(" + c[0] + ")", key.velocities[qvel++]);
        }
      }
    out.scenes += fmt::format("\n[scenes.{}]\ninitial = {{ {} }}\n", names.take(key.name), initial);
  }
}

std::string sum_text(const std::vector<std::string>& terms) {
  std::string out;
  for (const std::string& t : terms) out += (out.empty() ? "" : " + ") + t;
  return "\"(" + out + ")/2\"";
}

}  // namespace

std::optional<std::string> imported_model_text(const std::string& path, Diagnostics& diagnostics, bool in_memory,
                                               std::string name, RobotReading reading) {
  auto read = read_with_mujoco(path, reading);
  bool urdf = is_urdf_file(path);  // the file read once more, not at each message
  if (auto* failure = std::get_if<UnreadableRobot>(&read)) {
    diagnostics.error({failure->file.empty() ? path : failure->file, std::max(failure->line, 1), 1}, "", failure->message,
                      !failure->hint.empty() ? failure->hint
                                             : "MuJoCo " + mj_version_text() + "'s compiler reads the file for eomgen; the file must be " +
                                                   (urdf ? "URDF" : "MJCF") + " that it accepts");
    return std::nullopt;
  }
  const Robot& robot = std::get<Robot>(read);
  // a robot that nothing moves has no equations of motion: said here, not as an empty [coordinates]
  if (std::all_of(robot.bodies.begin(), robot.bodies.end(), [](const RobotBody& b) { return b.joints.empty(); })) {
    diagnostics.error({path, 1, 1}, "", "no joint of the robot moves: it has no coordinates and no equations of motion",
                      urdf ? "a URDF's revolute, continuous, prismatic, planar and floating joints move; "
                                           "fixed ones do not; a body that flies (a drone, a satellite) imports with "
                                           "--free-base"
                                         : "an MJCF body moves by a <joint> or <freejoint> in it");
    return std::nullopt;
  }
  std::string file = std::filesystem::path(path).filename().string();
  if (in_memory)
    std::cerr << fmt::format("eomgen: importing {} in memory ({}); `eomgen import` writes it as a model file\n", file, robot.reader);
  // a URDF includes nothing; an MJCF's warnings may be about an element of a file it includes
  std::vector<std::pair<std::string, std::string>> sources =
      urdf ? std::vector<std::pair<std::string, std::string>>{{path, text_of_file(path)}} : mjcf_sources(path);
  for (const std::string& note : robot.notes) std::cerr << fmt::format("eomgen: note: {}: {}\n", file, note);
  for (const RobotWarning& w : robot.warnings) {
    WarningPlace place = warning_place(sources, w);
    std::cerr << (place.line > 0 ? fmt::format("{}:{}:1: warning: {}\n", place.file, place.line, w.text)
                                 : fmt::format("eomgen: warning: {}: {}\n", file, w.text));
  }
  if (name.empty()) name = identifier_of(robot.name.empty() ? std::filesystem::path(path).stem().string() : robot.name);
  return model_file_text(robot, name, file);
}

std::string identifier_of(const std::string& text) {
  std::string out;
  for (char c : text) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '_') ? c : '_';
  if (out.empty() || std::isdigit(static_cast<unsigned char>(out[0]))) out = "_" + out;
  return out;
}

// a link that only marks a place (fixed, massless, a leaf: a URDF tool flange or a camera mount)
// is also a point of its name at its frame's origin, for outputs and constraints
void add_link_points(const Robot& robot, const std::vector<std::string>& frame_of, Names& names, Sections& out) {
  std::vector<bool> parent(robot.bodies.size(), false);
  for (const RobotBody& b : robot.bodies)
    if (b.parent >= 0) parent[std::size_t(b.parent)] = true;
  for (std::size_t b = 0; b < robot.bodies.size(); ++b) {
    const RobotBody& body = robot.bodies[b];
    if (!body.joints.empty() || body.mass > 0 || parent[b]) continue;
    out.points += fmt::format("\n[[points]]\nname = \"{}\"\nframe = \"{}\"\nposition = [\"0\", \"0\", \"0\"]\n",
                              names.take(body.name), frame_of[b]);
  }
}

// MJCF gravcomp c: a force −c m g at the centre of mass of the body, at a point of its own there
void add_gravity_compensation(const Robot& robot, const std::vector<std::string>& frame_of, Names& names, Sections& out) {
  for (std::size_t b = 0; b < robot.bodies.size(); ++b) {
    const RobotBody& body = robot.bodies[b];
    if (body.gravity_compensation == 0 || body.mass == 0) continue;
    std::string point = names.take(body.name + "_center_of_mass");
    Triple force;
    for (std::size_t k = 0; k < 3; ++k) force[k] = robot.gravity[k] * -(body.mass * body.gravity_compensation);
    out.points += fmt::format("\n[[points]]\nname = \"{}\"\nframe = \"{}\"\nposition = {}\n", point, frame_of[b],
                              vector_text(body.center));
    out.forces += fmt::format("\n[[forces]]  # gravcomp = {}\nat = \"{}\"\nforce = {}\n", format_number(body.gravity_compensation),
                              point, vector_text(force));
  }
}

// each loop as two points, one in each body, and a holonomic constraint per independent world
// component of their distance (MuJoCo's connect is soft, by its solref and solimp; here it is exact)
std::string loop_constraints(const Robot& robot, const std::vector<std::string>& frame_of, Names& names, Sections& out) {
  std::string text;
  for (const RobotLoop& loop : robot.loops) {
    std::string base = identifier_of(loop.name), ends[2];
    int bodies[2] = {loop.body1, loop.body2};
    const Triple* anchors[2] = {&loop.anchor1, &loop.anchor2};
    for (int k = 0; k < 2; ++k) {
      ends[k] = names.take(fmt::format("{}_{}", base, k + 1));
      out.points += fmt::format("\n[[points]]\nname = \"{}\"\n{}position = {}\n", ends[k],
                                bodies[k] < 0 ? "" : "frame = \"" + frame_of[std::size_t(bodies[k])] + "\"\n",
                                vector_text(*anchors[k]));
    }
    for (std::size_t a = 0; a < 3; ++a) {
      const char axis = "xyz"[a];
      if (!loop.kept[a]) {
        text += fmt::format("# {}: its {} component follows from the others at the initial state (left out)\n", base, axis);
        continue;
      }
      text += fmt::format("\n[[constraints]]\nname = \"{}\"\nholonomic = \"{}.{} - {}.{}\"\n", names.take(fmt::format("{}_{}", base, axis)),
                          ends[0], axis, ends[1], axis);
    }
  }
  return text;
}

// q1 − ref1 − (c0 + c1 d + … + c4 d⁴), d = q2 − ref2: MuJoCo's joint coupling, its zero terms left out
std::string coupling_constraints(const Robot& robot, const std::vector<std::vector<JointSymbols>>& joint_symbols,
                                 const std::vector<JointFollower>& followers, Names& names) {
  std::string text;
  std::set<std::size_t> followed;
  for (const JointFollower& f : followers) followed.insert(f.coupling);
  auto shifted = [](const std::string& q, double reference) {
    return reference == 0 ? q : fmt::format("({} - {})", q, format_number(reference));
  };
  for (std::size_t k = 0; k < robot.couplings.size(); ++k) {
    const RobotCoupling& c = robot.couplings[k];
    if (followed.count(k)) continue;
    // (a joint that follows another's coordinate enters by its angle in that coordinate)
    std::string q1 = joint_symbols[std::size_t(c.body1)][std::size_t(c.joint1)].angle();
    std::string expression = c.reference1 == 0 ? q1 : fmt::format("{} - {}", q1, format_number(c.reference1));
    // − c·term, written with the sign c gives it
    auto minus = [](double coefficient, const std::string& term) {
      std::string size = format_number(std::abs(coefficient));
      return fmt::format(" {} {}{}", coefficient < 0 ? "+" : "-", term.empty() ? size : (size == "1" ? "" : size + "*"), term);
    };
    if (c.coefficients[0] != 0) expression += minus(c.coefficients[0], "");
    if (c.body2 >= 0) {
      std::string d = shifted(joint_symbols[std::size_t(c.body2)][std::size_t(c.joint2)].angle(), c.reference2);
      for (std::size_t k = 1; k < 5; ++k)
        if (c.coefficients[k] != 0)
          expression += minus(c.coefficients[k], d + (k == 1 ? "" : fmt::format("^{}", k)));
    }
    text += fmt::format("\n[[constraints]]\nname = \"{}\"\nholonomic = \"{}\"\n", names.take(identifier_of(c.name)), expression);
  }
  return text;
}

std::string model_file_text(const Robot& robot, const std::string& name, const std::string& source) {
  Names names, frames;
  Sections out;
  std::vector<std::string> frame_of;
  for (const RobotBody& b : robot.bodies) frame_of.push_back(frames.take(b.name));
  std::vector<std::vector<JointSymbols>> joint_symbols = all_joint_symbols(robot, frame_of, names);
  std::vector<JointFollower> followers = joint_followers(robot);
  for (const JointFollower& f : followers) {
    JointSymbols& s = joint_symbols[std::size_t(f.body)][std::size_t(f.joint)];
    s.leader = joint_symbols[std::size_t(f.leader_body)][std::size_t(f.leader_joint)].coordinates[0];
    s.multiplier = f.multiplier, s.offset = f.offset;
  }
  for (std::size_t b = 0; b < robot.bodies.size(); ++b) add_body(robot, b, frame_of, out, joint_symbols);
  add_actuators(robot, joint_symbols, names, out);
  add_tendon_springs(robot, joint_symbols, out);
  add_keyframes(robot, joint_symbols, names, out);
  for (const RobotSite& s : robot.sites)
    out.points += fmt::format("\n[[points]]\nname = \"{}\"\n{}position = {}\n", names.take(s.name),
                              s.body < 0 ? "" : "frame = \"" + frame_of[std::size_t(s.body)] + "\"\n", vector_text(s.position));
  add_link_points(robot, frame_of, names, out);
  add_gravity_compensation(robot, frame_of, names, out);
  std::string constraints = loop_constraints(robot, frame_of, names, out) + coupling_constraints(robot, joint_symbols, followers, names);
  std::string text = fmt::format("# Imported from {} by eomgen import ({}); initial state: {}.\n", source, robot.reader,
                                 robot.initial_state);
  for (const std::string& note : robot.notes) text += "# note: " + note + "\n";
  for (const RobotWarning& w : robot.warnings) text += "# not carried: " + w.text + "\n";
  for (const std::string& w : out.warnings) text += "# not carried: " + w + "\n";
  text += fmt::format("\n[model]\nname = \"{}\"\ntitle = \"{} (imported)\"\n", name, robot.name.empty() ? name : robot.name);
  // a loop's constraints take multipliers
  if (!constraints.empty()) text += "method = \"lagrange1\"\n";
  text += "\n[gravity]\nacceleration = " + vector_text(robot.gravity) + "\n";
  if (!out.inputs.empty()) text += "\n[inputs]\n" + out.inputs;
  text += "\n[coordinates]\n" + out.coordinates + out.frames + out.bodies + out.points;
  if (!out.kinetic.empty() || !out.dissipation.empty() || !out.potential.empty()) {
    text += "\n[energy]\n";
    if (!out.kinetic.empty()) text += "kinetic = " + sum_text(out.kinetic) + "\n";
    if (!out.dissipation.empty()) text += "dissipation = " + sum_text(out.dissipation) + "\n";
    if (!out.potential.empty()) text += "potential = " + sum_text(out.potential) + "\n";
  }
  text += out.forces + constraints + out.scenes;
  return text;
}

}  // namespace eomgen
