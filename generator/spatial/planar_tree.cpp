#include "spatial/planar_tree.hpp"

#include <array>
#include <cmath>
#include <optional>
#include <set>

namespace eomgen {

namespace {

using Direction = std::array<double, 3>;

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

using Turn = std::array<Direction, 3>;

Direction turned(const Turn& R, const Direction& x) {
  Direction y{};
  for (std::size_t a = 0; a < 3; ++a) y[a] = R[a][0] * x[0] + R[a][1] * x[1] + R[a][2] * x[2];
  return y;
}

Turn product(const Turn& P, const Turn& E) {
  Turn R{};
  for (std::size_t a = 0; a < 3; ++a)
    for (std::size_t b = 0; b < 3; ++b) R[a][b] = P[a][0] * E[0][b] + P[a][1] * E[1][b] + P[a][2] * E[2][b];
  return R;
}

double length(const Direction& x) { return std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]); }

// in one plane at these values of the symbols: each link's world turn, then its column's world
// angular and linear parts against the first hinge's axis n
bool planar_at(const std::vector<TreeLink>& links, const GiNaC::exmap& values) {
  std::vector<Turn> world(links.size());
  std::optional<Direction> normal;
  std::vector<Direction> slides;
  for (std::size_t i = 0; i < links.size(); ++i) {
    const TreeLink& l = links[i];
    if (l.columns.size() > 1) return false;
    Turn E{};
    for (unsigned k = 0; k < 9; ++k) {
      std::optional<double> v = value_of(l.turn(k / 3, k % 3), values);
      if (!v) return false;
      E[k / 3][k % 3] = *v;
    }
    world[i] = l.parent < 0 ? E : product(world[std::size_t(l.parent)], E);
    if (l.columns.empty()) continue;
    Direction axis{}, motion{};
    for (unsigned k = 0; k < 3; ++k) {
      std::optional<double> w = value_of(l.columns[0].axis[k], values), u = value_of(l.columns[0].origin_velocity[k], values);
      if (!w || !u) return false;
      axis[k] = *w, motion[k] = *u;
    }
    Direction w = turned(world[i], axis), u = turned(world[i], motion);
    if (length(w) == 0) {
      slides.push_back(u);
      continue;
    }
    if (!normal) normal = Direction{w[0] / length(w), w[1] / length(w), w[2] / length(w)};
    const Direction& n = *normal;
    Direction across{n[1] * w[2] - n[2] * w[1], n[2] * w[0] - n[0] * w[2], n[0] * w[1] - n[1] * w[0]};
    double along = n[0] * u[0] + n[1] * u[1] + n[2] * u[2];
    if (length(across) > 1e-12 * length(w) || std::abs(along) > 1e-12 * (length(u) + 1)) return false;
  }
  if (!normal) return false;
  for (const Direction& u : slides)
    if (std::abs((*normal)[0] * u[0] + (*normal)[1] * u[1] + (*normal)[2] * u[2]) > 1e-12 * length(u)) return false;
  return true;
}

}  // namespace

bool moves_in_a_plane(const std::vector<TreeLink>& links) {
  std::vector<GiNaC::ex> symbols = symbols_of(links);
  for (double offset : {0.37, -1.21}) {
    GiNaC::exmap values;
    for (std::size_t k = 0; k < symbols.size(); ++k) values[symbols[k]] = offset + 0.731 * double(k % 11);
    if (!planar_at(links, values)) return false;
  }
  return true;
}

}  // namespace eomgen
