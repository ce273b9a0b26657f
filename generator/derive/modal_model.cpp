#include "derive/modal_model.hpp"

#include <algorithm>
#include <cmath>

namespace eomgen {

using GiNaC::ex;

namespace {

// a name for η_k that no symbol of the model has
std::string modal_name(const Symbols& s, int number) {
  std::string name = "eta" + std::to_string(number);
  while (s.by_name.count(name)) name = "modal_" + name;
  return name;
}

// rounding leaves couplings of 1e-17 between modes that the projection decouples: below 1e-12 of
// the largest numeric coefficient of the same kind they are dropped
ex without_rounding_couplings(const ex& e, const std::vector<GiNaC::realsymbol>& eta, const std::vector<GiNaC::realsymbol>& rate) {
  ex f = e.expand();
  GiNaC::exmap zero;
  std::vector<GiNaC::realsymbol> all = eta;
  all.insert(all.end(), rate.begin(), rate.end());
  for (const GiNaC::realsymbol& x : all) zero[x] = 0;
  std::vector<ex> c;
  double largest = 0;
  for (const GiNaC::realsymbol& x : all) {
    c.push_back(f.coeff(x, 1));
    if (GiNaC::is_a<GiNaC::numeric>(c.back())) largest = std::max(largest, std::abs(GiNaC::ex_to<GiNaC::numeric>(c.back()).to_double()));
  }
  ex out = f.subs(zero);
  for (std::size_t k = 0; k < all.size(); ++k) {
    bool rounding = GiNaC::is_a<GiNaC::numeric>(c[k]) && std::abs(GiNaC::ex_to<GiNaC::numeric>(c[k]).to_double()) < 1e-12 * largest;
    if (!rounding) out += c[k] * all[k];
  }
  return out;
}

}  // namespace

Equations modal_model(const Equations& linear, const ModalTruncation& mt) {
  const Symbols& s = linear.symbols;
  std::size_t n = s.num_coordinates(), r = mt.shapes.size();
  GiNaC::exmap values, to_modes;
  for (std::size_t i = 0; i < s.parameters.size(); ++i) values[s.parameters[i]] = mt.parameter_values[i];
  Equations out = linear;
  out.solve_by_mass_matrix();
  out.model_name = linear.model_name + "_modal";
  out.title = linear.title + " (modal truncation)";
  std::vector<GiNaC::realsymbol> eta, rate;
  for (std::size_t k = 0; k < r; ++k) {
    std::string name = modal_name(s, mt.mode_numbers[k]);
    eta.emplace_back(name), rate.emplace_back("der(" + name + ")");
  }
  std::vector<ex> q(n), v(n);
  for (std::size_t i = 0; i < n; ++i) {
    q[i] = mt.equilibrium[i], v[i] = 0;
    for (std::size_t k = 0; k < r; ++k) q[i] += mt.shapes[k][i] * eta[k], v[i] += mt.shapes[k][i] * rate[k];
    to_modes[s.coordinates[i]] = q[i], to_modes[s.velocities[i]] = v[i];
  }
  auto modal = [&](const ex& e) { return e.subs(values).subs(to_modes).expand(); };
  out.mass_matrix = GiNaC::matrix(unsigned(r), unsigned(r));
  out.forcing.assign(r, 0);
  for (std::size_t a = 0; a < r; ++a) {
    for (std::size_t i = 0; i < n; ++i) out.forcing[a] += mt.shapes[a][i] * linear.forcing[i];
    out.forcing[a] = without_rounding_couplings(modal(out.forcing[a]), eta, rate);
    for (std::size_t b = 0; b < r; ++b) {
      ex m = 0;
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) m += mt.shapes[a][i] * linear.mass_matrix(unsigned(i), unsigned(j)) * mt.shapes[b][j];
      out.mass_matrix(unsigned(a), unsigned(b)) = modal(m);
    }
  }
  // the shapes are mass-normalized (Φᵀ M Φ = I): what differs from I is rounding
  for (unsigned a = 0; a < r; ++a)
    for (unsigned b = 0; b < r; ++b) {
      const ex& m = out.mass_matrix(a, b);
      double expected = a == b ? 1 : 0;
      if (GiNaC::is_a<GiNaC::numeric>(m) && std::abs(GiNaC::ex_to<GiNaC::numeric>(m).to_double() - expected) < 1e-12)
        out.mass_matrix(a, b) = expected;
    }
  out.kinetic_energy = modal(linear.kinetic_energy);
  out.potential_energy = modal(linear.potential_energy);
  out.dissipation = modal(linear.dissipation);
  out.outputs.clear();
  for (std::size_t i = 0; i < n; ++i) out.outputs.push_back({s.coordinate_names[i], q[i]});
  for (std::size_t i = 0; i < n; ++i) out.outputs.push_back({s.velocities[i].get_name(), v[i]});
  for (const NamedSymbolic& o : linear.outputs) out.outputs.push_back({o.name, modal(o.expression)});
  out.drawing.clear();  // a linearized rotation is no rotation: nothing to animate
  for (Equations::BodyPosition& b : out.body_positions)
    for (ex& x : b.position) x = modal(x);
  out.first_integrals.clear();
  out.has_linearization = false;
  Symbols& t = out.symbols;
  for (std::size_t i = n; i-- > 0;) t.remove_coordinate(i);
  for (std::size_t k = 0; k < r; ++k) {
    t.by_name[eta[k].get_name()] = {SymbolKind::coordinate, k};
    t.coordinate_names.push_back(eta[k].get_name());
    t.coordinates.push_back(eta[k]), t.velocities.push_back(rate[k]);
    t.initial_coordinates.push_back(mt.initial_modal_coordinates[k]);
    t.initial_velocities.push_back(mt.initial_modal_rates[k]);
    t.initial_coordinate_expressions.push_back(mt.initial_modal_coordinates[k]);
    t.initial_rate_expressions.push_back(mt.initial_modal_rates[k]);
  }
  out.degrees_of_freedom = r;
  return out;
}

}  // namespace eomgen
