#include "symbolic_analysis/stability_conditions.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "emit/formats.hpp"

namespace eomgen {

using GiNaC::ex;

GiNaC::numeric exact_number(double value, int digits) {
  std::string text = digits > 0 ? fmt::format("{:.{}g}", value, digits) : format_number(value);
  bool negative = text[0] == '-';
  if (negative) text = text.substr(1);
  int exponent = 0;
  if (auto e = text.find_first_of("eE"); e != std::string::npos) {
    exponent = std::stoi(text.substr(e + 1));
    text = text.substr(0, e);
  }
  std::string mantissa;
  for (char c : text) {
    if (c == '.') exponent -= static_cast<int>(text.size() - text.find('.') - 1);
    else mantissa += c;
  }
  GiNaC::numeric n(mantissa.c_str());
  n = n * GiNaC::numeric(10).power(exponent);
  return negative ? -n : n;
}

namespace {

// numeric values (equilibrium, sines of it) are rounded to this many significant digits
// before they enter the exact computation, so that 0.5000000000000001 reads as 1/2
constexpr int constant_digits = 12;

bool has_symbols(const ex& e) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) return true;
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (has_symbols(e.op(i))) return true;
  return false;
}

// numbers that are not exact (floats, sin of a numeric angle) become exact rationals of their doubles
ex exact(const ex& e) {
  if (GiNaC::is_a<GiNaC::numeric>(e)) {
    const auto& n = GiNaC::ex_to<GiNaC::numeric>(e);
    return n.is_rational() ? e : ex(exact_number(n.to_double(), constant_digits));
  }
  if (GiNaC::is_a<GiNaC::symbol>(e)) return e;
  if (!has_symbols(e)) {
    ex v = e.evalf();
    if (GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_real())
      return exact_number(GiNaC::ex_to<GiNaC::numeric>(v).to_double(), constant_digits);
  }
  return e.map([](const ex& x) { return exact(x); });
}

std::vector<ex> operands_of(const ex& e, bool sum) {
  std::vector<ex> out;
  if (sum ? GiNaC::is_a<GiNaC::add>(e) : GiNaC::is_a<GiNaC::mul>(e))
    for (std::size_t i = 0; i < e.nops(); ++i) out.push_back(e.op(i));
  else
    out.push_back(e);
  return out;
}

// > 0 for positive parameters: a sum of terms, each a positive number times positive
// symbols and even powers of anything, at least one of them without even powers
bool is_positive(const ex& e, const GiNaC::exset& positive) {
  bool strictly = false;
  for (const ex& term : operands_of(e.expand(), true)) {
    bool has_even_power = false;
    for (const ex& f : operands_of(term, false)) {
      if (GiNaC::is_a<GiNaC::numeric>(f)) {
        if (!GiNaC::ex_to<GiNaC::numeric>(f).is_positive()) return false;
      } else if (GiNaC::is_a<GiNaC::power>(f) && f.op(1).info(GiNaC::info_flags::even)) {
        has_even_power = has_even_power || !positive.count(f.op(0));
      } else if (!positive.count(GiNaC::is_a<GiNaC::power>(f) ? f.op(0) : f)) {
        return false;
      }
    }
    strictly = strictly || !has_even_power;
  }
  return strictly;
}

// the condition scaled so that its largest numeric coefficient is ±1
ex normalized(const ex& condition) {
  double largest = 0;
  for (const ex& term : operands_of(condition.expand(), true))
    for (const ex& f : operands_of(term, false))
      if (GiNaC::is_a<GiNaC::numeric>(f)) largest = std::max(largest, std::abs(GiNaC::ex_to<GiNaC::numeric>(f).to_double()));
  if (largest == 0) return condition;
  return (condition / exact_number(largest, constant_digits)).expand();
}

