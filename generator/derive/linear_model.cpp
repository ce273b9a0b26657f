#include "derive/linear_model.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

// e to first order about the point: e0 + Σ ∂e/∂x_k (x_k − x0_k), the x the coordinates and velocities
ex first_order(const ex& e, const Symbols& s, const GiNaC::exmap& point) {
  ex out = e.subs(point);
  for (std::size_t k = 0; k < s.coordinates.size(); ++k) {
    out += e.diff(s.coordinates[k]).subs(point) * (s.coordinates[k] - s.coordinates[k].subs(point));
    out += e.diff(s.velocities[k]).subs(point) * s.velocities[k];
  }
  return out.normal();
}

// the potential to second order in q − q0
ex second_order(const ex& V, const Symbols& s, const GiNaC::exmap& point) {
  ex out = first_order(V, s, point);
  for (std::size_t i = 0; i < s.coordinates.size(); ++i)
    for (std::size_t j = 0; j < s.coordinates.size(); ++j)
      out += V.diff(s.coordinates[i]).diff(s.coordinates[j]).subs(point) * (s.coordinates[i] - s.coordinates[i].subs(point)) *
             (s.coordinates[j] - s.coordinates[j].subs(point)) / 2;
  return out.normal();
}

}  // namespace

Equations linearized_model(const Equations& e, const std::vector<double>& q0, std::string& refusal) {
  if (e.method != "lagrange2" || e.has_multipliers || e.uses_pseudo_velocities() || e.constraints.size() > 0) {
    refusal = "the linear model is made for unconstrained Lagrange II models";
    return e;
  }
  const Symbols& s = e.symbols;
  std::size_t n = s.num_coordinates();
  GiNaC::exmap point, rest;
  for (std::size_t i = 0; i < n; ++i) point[s.coordinates[i]] = q0[i], point[s.velocities[i]] = 0, rest[s.coordinates[i]] = q0[i];
  Equations out = e;
  out.solve_by_mass_matrix();
  out.model_name = e.model_name + "_linear";
  out.title = e.title + " (linearized)";
  for (unsigned i = 0; i < n; ++i)
    for (unsigned j = 0; j < n; ++j) out.mass_matrix(i, j) = e.mass_matrix(i, j).subs(rest).normal();
  for (std::size_t i = 0; i < n; ++i) out.forcing[i] = first_order(e.forcing[i], s, point);
  ex T = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) T += out.mass_matrix(unsigned(i), unsigned(j)) * s.velocities[i] * s.velocities[j] / 2;
  out.kinetic_energy = T.expand();
  out.potential_energy = second_order(e.potential_energy, s, point);
  out.dissipation = e.dissipation.subs(rest).normal();
  for (NamedSymbolic& o : out.outputs) o.expression = first_order(o.expression, s, point);
  out.first_integrals.clear();
  out.has_linearization = false;
  out.drawing.clear();  // a linearized rotation is no rotation: nothing to animate
  for (Equations::BodyPosition& b : out.body_positions)
    for (ex& x : b.position) x = first_order(x, s, point);
  return out;
}

}  // namespace eomgen
