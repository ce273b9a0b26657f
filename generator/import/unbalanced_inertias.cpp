#include "import/unbalanced_inertias.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <cstdlib>
#include <sstream>

#include <Eigen/Eigenvalues>

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

// URDF's rpy: R = Rz(yaw) Ry(pitch) Rx(roll), row-major
std::array<double, 9> rotation_of(const Triple& rpy) {
  double cr = std::cos(rpy[0]), sr = std::sin(rpy[0]), cp = std::cos(rpy[1]), sp = std::sin(rpy[1]), cy = std::cos(rpy[2]),
         sy = std::sin(rpy[2]);
  return {cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr,
          sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr,
          -sp,     cp * sr,                cp * cr};
}

bool unphysical(const Triple& m) {
  return m[0] + m[1] < m[2] || m[0] + m[2] < m[1] || m[1] + m[2] < m[0] || m[0] < 0 || m[1] < 0 || m[2] < 0;
}

// the <inertial> of the link whose tag opens at `link`, or nothing
std::optional<LinkInertia> link_inertia(const std::string& urdf, std::size_t link) {
  std::size_t open_end = past_tag(urdf, link);
  if (open_end == std::string::npos || urdf[open_end - 2] == '/') return std::nullopt;
  std::optional<std::string> name = attribute(urdf, link, open_end, "name");
  std::size_t link_end = urdf.find("</link", open_end);
  std::size_t inertial = element_start(urdf, "inertial", open_end);
  if (!name || inertial == std::string::npos || inertial > link_end) return std::nullopt;
  std::size_t inertial_end = urdf.find("</inertial", inertial);
  std::size_t origin = element_start(urdf, "origin", inertial), inertia = element_start(urdf, "inertia", inertial);
  if (inertia == std::string::npos || inertia > inertial_end) return std::nullopt;
  Triple rpy{0, 0, 0};
  if (origin != std::string::npos && origin < inertial_end) rpy = triple_attribute(urdf, origin, past_tag(urdf, origin), "rpy");
  std::size_t mass = element_start(urdf, "mass", inertial);
  std::size_t e = past_tag(urdf, inertia);
  auto I = [&](const char* n) { return number_attribute(urdf, inertia, e, n); };
  const double stated[9] = {I("ixx"), I("ixy"), I("ixz"), I("ixy"), I("iyy"), I("iyz"), I("ixz"), I("iyz"), I("izz")};
  // in the link's frame: R I Rᵀ
  std::array<double, 9> R = rotation_of(rpy);
  double turned[9];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      double sum = 0;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) sum += R[std::size_t(3 * r + a)] * stated[3 * a + b] * R[std::size_t(3 * c + b)];
      turned[3 * r + c] = sum;
    }
  // the principal moments and axes to the last digit: MuJoCo's mju_eig3 leaves errors near 1e-8
  Eigen::Matrix3d tensor;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) tensor(r, c) = turned[3 * r + c];
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(tensor);
  Eigen::Vector3d moments = eigen.eigenvalues();
  Eigen::Matrix3d vectors = eigen.eigenvectors();
  if (vectors.determinant() < 0) vectors.col(2) = -vectors.col(2);  // a rotation, not a reflection
  Eigen::Quaterniond quat(vectors);
  LinkInertia l;
  l.link = *name;
  if (mass != std::string::npos && mass < inertial_end) l.mass = number_attribute(urdf, mass, past_tag(urdf, mass), "value");
  // a moment of rounding's size alone (a rank-one dummy inertia's, of either sign) is zero
  double largest = std::max({std::abs(moments[0]), std::abs(moments[1]), std::abs(moments[2])});
  for (int k = 0; k < 3; ++k) l.principal[std::size_t(k)] = std::abs(moments[k]) <= 1e-12 * largest ? 0.0 : moments[k];
  l.axes = {quat.w(), quat.x(), quat.y(), quat.z()};
  l.unbalanced = unphysical(l.principal);
  return l;
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

std::vector<std::string> with_stated_inertias(std::vector<RobotBody>& bodies, const std::string& urdf) {
  std::vector<std::string> unbalanced;
  std::vector<LinkInertia> links = urdf_link_inertias(urdf);
  for (RobotBody& b : bodies) {
    const Triple& m = b.principal_inertia;
    if (m[0] != m[1] || m[1] != m[2]) continue;
    for (const LinkInertia& l : links) {
      // a body of several links (MuJoCo fuses a floating base's fixed links) has more mass than its own
      if (l.link != b.name || std::abs(l.mass - b.mass) > 1e-12 * std::abs(l.mass)) continue;
      b.principal_inertia = l.principal;
      b.inertia_axes = l.axes;
      if (l.unbalanced) unbalanced.push_back(l.link);
      break;
    }
  }
  return unbalanced;
}

}  // namespace eomgen