// drops factors known to be positive: positive numbers, even powers, kept parameters
ex without_positive_factors(const ex& condition, const GiNaC::exset& positive) {
  if (condition.expand().is_zero()) return 0;  // vanishes: not a condition that holds
  ex f = GiNaC::factor(condition.expand());
  std::vector<ex> factors;
  if (GiNaC::is_a<GiNaC::mul>(f))
    for (std::size_t i = 0; i < f.nops(); ++i) factors.push_back(f.op(i));
  else
    factors.push_back(f);
  ex sign = 1, rest = 1;
  for (const ex& x : factors) {
    if (GiNaC::is_a<GiNaC::numeric>(x)) {
      if (GiNaC::ex_to<GiNaC::numeric>(x).is_negative()) sign = -sign;
      continue;
    }
    if (GiNaC::is_a<GiNaC::power>(x) && x.op(1).info(GiNaC::info_flags::even)) continue;
    const ex base = GiNaC::is_a<GiNaC::power>(x) ? x.op(0) : x;
    if (positive.count(base) || is_positive(base, positive)) continue;
    rest *= x;
  }
  return (sign * rest).expand().is_zero() ? ex(0) : normalized(sign * rest);
}

}  // namespace

StabilityConditions stability_conditions(const Equations& e, const std::vector<std::string>& kept,
                                         const std::vector<double>& parameters, const std::vector<double>& inputs,
                                         const std::vector<double>& state) {
  // M q'' + P q' + Q q = 0 in independent coordinates: not Lagrange I, not Appell's first-order form
  if (e.has_multipliers || e.uses_pseudo_velocities())
    throw std::invalid_argument("symbolic stability conditions need independent coordinates and q' as velocities");
  const Symbols& s = e.symbols;
  std::size_t n = s.num_coordinates();
  StabilityConditions out;
  out.kept = kept;
  GiNaC::exset positive;
  GiNaC::exmap numbers{{s.time, 0}};
  for (std::size_t i = 0; i < s.parameters.size(); ++i) {
    if (std::find(kept.begin(), kept.end(), s.parameter_names[i]) != kept.end()) positive.insert(s.parameters[i]);
    else numbers[s.parameters[i]] = exact_number(parameters[i]);
  }
  for (std::size_t i = 0; i < s.inputs.size(); ++i) numbers[s.inputs[i]] = exact_number(inputs[i]);

  // the equilibrium unknowns: non-cyclic coordinates, cyclic velocities; does the equilibrium move?
  std::vector<bool> cyclic = cyclic_coordinates(e);
  std::vector<ex> unknowns;
  GiNaC::exmap at_equilibrium;
  for (std::size_t i = 0; i < n; ++i) {
    if (cyclic[i]) {
      unknowns.push_back(s.velocities[i]);
      at_equilibrium[s.velocities[i]] = exact_number(state[n + i]);
    } else {
      unknowns.push_back(s.coordinates[i]);
      at_equilibrium[s.coordinates[i]] = exact_number(state[i]);
      numbers[s.velocities[i]] = 0;
    }
  }
  GiNaC::exmap all = numbers;
  for (const auto& [k, v] : at_equilibrium) all[k] = v;
  GiNaC::exmap evaluation = all;
  for (std::size_t i = 0; i < s.parameters.size(); ++i) evaluation[s.parameters[i]] = exact_number(parameters[i]);
  bool moves = false;
  for (std::size_t i = 0; i < n && !moves; ++i)
    for (const ex& p : positive) {
      ex sensitivity = e.forcing[i].diff(GiNaC::ex_to<GiNaC::symbol>(p)).subs(evaluation).evalf();
      if (!GiNaC::is_a<GiNaC::numeric>(sensitivity) ||
          std::abs(GiNaC::ex_to<GiNaC::numeric>(sensitivity).to_double()) > 1e-12) {
        moves = true;
        break;
      }
    }
  GiNaC::exmap substitution = moves ? numbers : all;
  if (moves) {
    for (std::size_t i = 0; i < n; ++i) {
      out.equilibrium_unknowns.push_back(GiNaC::ex_to<GiNaC::symbol>(unknowns[i]).get_name());
      out.equilibrium_equations.push_back(exact(e.forcing[i].subs(substitution)));
    }
  }
  // det(λ² M + λ P + Q) with P = −∂f/∂q', Q = −∂f/∂q; each cyclic coordinate gives a factor λ
  GiNaC::matrix pencil(n, n);
  for (unsigned i = 0; i < n; ++i)
    for (unsigned j = 0; j < n; ++j) {
      ex P = -e.forcing[i].diff(s.velocities[j]), Q = -e.forcing[i].diff(s.coordinates[j]);
      pencil(i, j) = exact((GiNaC::pow(out.lambda, 2) * e.mass_matrix(i, j) + out.lambda * P + Q).subs(substitution));
    }
  ex full = pencil.determinant().expand();
  int cyclic_count = static_cast<int>(std::count(cyclic.begin(), cyclic.end(), true));
  ex polynomial = 0;
  for (int k = cyclic_count; k <= full.degree(out.lambda); ++k)
    polynomial += full.coeff(out.lambda, k) * GiNaC::pow(out.lambda, k - cyclic_count);
  polynomial = polynomial.expand();
  int degree = polynomial.degree(out.lambda);
  std::vector<ex> c;  // highest power first, scaled so that the largest number in the leading coefficient is 1
  ex scale = normalized(polynomial.coeff(out.lambda, degree)) / polynomial.coeff(out.lambda, degree);
  out.characteristic_polynomial = 0;
  for (int k = degree; k >= 0; --k) {
    c.push_back((polynomial.coeff(out.lambda, k) * scale).expand());
    out.characteristic_polynomial += c.back() * GiNaC::pow(out.lambda, k);
  }
  out.characteristic_polynomial = out.characteristic_polynomial.expand();
  // all coefficients positive, and the inner Hurwitz determinants Δ_2 … Δ_{n−1} (Liénard–Chipart would need fewer)
  auto at = [&](int k) { return k >= 0 && k <= degree ? c[k] : ex(0); };
  // a condition that vanishes identically is not one that holds: the roots sit on the imaginary
  // axis (or at zero) for every value, and the first method decides nothing
  for (int k = 0; k <= degree; ++k) {
    ex condition = without_positive_factors(c[k] * c[0], positive);
    if (condition.is_zero()) out.vanishing.push_back(fmt::format("the coefficient of lambda^{}", degree - k));
    else if (!GiNaC::is_a<GiNaC::numeric>(condition)) out.conditions.push_back(condition);
    else if (GiNaC::is_a<GiNaC::numeric>(condition) && GiNaC::ex_to<GiNaC::numeric>(condition).is_negative())
      out.conditions.push_back(condition);
  }
  for (int k = 2; k < degree; ++k) {
    GiNaC::matrix H(k, k);
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j) H(i, j) = at(2 * j - i + 1);
    ex condition = without_positive_factors(H.determinant() * GiNaC::pow(c[0], k), positive);
    if (condition.is_zero()) out.vanishing.push_back(fmt::format("the Hurwitz determinant Delta_{}", k));
    else if (!GiNaC::is_a<GiNaC::numeric>(condition) || GiNaC::ex_to<GiNaC::numeric>(condition).is_negative())
      out.conditions.push_back(condition);
  }
  for (const ex& p : positive) {
    bool appears = out.characteristic_polynomial.has(p);
    for (const ex& q : out.equilibrium_equations) appears = appears || q.has(p);
    if (!appears) out.absent.push_back(GiNaC::ex_to<GiNaC::symbol>(p).get_name());
  }
  std::sort(out.absent.begin(), out.absent.end());
  return out;
}

GiNaC::ex rounded_for_display(const GiNaC::ex& e, int digits) {
  if (GiNaC::is_a<GiNaC::numeric>(e)) {
    const auto& n = GiNaC::ex_to<GiNaC::numeric>(e);
    if (n.is_integer() || !n.is_real()) return e;
    return GiNaC::numeric(std::stod(fmt::format("{:.{}g}", n.to_double(), digits)));
  }
  struct Rounding : GiNaC::map_function {
    int digits;
    explicit Rounding(int d) : digits(d) {}
    ex operator()(const ex& x) override { return rounded_for_display(x, digits); }
  } rounding(digits);
  return e.map(rounding);
}

}  // namespace eomgen
