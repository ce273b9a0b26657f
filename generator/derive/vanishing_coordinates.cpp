#include "derive/vanishing_coordinates.hpp"

#include <algorithm>

#include "kinematics/drawn_bodies.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

bool kept(const Equations& e, const std::vector<std::string>& keep, std::size_t j) {
  const Symbols& s = e.symbols;
  for (const std::string& name : keep) {
    if (name == s.coordinate_names[j] || name == s.velocities[j].get_name()) return true;
    for (const NamedSymbolic& o : e.outputs)
      if (o.name == name && s.involves(o.expression, j)) return true;
  }
  return false;
}

// row and column j of M and f_j vanish, and nothing else of the motion contains q_j or der(q_j)
bool vanishes(const Equations& e, std::size_t j) {
  const Symbols& s = e.symbols;
  std::size_t n = s.num_coordinates();
  if (!e.forcing[j].normal().is_zero()) return false;
  for (unsigned i = 0; i < n; ++i) {
    if (!e.mass_matrix(unsigned(j), i).normal().is_zero() || !e.mass_matrix(i, unsigned(j)).normal().is_zero()) return false;
    if (i != j && s.involves(e.forcing[i], j)) return false;
    for (unsigned k = 0; k < n; ++k)
      if (s.involves(e.mass_matrix(i, k), j)) return false;
  }
  return true;
}


}  // namespace

void remove_coordinate(Equations& e, std::size_t j) {
  const Symbols& s = e.symbols;
  std::size_t n = s.num_coordinates();
  auto gone = [&](const ex& x) { return s.involves(x, j); };
  e.outputs.erase(std::remove_if(e.outputs.begin(), e.outputs.end(), [&](const NamedSymbolic& o) { return gone(o.expression); }),
                  e.outputs.end());
  e.body_positions.erase(std::remove_if(e.body_positions.begin(), e.body_positions.end(),
                                        [&](const Equations::BodyPosition& b) { return gone(b.position[0]) || gone(b.position[1]) || gone(b.position[2]); }),
                         e.body_positions.end());
  remove_drawn_bodies(e.drawing, [&](const DrawnBody& d) {
    for (const GiNaC::ex& x : d.position)
      if (gone(x)) return true;
    for (unsigned i = 0; i < 9; ++i)
      if (gone(d.rotation.op(i))) return true;
    return false;
  });
  e.first_integrals.erase(std::remove_if(e.first_integrals.begin(), e.first_integrals.end(),
                                         [&](const FirstIntegral& f) { return gone(f.expression); }),
                          e.first_integrals.end());
  GiNaC::matrix M(unsigned(n - 1), unsigned(n - 1));
  for (unsigned a = 0, r = 0; a < n; ++a) {
    if (a == j) continue;
    for (unsigned b = 0, c = 0; b < n; ++b)
      if (b != j) M(r, c++) = e.mass_matrix(a, b);
    ++r;
  }
  e.mass_matrix = M;
  e.solve_by_mass_matrix();
  e.forcing.erase(e.forcing.begin() + static_cast<std::ptrdiff_t>(j));
  e.symbols.remove_coordinate(j);
  e.degrees_of_freedom = e.symbols.num_coordinates();
  e.has_linearization = false;
}

std::vector<std::string> remove_vanishing_coordinates(Equations& e, const std::vector<std::string>& keep) {
  std::vector<std::string> removed;
  if (e.method != "lagrange2" || e.constraints.size() > 0 || e.uses_pseudo_velocities()) return removed;
  for (bool changed = true; changed && e.symbols.num_coordinates() > 1;) {
    changed = false;
    for (std::size_t j = 0; j < e.symbols.num_coordinates(); ++j)
      if (vanishes(e, j) && !kept(e, keep, j) && !e.symbols.involves(e.kinetic_energy + e.potential_energy + e.dissipation, j)) {
        removed.push_back(e.symbols.coordinate_names[j]);
        remove_coordinate(e, j);
        changed = true;
        break;
      }
  }
  return removed;
}

}  // namespace eomgen
