// A URDF's link inertias as the file states them, for MuJoCo as an oracle of imported URDFs. MuJoCo's
// compiler finds a full tensor's principal axes by an iteration with a loose stop, which turns the
// tensor (the seven-joint arm's accelerations by 1.2e-7); eomgen takes the six numbers as written,
// as URDF readers do. Given the stated tensors, MuJoCo's accelerations are the file's robot's to
// rounding. Read here by a few regular expressions, not by eomgen's reader, and set on each body
// that is its link alone.
#pragma once

#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <mujoco/mujoco.h>

namespace {

struct StatedInertia {
  double mass = 0;
  Eigen::Matrix3d tensor = Eigen::Matrix3d::Zero();  // about the centre, in the link's frame
};

// the number of attribute `name` in `element`, or 0
inline double urdf_number(const std::string& element, const std::string& name) {
  std::smatch m;
  return std::regex_search(element, m, std::regex("\\b" + name + "\\s*=\\s*\"([^\"]*)\"")) ? std::stod(m[1]) : 0.0;
}

// each link with an <inertial>: its mass and R(rpy) I R(rpy)ᵀ, R = Rz(yaw) Ry(pitch) Rx(roll)
inline std::map<std::string, StatedInertia> stated_urdf_inertias(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  // without its comments: a file may keep an old value there (Talos: <!-- <mass value="1.52896"/> -->)
  std::string urdf = std::regex_replace(text.str(), std::regex("<!--[\\s\\S]*?-->"), "");
  std::map<std::string, StatedInertia> links;
  std::regex link("<link\\s+name\\s*=\\s*\"([^\"]*)\"\\s*>([\\s\\S]*?)</link>");
  for (std::sregex_iterator it(urdf.begin(), urdf.end(), link), end; it != end; ++it) {
    std::string body = (*it)[2];
    std::smatch inertial, origin, mass, inertia;
    if (!std::regex_search(body, inertial, std::regex("<inertial>([\\s\\S]*?)</inertial>"))) continue;
    std::string part = inertial[1];
    double rpy[3] = {0, 0, 0};
    if (std::regex_search(part, origin, std::regex("<origin[^>]*rpy\\s*=\\s*\"([^\"]*)\""))) {
      std::istringstream angles(origin[1].str());
      angles >> rpy[0] >> rpy[1] >> rpy[2];
    }
    std::regex_search(part, mass, std::regex("<mass[^>]*>"));
    std::regex_search(part, inertia, std::regex("<inertia[^>]*>"));
    std::string I = inertia[0];
    Eigen::Matrix3d stated;
    stated << urdf_number(I, "ixx"), urdf_number(I, "ixy"), urdf_number(I, "ixz"), urdf_number(I, "ixy"),
        urdf_number(I, "iyy"), urdf_number(I, "iyz"), urdf_number(I, "ixz"), urdf_number(I, "iyz"), urdf_number(I, "izz");
    Eigen::Matrix3d R = (Eigen::AngleAxisd(rpy[2], Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(rpy[1], Eigen::Vector3d::UnitY()) *
                         Eigen::AngleAxisd(rpy[0], Eigen::Vector3d::UnitX()))
                            .toRotationMatrix();
    links[(*it)[1]] = {urdf_number(mass[0], "value"), R * stated * R.transpose()};
  }
  return links;
}

// MuJoCo's model of the URDF at `path` with each body that is one link alone (its mass the link's)
// given the stated tensor: its principal moments and axes (body_inertia, body_iquat)
inline void with_stated_urdf_inertias(mjModel* m, const std::string& path) {
  std::map<std::string, StatedInertia> links = stated_urdf_inertias(path);
  for (int b = 1; b < m->nbody; ++b) {
    auto link = links.find(mj_id2name(m, mjOBJ_BODY, b) ? mj_id2name(m, mjOBJ_BODY, b) : "");
    if (link == links.end() || std::abs(link->second.mass - m->body_mass[b]) > 1e-12 * link->second.mass) continue;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(link->second.tensor);
    Eigen::Matrix3d axes = eigen.eigenvectors();
    if (axes.determinant() < 0) axes.col(2) = -axes.col(2);
    Eigen::Quaterniond q(axes);
    for (int k = 0; k < 3; ++k) m->body_inertia[3 * b + k] = eigen.eigenvalues()[k];
    m->body_iquat[4 * b] = q.w(), m->body_iquat[4 * b + 1] = q.x(), m->body_iquat[4 * b + 2] = q.y(), m->body_iquat[4 * b + 3] = q.z();
    // MuJoCo skips body_iquat where it compiled the inertial frame as the body's own (body_sameframe,
    // and body_simple after it): the new axes need the general path (UR5's links, whose moments
    // Eigen orders otherwise, moved the accelerations by 3e-4 without this)
    m->body_sameframe[b] = 0, m->body_simple[b] = 0;
    for (int k = m->body_dofadr[b]; k >= 0 && k < m->body_dofadr[b] + m->body_dofnum[b]; ++k) m->dof_simplenum[k] = 0;
  }
}

}  // namespace
