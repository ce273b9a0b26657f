#include "derive/angle_coordinates.hpp"

namespace eomgen {

namespace {

// Marks the coordinates that x takes as f(k q + …) with f a circular function and k a number other
// than zero.
void mark_angles(const GiNaC::ex& x, const std::vector<GiNaC::realsymbol>& coordinates, std::vector<bool>& angle) {
  if (GiNaC::is_a<GiNaC::function>(x)) {
    const std::string name = GiNaC::ex_to<GiNaC::function>(x).get_name();
    if (name == "sin" || name == "cos" || name == "tan")
      for (std::size_t q = 0; q < coordinates.size(); ++q) {
        if (angle[q] || !x.op(0).has(coordinates[q])) continue;
        GiNaC::ex k = x.op(0).diff(coordinates[q]).expand();
        angle[q] = GiNaC::is_a<GiNaC::numeric>(k) && !k.is_zero();
      }
  }
  for (std::size_t i = 0; i < x.nops(); ++i) mark_angles(x.op(i), coordinates, angle);
}

}  // namespace

std::vector<bool> angle_coordinates(const Equations& e) {
  const std::vector<GiNaC::realsymbol>& q = e.symbols.coordinates;
  std::vector<bool> angle(q.size(), false);
  auto mark = [&](const GiNaC::ex& x) { mark_angles(x, q, angle); };
  for (const Intermediate& i : e.intermediates) mark(i.definition);
  if (const NewtonEulerRecursion* recursion = e.newton_euler())
    for (const Intermediate& i : recursion->acceleration_intermediates) mark(i.definition);
  if (const ArticulatedForwardDynamics* tree = e.articulated())
    for (const Intermediate& i : tree->intermediates) mark(i.definition);
  for (const GiNaC::ex& f : e.forcing) mark(f);
  mark(e.mass_matrix), mark(e.kinetic_energy), mark(e.potential_energy), mark(e.hamiltonian);
  for (const GiNaC::ex& g : e.constraints.position) mark(g);
  mark(e.constraints.jacobian);
  for (const GiNaC::ex& r : e.coordinate_rates) mark(r);
  for (const Equations::BodyPosition& b : e.body_positions)
    for (const GiNaC::ex& x : b.position) mark(x);
  return angle;
}

}  // namespace eomgen
