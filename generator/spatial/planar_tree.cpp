#include "spatial/planar_tree.hpp"

#include <cmath>
#include <optional>
#include <set>

#include <Eigen/Dense>

namespace eomgen {

namespace {

// every symbol of the links' turns and columns, in the order of their first appearance
std::vector<GiNaC::ex> symbols_of(const std::vector<TreeLink>& links) {
  std::vector<GiNaC::ex> symbols;
  std::set<GiNaC::ex, GiNaC::ex_is_less> seen;
  auto collect = [&](const GiNaC::ex& e) {
    for (auto i = e.preorder_begin(); i != e.preorder_end(); ++i)
      if (GiNaC::is_a<GiNaC::symbol>(*i) && seen.insert(*i).second) symbols.push_back(*i);
  };
  for (const TreeLink& l : links) {
    for (unsigned k = 0; k < 9; ++k) collect(l.turn(k / 3, k % 3));
    for (const TreeLink::Column& c : l.columns)
      for (unsigned k = 0; k < 3; ++k) collect(c.axis[k]), collect(c.origin_velocity[k]);
  }
  return symbols;
}

std::optional<double> value_of(const GiNaC::ex& e, const GiNaC::exmap& values) {
  GiNaC::ex v = e.subs(values).evalf();
  if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real()) return std::nullopt;
  return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
}

// in one plane at these values of the symbols: each link's world turn, then its column's world
// angular part w along the first hinge's axis n and its linear part u across it
bool planar_at(const std::vector<TreeLink>& links, const GiNaC::exmap& values) {
  std::vector<Eigen::Matrix3d> world(links.size());
  std::optional<Eigen::Vector3d> normal;
  std::vector<Eigen::Vector3d> slides;
  // entry(k) for k < count into out[k], where every one is a real number
  auto numbers = [&](const auto& entry, double* out, unsigned count) {
    for (unsigned k = 0; k < count; ++k) {
      std::optional<double> v = value_of(entry(k), values);
      if (!v) return false;
      out[k] = *v;
    }
    return true;
  };
  for (std::size_t i = 0; i < links.size(); ++i) {
    const TreeLink& l = links[i];
    if (l.columns.size() > 1) return false;
    Eigen::Matrix<double, 3, 3, Eigen::RowMajor> E;
    if (!numbers([&](unsigned k) { return l.turn(k / 3, k % 3); }, E.data(), 9)) return false;
    world[i] = l.parent < 0 ? Eigen::Matrix3d(E) : Eigen::Matrix3d(world[std::size_t(l.parent)] * E);
    if (l.columns.empty()) continue;
    Eigen::Vector3d axis, motion;
    if (!numbers([&](unsigned k) { return l.columns[0].axis[k]; }, axis.data(), 3) ||
        !numbers([&](unsigned k) { return l.columns[0].origin_velocity[k]; }, motion.data(), 3))
      return false;
    Eigen::Vector3d w = world[i] * axis, u = world[i] * motion;
    if (w.norm() == 0) {
      slides.push_back(u);
      continue;
    }
    if (!normal) normal = w.normalized();
    if (normal->cross(w).norm() > 1e-12 * w.norm() || std::abs(normal->dot(u)) > 1e-12 * u.norm()) return false;
  }
  if (!normal) return false;
  for (const Eigen::Vector3d& u : slides)
    if (std::abs(normal->dot(u)) > 1e-12 * u.norm()) return false;
  return true;
}

}  // namespace

bool moves_in_a_plane(const std::vector<TreeLink>& links) {
  std::vector<GiNaC::ex> symbols = symbols_of(links);
  for (double offset : {0.37, -1.21}) {
    GiNaC::exmap values;
    for (std::size_t k = 0; k < symbols.size(); ++k) values[symbols[k]] = offset + 0.731 * double(k);
    if (!planar_at(links, values)) return false;
  }
  return true;
}

}  // namespace eomgen
