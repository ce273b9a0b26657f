#include "derive/quadratic_kinetic_energy.hpp"

#include <algorithm>
#include <cmath>

#include "derive/state_values.hpp"
#include "symbolic/gradient.hpp"

namespace eomgen {

namespace {

// whether T is written in the recursion's quantities (then it is long code, however short it looks)
bool uses_intermediates(const Equations& e) {
  GiNaC::exset used;
  collect_symbols(e.kinetic_energy, used);
  return std::any_of(e.intermediates.begin(), e.intermediates.end(), [&](const Intermediate& i) { return used.count(i.symbol) > 0; });
}

}  // namespace

bool kinetic_energy_is_quadratic_form(const Equations& e) {
  // a tree of particles is scleronomic and has no [energy] kinetic, so T = ½ q'ᵀ M q' exactly (Hiller §3.5)
  if (e.articulated()) return true;
  std::size_t n = e.num_velocities();
  if (!e.newton_euler() || e.has_multipliers || e.solves_for_velocities() || e.mass_matrix.rows() != n ||
      !uses_intermediates(e))
    return false;
  // two states, since one could make a linear term vanish by chance
  for (int seed = 0; seed < 2; ++seed) {
    StateValues at = StateValues::spread(e.symbols, e.intermediates, seed);
    double T = at(e.kinetic_energy), form = 0, largest = std::abs(T);
    for (unsigned i = 0; i < n; ++i)
      for (unsigned j = 0; j < n; ++j) {
        double term = 0.5 * at(e.symbols.velocities[i]) * at(e.mass_matrix(i, j)) * at(e.symbols.velocities[j]);
        form += term, largest = std::max(largest, std::abs(term));
      }
    if (!(std::abs(T - form) <= 1e-12 * largest)) return false;
  }
  return true;
}

}  // namespace eomgen
