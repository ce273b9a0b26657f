#include "derive/decoupled_coordinates.hpp"

#include <algorithm>

#include "derive/vanishing_coordinates.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

// the coordinates the names read, or nothing when a name is unknown
std::vector<bool> named_coordinates(const Equations& e, const std::vector<std::string>& needed) {
  const Symbols& s = e.symbols;
  std::vector<bool> in(s.num_coordinates(), false);
  for (const std::string& name : needed) {
    bool found = false;
    for (std::size_t j = 0; j < s.num_coordinates(); ++j)
      if (name == s.coordinate_names[j] || name == s.velocities[j].get_name()) in[j] = found = true;
    for (const NamedSymbolic& o : e.outputs)
      if (o.name == name) {
        found = true;
        for (std::size_t j = 0; j < s.num_coordinates(); ++j) in[j] = in[j] || s.involves(o.expression, j);
      }
    if (!found) return {};
  }
  return in;
}

// the rows of M and f of the subsystem contain coordinate j (or its rate), or M couples them to it
bool feeds_back(const Equations& e, const std::vector<bool>& in, std::size_t j) {
  const Symbols& s = e.symbols;
  for (unsigned i = 0; i < in.size(); ++i) {
    if (!in[i]) continue;
    if (s.involves(e.forcing[i], j) || !e.mass_matrix(i, unsigned(j)).normal().is_zero()) return true;
    for (unsigned k = 0; k < in.size(); ++k)
      if (in[k] && s.involves(e.mass_matrix(i, k), j)) return true;
  }
  return false;
}

// T + V + D splits into a part of the subsystem and a part of the rest: no mixed second derivative
bool energies_separate(const Equations& e, const std::vector<bool>& in) {
  const Symbols& s = e.symbols;
  ex sum = e.kinetic_energy + e.potential_energy + e.dissipation;
  for (std::size_t i = 0; i < in.size(); ++i)
    for (std::size_t j = 0; j < in.size(); ++j) {
      if (!in[i] || in[j]) continue;
      for (const GiNaC::realsymbol& a : {s.coordinates[i], s.velocities[i]})
        for (const GiNaC::realsymbol& b : {s.coordinates[j], s.velocities[j]})
          if (!sum.diff(a).diff(b).normal().is_zero()) return false;
    }
  return true;
}

}  // namespace

std::vector<std::string> drop_coordinates_not_fed_back(Equations& e, const std::vector<std::string>& needed) {
  if (e.method != "lagrange2" || e.constraints.size() > 0 || e.uses_pseudo_velocities()) return {};
  std::vector<bool> in = named_coordinates(e, needed);
  if (in.empty() || std::none_of(in.begin(), in.end(), [](bool b) { return b; })) return {};
  for (bool grew = true; grew;) {
    grew = false;
    for (std::size_t j = 0; j < in.size(); ++j)
      if (!in[j] && feeds_back(e, in, j)) in[j] = grew = true;
  }
  if (std::all_of(in.begin(), in.end(), [](bool b) { return b; })) return {};
  if (!energies_separate(e, in)) e.conserves_energy_without_inputs = false;
  const Symbols& s = e.symbols;
  GiNaC::exmap held;
  for (std::size_t j = 0; j < in.size(); ++j)
    if (!in[j]) held[s.coordinates[j]] = s.initial_coordinates[j], held[s.velocities[j]] = 0;
  e.kinetic_energy = e.kinetic_energy.subs(held).expand();
  e.potential_energy = e.potential_energy.subs(held).expand();
  e.dissipation = e.dissipation.subs(held).expand();
  std::vector<std::string> dropped;
  for (std::size_t j = in.size(); j-- > 0;)
    if (!in[j]) {
      dropped.insert(dropped.begin(), s.coordinate_names[j]);
      remove_coordinate(e, j);
    }
  return dropped;
}

}  // namespace eomgen
