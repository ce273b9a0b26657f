#include "derive/initial_state.hpp"

#include <cmath>

namespace eomgen {

namespace {

std::optional<double> value_of(const GiNaC::ex& e, const GiNaC::exmap& values) {
  GiNaC::ex v = e.subs(values).evalf();
  if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real()) return std::nullopt;
  double x = GiNaC::ex_to<GiNaC::numeric>(v).to_double();
  if (!std::isfinite(x)) return std::nullopt;
  return x;
}

}  // namespace

std::optional<std::vector<double>> initial_state(const Equations& e, const std::vector<double>& parameters,
                                                 std::string& failed) {
  const Symbols& s = e.symbols;
  std::size_t n = s.num_coordinates();
  if (s.initial_coordinate_expressions.size() != n) {  // equations built without the file's expressions
    std::vector<double> x = s.initial_coordinates;
    x.insert(x.end(), s.initial_velocities.begin(), s.initial_velocities.end());
    return x;
  }
  GiNaC::exmap values;
  for (std::size_t i = 0; i < s.parameters.size() && i < parameters.size(); ++i) values[s.parameters[i]] = parameters[i];
  std::vector<double> x;
  for (std::size_t i = 0; i < n; ++i) {
    auto q0 = value_of(s.initial_coordinate_expressions[i], values);
    if (!q0) return failed = "the initial value of " + s.coordinate_names[i], std::nullopt;
    x.push_back(*q0);
  }
  std::vector<double> rates;
  for (std::size_t i = 0; i < n; ++i) {
    auto r = value_of(s.initial_rate_expressions[i], values);
    if (!r) return failed = "the initial rate of " + s.coordinate_names[i], std::nullopt;
    rates.push_back(*r);
  }
  if (!e.uses_pseudo_velocities()) {
    x.insert(x.end(), rates.begin(), rates.end());
    return x;
  }
  // pseudo-velocities s0 = Y(q0) q0' + y(q0) from their definitions
  GiNaC::exmap at = values;
  const std::vector<GiNaC::realsymbol>& rate_symbols = e.coordinate_velocities;
  for (std::size_t i = 0; i < n; ++i) {
    at[s.coordinates[i]] = x[i];
    if (i < rate_symbols.size()) at[rate_symbols[i]] = rates[i];
  }
  at[s.time] = 0;
  for (const NamedSymbolic& d : e.pseudo_velocity_definitions) {
    auto v = value_of(d.expression, at);
    if (!v) return failed = "the initial value of the pseudo-velocity " + d.name, std::nullopt;
    x.push_back(*v);
  }
  return x;
}

}  // namespace eomgen
