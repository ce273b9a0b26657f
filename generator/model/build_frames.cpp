#include <fmt/format.h>

#include "model/frame_joints.hpp"
#include "model/model_builder.hpp"
#include "model/recursive_frames.hpp"

namespace eomgen {

using GiNaC::ex;

void ModelBuilder::read_frames() {
  for (const FrameEntry& f : f_.frames) {
    if (f.name.empty()) continue;  // reported by the parser
    if (!is_identifier(f.name) || f.name == "inertial") {
      d_.error(f.where, f.key + ".name", fmt::format("'{}' cannot name a frame", f.name),
               "use letters, digits and _; \"inertial\" is the inertial frame");
      continue;
    }
    const PlacedFrame* parent = frame(f.parent, f.parent_where, f.key + ".parent");
    if (!parent) continue;
    Rotation relative = rotation(f.rotation);
    Vector3 origin = f.origin.empty() ? Vector3{0, 0, 0} : vector(f.origin, allow_configuration, "a position");
    std::optional<FrameLink::Joint> joint;
    if (is_constant_placement(relative, origin)) {
      joint = FrameLink::Joint{};
      joint->placement = relative.matrix;
      joint->placement_origin = origin;
    }
    if (f.joint) {
      auto moved = move_by_joint(*f.joint, relative, origin);
      if (joint && moved) {
        moved->placement = joint->placement;
        moved->placement_origin = joint->placement_origin;
      }
      joint = joint ? moved : std::nullopt;
    }
    if (frames_.count(f.name)) {
      d_.error(f.where, f.key + ".name", fmt::format("two frames are named '{}'", f.name), "give each frame its own name");
      continue;
    }
    if (!m_.recursive_kinematics) {
      frames_.emplace(f.name, place_frame(*parent, relative, origin));
      continue;
    }
    if (moves_with_time(relative.matrix, origin, m_.symbols.time))
      d_.error(f.where, f.key, fmt::format("frame '{}' moves with time t itself", f.name),
               "frames derived link by link (the model's ball or free joints need it) are placed by the coordinates "
               "alone: make the prescribed motion a coordinate");
    if (reading_ == FrameReading::tree && !joint && !f.joint)
      if (auto links = frame_as_joints(relative, origin, m_.symbols)) {
        frames_.emplace(f.name, place_joint_links(f.name, link_of(f.parent), *links));
        continue;
      }
    frame_index_[f.name] = int(m_.frame_links.size());
    frames_.emplace(f.name, place_recursive_frame(m_, f.name, link_of(f.parent), relative, origin));
    m_.frame_links.back().joint = joint;
  }
}

// a universal joint's first turns, or a gantry's slides, are massless links of their own, the
// frame (or a body's link, `name`) the last
PlacedFrame ModelBuilder::place_joint_links(const std::string& name, int parent_link, const std::vector<JointLink>& links) {
  for (std::size_t k = 0; k + 1 < links.size(); ++k) {
    place_recursive_frame(m_, unused_link_name(fmt::format("{}_turn{}", name, k + 1)), parent_link, links[k].relative,
                          links[k].origin);
    m_.frame_links.back().joint = links[k].joint;
    parent_link = int(m_.frame_links.size()) - 1;
  }
  frame_index_[name] = int(m_.frame_links.size());
  PlacedFrame placed = place_recursive_frame(m_, name, parent_link, links.back().relative, links.back().origin);
  m_.frame_links.back().joint = links.back().joint;
  return placed;
}

// `name`, or with more underscores before its last part while a frame or link has it
std::string ModelBuilder::unused_link_name(std::string name) const {
  auto taken = [&](const std::string& n) {
    for (const FrameEntry& f : f_.frames)
      if (f.name == n) return true;
    for (const FrameLink& l : m_.frame_links)
      if (l.name == n) return true;
    return false;
  };
  std::size_t last = name.rfind('_');
  while (taken(name)) name.insert(last == std::string::npos ? name.size() : last, "_");
  return name;
}

int ModelBuilder::link_of(const std::string& name) const {
  auto found = frame_index_.find(name);
  return found == frame_index_.end() ? -1 : found->second;
}

FramePlacement ModelBuilder::placement(const std::string& frame_name, const Vector3& local, const Rotation& relative,
                                     const SourceLocation& where, const std::string& key) {
  FramePlacement p;
  if (!m_.recursive_kinematics) return p;
  if (frame_name.empty() && uses_frames(local, m_.intermediates))
    d_.error(where, key, "with recursive kinematics a body is placed in a frame, not through a point of one",
             "give the body frame = \"...\" and its centre in that frame's coordinates");
  else if (!frame_name.empty() && moves_with_time(relative.matrix, local, m_.symbols.time))
    d_.error(where, key, "with recursive kinematics a body in a frame moves with the coordinates alone, not with t",
             "make the prescribed motion a coordinate");
  p.frame = link_of(frame_name);
  p.local = local;
  p.sequence = relative.sequence;
  p.relative = relative.matrix;
  return p;
}

const PlacedFrame* ModelBuilder::frame(const std::string& name, const SourceLocation& where, const std::string& key) {
  static const PlacedFrame inertial = inertial_frame();
  if (name.empty()) return &inertial;
  auto found = frames_.find(name);
  if (found != frames_.end()) return &found->second;
  std::vector<std::string> names{"inertial"};
  for (const FrameEntry& f : f_.frames) names.push_back(f.name);
  bool later = std::find(names.begin(), names.end(), name) != names.end();
  d_.error(where, key, fmt::format("'{}' is not a frame{}", name, later ? " yet: [[frames]] are read from the top" : ""),
           later ? "move the parent frame above the frames and bodies that use it" : suggest(name, names, "frames"));
  return nullptr;
}

void ModelBuilder::read_points() {
  for (const PointEntry& p : f_.points) {
    const PlacedFrame* in = frame(p.frame, p.frame_where, p.key + ".frame");
    if (!in || p.name.empty()) continue;
    Vector3 at = place_point(*in, vector(p.position, allow_configuration, "a position"));
    define_whole(p.name, p.where, p.key + ".name", {at[0], at[1], at[2]});
    placed_points_.push_back({p.name, at, in->rotation.matrix, p.frame});
  }
}

}  // namespace eomgen
