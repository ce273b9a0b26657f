#include "derive/pseudo_velocities.hpp"

#include <cmath>

#include <fmt/format.h>

#include "derive/constraints.hpp"
#include "symbolic/simplify.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

// a rational expression with trigonometric identities applied to numerator and denominator
ex tidy_ratio(const ex& e, const MotionSymbols& motion) {
  ex r = GiNaC::normal(e);
  ex numerator = tidy(r.numer(), motion), denominator = tidy(r.denom(), motion);
  if (GiNaC::is_a<GiNaC::numeric>(denominator)) return tidy(numerator / denominator, motion);
  return numerator / denominator;
}

// rows of Y (∂s/∂q') and y (s at q' = 0) for every definition
void split_linear(const std::vector<NamedSymbolic>& definitions, const Symbols& s, GiNaC::matrix& Y, std::vector<ex>& y) {
  GiNaC::exmap at_rest;
  for (const auto& v : s.velocities) at_rest[v] = 0;
  for (unsigned i = 0; i < definitions.size(); ++i) {
    for (unsigned j = 0; j < s.velocities.size(); ++j) Y(i, j) = definitions[i].expression.diff(s.velocities[j]);
    y.push_back(definitions[i].expression.subs(at_rest));
  }
}

// independent coordinates: the complement of the first set of m columns of C with a
// non-singular square block at the initial state
std::variant<std::vector<std::size_t>, std::string> independent_coordinates(const ConstraintSet& c, const Symbols& s) {
  std::size_t n = s.coordinates.size(), m = c.size();
  std::vector<bool> chosen(n, false);
  std::fill(chosen.begin(), chosen.begin() + static_cast<long>(m), true);  // dependent columns, as a combination
  do {
    GiNaC::matrix block(m, m);
    for (unsigned i = 0, col = 0; col < n; ++col)
      if (chosen[col]) {
        for (unsigned r = 0; r < m; ++r) block(r, i) = c.jacobian(r, col);
        ++i;
      }
    ex det = m ? block.determinant() : ex(1);
    if (std::abs(initial_value(det, s)) > 1e-9) {
      std::vector<std::size_t> independent;
      for (std::size_t j = 0; j < n; ++j)
        if (!chosen[j]) independent.push_back(j);
      return independent;
    }
  } while (std::prev_permutation(chosen.begin(), chosen.end()));
  return std::string("the constraints are dependent at the initial state: no set of coordinates is determined by them");
}

}  // namespace

std::variant<PseudoVelocities, std::string> pseudo_velocities(const Model& model, const ConstraintSet& c,
                                                               const MotionSymbols& motion) {
  const Symbols& s = model.symbols;
  std::size_t n = s.coordinates.size(), m = c.size(), k = n - m;
  PseudoVelocities p;
  if (model.pseudo_velocities.empty()) {
    auto independent = independent_coordinates(c, s);
    if (auto* why = std::get_if<std::string>(&independent)) return *why;
    for (std::size_t j : std::get<std::vector<std::size_t>>(independent)) {
      p.symbols.push_back(s.velocities[j]);
      p.definitions.push_back({s.velocities[j].get_name(), s.velocities[j]});
    }
  } else {
    if (model.pseudo_velocities.size() != k)
      return fmt::format("[pseudo_velocities] has {} entr{}, but the model has {} degree{} of freedom ({} coordinates, "
                         "{} constraint{}): give one pseudo-velocity per degree of freedom",
                         model.pseudo_velocities.size(), model.pseudo_velocities.size() == 1 ? "y" : "ies", k,
                         k == 1 ? "" : "s", n, m, m == 1 ? "" : "s");
    for (const NamedSymbolic& d : model.pseudo_velocities) {
      p.symbols.emplace_back(d.name);
      p.definitions.push_back(d);
    }
  }
  // [Y; C] q' = [s − y; −b]  ⇒  q' = K⁻¹ [s − y; −b]
  GiNaC::matrix Y(k, n), K(n, n), right(n, 1);
  std::vector<ex> y;
  split_linear(p.definitions, s, Y, y);
  for (unsigned i = 0; i < n; ++i)
    for (unsigned j = 0; j < n; ++j) K(i, j) = i < k ? Y(i, j) : c.jacobian(i - k, j);
  for (unsigned i = 0; i < n; ++i) right(i, 0) = i < k ? p.symbols[i] - y[i] : -c.bias[i - k];
  ex det = tidy_ratio(K.determinant(), motion);
  if (det.is_zero() || std::abs(initial_value(det, s)) < 1e-9)
    return std::string("the pseudo-velocities and the constraints do not determine the velocities at the initial "
                       "state (the matrix [Y; C] of s = Y q' + y and C q' + b = 0 is singular there)");
  GiNaC::matrix rates = K.inverse().mul(right);
  for (unsigned j = 0; j < n; ++j) p.coordinate_rates.push_back(tidy_ratio(rates(j, 0), motion));
  for (const NamedSymbolic& d : p.definitions) p.initial_values.push_back(initial_value(d.expression, s));
  return p;
}

}  // namespace eomgen
