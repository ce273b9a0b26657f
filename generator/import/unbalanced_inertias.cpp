#include "import/unbalanced_inertias.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>
#include <set>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <fmt/format.h>

#include "import/urdf_text.hpp"
#include "import/xml_text.hpp"

namespace eomgen {

namespace {

double number_attribute(const std::string& text, std::size_t start, std::size_t end, const std::string& name) {
  std::optional<std::string> value = attribute(text, start, end, name);
  return value ? std::strtod(value->c_str(), nullptr) : 0.0;
}

// URDF's rpy: R = Rz(yaw) Ry(pitch) Rx(roll)
Eigen::Matrix3d rotation_of(const Triple& rpy) {
  return (Eigen::AngleAxisd(rpy[2], Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(rpy[1], Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rpy[0], Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

bool unphysical(const Triple& m) {
  return m[0] + m[1] < m[2] || m[0] + m[2] < m[1] || m[1] + m[2] < m[0] || m[0] < 0 || m[1] < 0 || m[2] < 0;
}

// the tensor an <inertial> [start, end) states, turned into the link's frame by its origin's rpy: R I Rᵀ
std::optional<Eigen::Matrix3d> link_frame_tensor(const std::string& urdf, std::size_t start, std::size_t end) {
  std::size_t origin = element_start(urdf, "origin", start), inertia = element_start(urdf, "inertia", start);
  if (inertia == std::string::npos || inertia > end) return std::nullopt;
  Triple rpy{0, 0, 0};
  if (origin != std::string::npos && origin < end) rpy = triple_attribute(urdf, origin, past_tag(urdf, origin), "rpy");
  std::size_t close = past_tag(urdf, inertia);
  auto I = [&](const char* n) { return number_attribute(urdf, inertia, close, n); };
  Eigen::Matrix3d stated;
  stated << I("ixx"), I("ixy"), I("ixz"), I("ixy"), I("iyy"), I("iyz"), I("ixz"), I("iyz"), I("izz");
  Eigen::Matrix3d R = rotation_of(rpy);
  return R * stated * R.transpose();
}

// principal moments and axes to the last digit (MuJoCo's mju_eig3 leaves errors near 1e-8); a
// moment of rounding's size alone (a rank-one dummy inertia's, of either sign) is zero
void set_principal(const Eigen::Matrix3d& tensor, LinkInertia& l) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) l.tensor[std::size_t(3 * r + c)] = tensor(r, c);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(tensor);
  Eigen::Vector3d moments = eigen.eigenvalues();
  Eigen::Matrix3d axes = eigen.eigenvectors();
  if (axes.determinant() < 0) axes.col(2) = -axes.col(2);  // a rotation, not a reflection
  Eigen::Quaterniond q(axes);
  double largest = moments.cwiseAbs().maxCoeff();
  for (int k = 0; k < 3; ++k) l.principal[std::size_t(k)] = std::abs(moments[k]) <= 1e-12 * largest ? 0.0 : moments[k];
  l.axes = {q.w(), q.x(), q.y(), q.z()};
  l.unbalanced = unphysical(l.principal);
}

// the <inertial> of the link whose tag opens at `link`, or nothing
std::optional<LinkInertia> link_inertia(const std::string& urdf, std::size_t link) {
  std::size_t open_end = past_tag(urdf, link);
  if (open_end == std::string::npos || urdf[open_end - 2] == '/') return std::nullopt;
  std::optional<std::string> name = attribute(urdf, link, open_end, "name");
  std::size_t inertial = element_start(urdf, "inertial", open_end);
  if (!name || inertial == std::string::npos || inertial > urdf.find("</link", open_end)) return std::nullopt;
  std::size_t inertial_end = urdf.find("</inertial", inertial);
  std::optional<Eigen::Matrix3d> tensor = link_frame_tensor(urdf, inertial, inertial_end);
  if (!tensor) return std::nullopt;
  LinkInertia l;
  l.link = *name;
  std::size_t mass = element_start(urdf, "mass", inertial), origin = element_start(urdf, "origin", inertial);
  if (mass != std::string::npos && mass < inertial_end) l.mass = number_attribute(urdf, mass, past_tag(urdf, mass), "value");
  if (origin != std::string::npos && origin < inertial_end) l.center = triple_attribute(urdf, origin, past_tag(urdf, origin), "xyz");
  set_principal(*tensor, l);
  return l;
}

// the body that is this link alone, or with the links fixed to it: its mass and centre those (to
// MuJoCo's rounding of the centre it sums, relative to the body's size: its centre's distance or its
// radius of gyration, which the parts' distances set where they balance about the origin)
bool is_body_of(const RobotBody& b, const LinkInertia& l) {
  double size = l.mass > 0 ? std::sqrt(std::max(0.0, (l.tensor[0] + l.tensor[4] + l.tensor[8]) / l.mass)) : 0.0;
  for (std::size_t k = 0; k < 3; ++k) size = std::max({size, std::abs(l.center[k]), std::abs(b.center[k])});
  for (std::size_t k = 0; k < 3; ++k)
    if (std::abs(l.center[k] - b.center[k]) > 1e-9 * size) return false;
  return b.name == l.link && std::abs(l.mass - b.mass) <= 1e-12 * std::abs(l.mass);
}

// a link's mass, centre and tensor in the frame of a link it is fixed to, d = turn·x + shift
struct MassPart {
  std::string link;
  double mass;
  Eigen::Vector3d center;
  Eigen::Matrix3d tensor;
};

// a link and the links that hang from it by fixed joints, in its frame
void collect_fixed(const std::string& link, const Eigen::Matrix3d& turn, const Eigen::Vector3d& shift,
                   const std::map<std::string, const LinkInertia*>& stated, const std::vector<UrdfJoint>& joints,
                   std::vector<MassPart>& parts, std::size_t depth) {
  if (depth > joints.size()) return;  // a cycle, which the import refuses before this
  // a link of mass 0 with a moment of inertia (Bolt's feet) adds its moment
  if (auto l = stated.find(link);
      l != stated.end() && (l->second->mass > 0 || std::any_of(l->second->tensor.begin(), l->second->tensor.end(), [](double v) { return v != 0; }))) {
    Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> I(l->second->tensor.data());
    Eigen::Vector3d c(l->second->center[0], l->second->center[1], l->second->center[2]);
    parts.push_back({link, l->second->mass, turn * c + shift, turn * I * turn.transpose()});
  }
  for (const UrdfJoint& j : joints)
    if (j.parent == link && j.type == "fixed")
      collect_fixed(j.child, turn * rotation_of(j.rpy), turn * Eigen::Vector3d(j.xyz[0], j.xyz[1], j.xyz[2]) + shift, stated,
                    joints, parts, depth + 1);
}

}  // namespace

bool refuses_unbalanced_inertia(const std::string& mujoco_error) {
  return mujoco_error.find("inertia must satisfy A + B >= C") != std::string::npos;
}

std::string with_balanced_inertias(const std::string& urdf) {
  return with_compiler_attributes(urdf, " balanceinertia=\"true\"", {"balanceinertia"});
}

bool refuses_to_fuse_singular_inertias(const std::string& mujoco_error) {
  return mujoco_error.find("inertia must have positive eigenvalues") != std::string::npos &&
         mujoco_error.find("in fusing static body inertias") != std::string::npos;
}

std::string with_positive_moments(const std::string& urdf) {
  std::string text = urdf;
  for (std::size_t at = element_start(text, "link"); at != std::string::npos; at = element_start(text, "link", at + 1)) {
    std::optional<LinkInertia> l = link_inertia(text, at);
    if (!l || std::min({l->principal[0], l->principal[1], l->principal[2]}) > 0) continue;
    // at least the moments of its mass spread over a millimetre (URDF's lengths are metres), as a
    // point mass or moments of rounding's size (1e-35) are not positive to MuJoCo
    double mean = std::max((std::abs(l->principal[0]) + std::abs(l->principal[1]) + std::abs(l->principal[2])) / 3, l->mass * 1e-6);
    if (mean == 0) continue;
    std::size_t inertial = element_start(text, "inertial", at);
    std::size_t inertia = element_start(text, "inertia", inertial), end = past_tag(text, inertia);
    std::string lines(std::size_t(std::count(text.begin() + long(inertia), text.begin() + long(end), '\n')), '\n');
    text.replace(inertia, end - inertia,
                 fmt::format("<inertia ixx=\"{0:.17g}\" ixy=\"0\" ixz=\"0\" iyy=\"{0:.17g}\" iyz=\"0\" izz=\"{0:.17g}\"/>{1}", mean, lines));
  }
  return text;
}

std::vector<LinkInertia> urdf_link_inertias(const std::string& urdf) {
  std::vector<LinkInertia> links;
  for (std::size_t at = element_start(urdf, "link"); at != std::string::npos; at = element_start(urdf, "link", at + 1))
    if (std::optional<LinkInertia> l = link_inertia(urdf, at)) links.push_back(*l);
  return links;
}

std::vector<LinkInertia> urdf_fused_inertias(const std::string& urdf, const std::vector<LinkInertia>& links) {
  std::map<std::string, const LinkInertia*> stated;
  for (const LinkInertia& l : links) stated[l.link] = &l;
  std::vector<UrdfJoint> joints = urdf_joints(urdf);
  std::set<std::string> tops;
  for (const UrdfJoint& j : joints)
    if (j.type == "fixed") tops.insert(j.parent);
  std::vector<LinkInertia> fused;
  for (const std::string& top : tops) {
    std::vector<MassPart> parts;
    collect_fixed(top, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), stated, joints, parts, 0);
    // a massless top (the link a floating base's body is fixed to) takes its one part's inertia
    if (parts.empty() || (parts.size() == 1 && parts[0].link == top)) continue;
    LinkInertia l;
    l.link = top;
    Eigen::Vector3d moment = Eigen::Vector3d::Zero();
    for (const MassPart& p : parts) l.mass += p.mass, moment += p.mass * p.center;
    Eigen::Vector3d c = moment / l.mass;
    Eigen::Matrix3d I = Eigen::Matrix3d::Zero();
    for (const MassPart& p : parts) {
      Eigen::Vector3d d = p.center - c;
      I += p.tensor + p.mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
      if (p.link != top) l.fused.push_back(p.link);
    }
    l.center = {c[0], c[1], c[2]};
    set_principal(I, l);
    fused.push_back(l);
  }
  return fused;
}

StatedInertias with_stated_inertias(std::vector<RobotBody>& bodies, const std::string& urdf) {
  StatedInertias out;
  std::vector<LinkInertia> links = urdf_link_inertias(urdf), fused = urdf_fused_inertias(urdf, links);
  // a link with links fixed to it first: where they add no mass (a foot of mass 0 with a moment of
  // inertia) the link alone has the body's mass and centre too, but not its moment
  std::vector<const LinkInertia*> candidates;
  for (const LinkInertia& l : fused) candidates.push_back(&l);
  for (const LinkInertia& l : links) candidates.push_back(&l);
  std::set<std::string> taken;
  auto is_a_body = [&](const std::string& link) {
    return std::any_of(bodies.begin(), bodies.end(), [&](const RobotBody& b) { return b.name == link; });
  };
  for (const LinkInertia* l : candidates) {
    // fused only where MuJoCo fused: a link kept as a body of its own keeps its own inertia
    if (std::any_of(l->fused.begin(), l->fused.end(), is_a_body)) continue;
    auto body = std::find_if(bodies.begin(), bodies.end(), [&](const RobotBody& b) { return is_body_of(b, *l); });
    if (body == bodies.end() || !taken.insert(l->link).second) continue;
    body->center = l->center;
    body->principal_inertia = l->principal;
    body->inertia_axes = l->axes;
    taken.insert(l->fused.begin(), l->fused.end());
  }
  for (const LinkInertia& l : links)
    if (l.unbalanced) (taken.count(l.link) ? out.given_back : out.left_balanced).push_back(l.link);
  return out;
}

}  // namespace eomgen
