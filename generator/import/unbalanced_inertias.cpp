#include "import/unbalanced_inertias.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <sstream>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "import/xml_text.hpp"

namespace eomgen {

namespace {

double number_attribute(const std::string& text, std::size_t start, std::size_t end, const std::string& name) {
  std::optional<std::string> value = attribute(text, start, end, name);
  return value ? std::strtod(value->c_str(), nullptr) : 0.0;
}

Triple triple_attribute(const std::string& text, std::size_t start, std::size_t end, const std::string& name) {
  Triple t{0, 0, 0};
  if (std::optional<std::string> value = attribute(text, start, end, name)) {
    std::istringstream in(*value);
    in >> t[0] >> t[1] >> t[2];
  }
  return t;
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
  std::size_t mass = element_start(urdf, "mass", inertial);
  if (mass != std::string::npos && mass < inertial_end) l.mass = number_attribute(urdf, mass, past_tag(urdf, mass), "value");
  set_principal(*tensor, l);
  return l;
}

// the body that is this link alone: a body of several links (MuJoCo fuses a floating base's fixed
// links) has more mass than its own
bool is_link_alone(const RobotBody& b, const LinkInertia& l) {
  return b.name == l.link && std::abs(l.mass - b.mass) <= 1e-12 * std::abs(l.mass);
}

}  // namespace

bool refuses_unbalanced_inertia(const std::string& mujoco_error) {
  return mujoco_error.find("inertia must satisfy A + B >= C") != std::string::npos;
}

std::string with_balanced_inertias(const std::string& urdf) {
  return with_compiler_attributes(urdf, " balanceinertia=\"true\"", {"balanceinertia"});
}

std::vector<LinkInertia> urdf_link_inertias(const std::string& urdf) {
  std::vector<LinkInertia> links;
  for (std::size_t at = element_start(urdf, "link"); at != std::string::npos; at = element_start(urdf, "link", at + 1))
    if (std::optional<LinkInertia> l = link_inertia(urdf, at)) links.push_back(*l);
  return links;
}

StatedInertias with_stated_inertias(std::vector<RobotBody>& bodies, const std::string& urdf) {
  StatedInertias out;
  for (const LinkInertia& l : urdf_link_inertias(urdf)) {
    auto alone = std::find_if(bodies.begin(), bodies.end(), [&](const RobotBody& b) { return is_link_alone(b, l); });
    if (alone == bodies.end()) {
      if (l.unbalanced) out.left_balanced.push_back(l.link);
      continue;
    }
    const Triple& m = alone->principal_inertia;
    if (m[0] != m[1] || m[1] != m[2]) continue;  // not balanced by MuJoCo
    alone->principal_inertia = l.principal;
    alone->inertia_axes = l.axes;
    if (l.unbalanced) out.given_back.push_back(l.link);
  }
  return out;
}

}  // namespace eomgen
