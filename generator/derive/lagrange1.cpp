/// @file Lagrange's equations of the first kind (Hiller §2.4, §4.2): the coordinates
/// are not independent, and the constraint forces enter through multipliers,
/// M(q,t)·q'' = f(q,q',u,t) + C(q,t)ᵀ·λ,  C q'' + γ(q,q',t) = 0.
/// M and f are those of the unconstrained system (Lagrange II without the constraints).
#include "derive/constraints.hpp"
#include "derive/methods.hpp"

namespace eomgen {

Equations derive_lagrange1(const Model& model, const Mechanics& mechanics) {
  Equations e = derive_lagrange2(model, mechanics);
  e.method = "lagrange1";
  e.constraints = constraint_set(model, mechanics);
  require_independent(e.constraints, model.symbols, mechanics.intermediates);
  e.has_multipliers = true;
  e.degrees_of_freedom = model.symbols.coordinates.size() - e.constraints.size();
  e.conserves_energy_without_inputs =
      e.conserves_energy_without_inputs && constraints_scleronomic(e.constraints, model.symbols);
  return e;
}

}  // namespace eomgen
