#include "derive/quadratic_kinetic_energy.hpp"

#include <algorithm>
#include <cmath>

#include "derive/state_values.hpp"

namespace eomgen {

namespace {

// whether T is written in the recursion's quantities (then it is long code, however short it looks)
bool uses_intermediates(const Equations& e) {
  for (const Intermediate& i : e.intermediates)
    if (e.kinetic_energy.has(i.symbol)) return true;
  return false;
}

}  // namespace

bool kinetic_energy_is_quadratic_form(const Equations& e) {
  std::size_t n = e.num_velocities();
  if (e.inverse_dynamics.empty() || e.has_multipliers || e.solves_for_velocities() || e.mass_matrix.rows() != n ||
      !e.articulated_accelerations.empty() || !uses_intermediates(e))
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
