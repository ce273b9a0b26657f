#include "symbolic_analysis/exact_linear_system.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "symbolic/canonical_print.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

// the decimal a double was written as, exactly: 0.1 → 1/10 (shortest round-trip digits)
std::optional<GiNaC::numeric> exact_decimal(double v) {
  std::string s = fmt::format("{}", v);
  if (s.find_first_of("eEn") != std::string::npos) return std::nullopt;  // exponents, inf, nan
  bool negative = s[0] == '-';
  if (negative) s = s.substr(1);
  std::size_t dot = s.find('.');
  std::string digits = dot == std::string::npos ? s : s.substr(0, dot) + s.substr(dot + 1);
  std::size_t decimals = dot == std::string::npos ? 0 : s.size() - dot - 1;
  if (digits.size() > 17) return std::nullopt;
  GiNaC::numeric value(digits.c_str());
  value = value / GiNaC::pow(GiNaC::numeric(10), GiNaC::numeric(static_cast<long>(decimals)));
  return negative ? -value : value;
}

// an angle written as a multiple of π (--at phi=Pi, 3*Pi/4): k π/d with d ≤ 12 when v is the double
// nearest to it, so that cos(π) is −1 exactly; a decimal that is no such double stays a decimal
std::optional<ex> exact_angle(double v) {
  if (v == 0 || !std::isfinite(v)) return std::nullopt;
  for (long d = 1; d <= 12; ++d) {
    double k = std::round(v * static_cast<double>(d) / M_PI);
    if (k == 0 || std::abs(k) > 48 * static_cast<double>(d)) continue;
    ex angle = GiNaC::numeric(static_cast<long>(k), d) * GiNaC::Pi;
    if (GiNaC::ex_to<GiNaC::numeric>(angle.evalf()).to_double() == v) return angle;
  }
  return std::nullopt;
}

bool is_rational_number(const ex& v) {
  return GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_rational();
}

struct Point {
  GiNaC::exmap substitution;  // state, inputs, time and (at values) the parameters
  GiNaC::exmap values;        // parameter symbols kept → their values
  GiNaC::lst kept;
};

// each entry at the point, checked to be rational (at values) or a rational function of the kept parameters
std::optional<GiNaC::matrix> exact_at(const GiNaC::matrix& X, const Point& point, const char* name, std::string& refusal) {
  GiNaC::matrix out(X.rows(), X.cols());
  for (unsigned i = 0; i < X.rows(); ++i)
    for (unsigned j = 0; j < X.cols(); ++j) {
      ex v = X(i, j).subs(point.substitution).normal();
      bool exact = point.kept.nops() == 0 ? is_rational_number(v)
                                          : v.numer().is_polynomial(point.kept) && v.denom().is_polynomial(point.kept) &&
                                                is_rational_number(v.subs(point.values).normal());
      if (!exact) {
        refusal = fmt::format("{}[{}][{}] = {} is not {} at this state", name, i, j, canonical_text(v),
                              point.kept.nops() ? "a rational function of the parameters" : "rational");
        return std::nullopt;
      }
      out(i, j) = v;
    }
  return out;
}

GiNaC::matrix stacked(const GiNaC::matrix& top, const GiNaC::matrix& bottom) {
  GiNaC::matrix out(top.rows() + bottom.rows(), top.cols());
  for (unsigned j = 0; j < top.cols(); ++j) {
    for (unsigned i = 0; i < top.rows(); ++i) out(i, j) = top(i, j);
    for (unsigned i = 0; i < bottom.rows(); ++i) out(top.rows() + i, j) = bottom(i, j);
  }
  return out;
}

// y = C x + D u for each output: a state picks its entry, an [outputs] expression is differentiated
void output_rows(const Equations& e, const std::vector<std::string>& names, GiNaC::matrix& C, GiNaC::matrix& D) {
  const Symbols& s = e.symbols;
  std::size_t n = s.num_coordinates();
  C = GiNaC::matrix(names.size(), 2 * n), D = GiNaC::matrix(names.size(), s.inputs.size());
  for (unsigned r = 0; r < names.size(); ++r) {
    ex y;
    for (std::size_t i = 0; i < n; ++i) {
      if (names[r] == s.coordinate_names[i]) y = s.coordinates[i];
      if (names[r] == s.velocities[i].get_name()) y = s.velocities[i];
    }
    for (const NamedSymbolic& o : e.outputs)
      if (o.name == names[r]) y = o.expression;
    for (unsigned i = 0; i < n; ++i) C(r, i) = y.diff(s.coordinates[i]), C(r, n + i) = y.diff(s.velocities[i]);
    for (unsigned j = 0; j < s.inputs.size(); ++j) D(r, j) = y.diff(s.inputs[j]);
  }
}

}  // namespace

GiNaC::matrix at_values(const GiNaC::matrix& X, const GiNaC::exmap& values) {
  GiNaC::matrix out(X.rows(), X.cols());
  for (unsigned i = 0; i < X.rows(); ++i)
    for (unsigned j = 0; j < X.cols(); ++j) out(i, j) = X(i, j).subs(values).normal();
  return out;
}

ExactLinearSystem exact_linear_system(const Equations& e, const std::vector<double>& parameters,
                                      const std::vector<double>& inputs, const std::vector<double>& state,
                                      bool keep_parameters, const std::vector<std::string>& outputs) {
  ExactLinearSystem out;
  out.in_parameters = keep_parameters;
  const Symbols& s = e.symbols;
  std::size_t n = s.num_coordinates();
  if (e.uses_pseudo_velocities() || e.has_multipliers || e.method == "routh" || e.method == "hamilton" || n > 6) {
    out.refusal = "exact arithmetic is used for Lagrange II models of up to six coordinates";
    return out;
  }
  Point point;
  point.substitution[s.time] = 0;
  auto exact = [&](const GiNaC::realsymbol& x, double v, const std::string& name) -> std::optional<GiNaC::numeric> {
    auto r = exact_decimal(v);
    if (!r && out.refusal.empty()) out.refusal = fmt::format("{} = {} has no exact decimal value", name, v);
    if (r) point.substitution[x] = *r;
    return r;
  };
  for (std::size_t i = 0; i < s.parameters.size(); ++i) {
    auto value = exact(s.parameters[i], parameters[i], s.parameter_names[i]);
    if (!keep_parameters || !value) continue;
    // a positive parameter as a positive symbol, so that sqrt(n^2) is n
    ex symbol = *value > 0 ? ex(GiNaC::possymbol(s.parameter_names[i])) : ex(GiNaC::realsymbol(s.parameter_names[i]));
    point.substitution[s.parameters[i]] = symbol;
    point.values[symbol] = *value;
    point.kept.append(symbol);
    if (*value > 0) out.assumptions.push_back(s.parameter_names[i] + " > 0");
  }
  for (std::size_t i = 0; i < s.inputs.size(); ++i) exact(s.inputs[i], inputs[i], s.input_names[i]);
  for (std::size_t i = 0; i < n; ++i) {
    if (auto angle = exact_angle(state[i])) point.substitution[s.coordinates[i]] = *angle;
    else exact(s.coordinates[i], state[i], s.coordinate_names[i]);
    exact(s.velocities[i], state[n + i], s.velocities[i].get_name());
  }
  if (!out.refusal.empty()) return out;
  out.parameter_values = point.values;
  Equations linear = e;
  if (!linear.has_linearization) add_linearization(linear);
  auto M = exact_at(e.mass_matrix, point, "M", out.refusal);
  auto P = M ? exact_at(linear.linear_damping_gyroscopic, point, "P", out.refusal) : std::nullopt;
  auto Q = P ? exact_at(linear.linear_stiffness_circulatory, point, "Q", out.refusal) : std::nullopt;
  auto Bq = Q ? exact_at(linear.linear_input, point, "B", out.refusal) : std::nullopt;
  GiNaC::matrix C, D;
  output_rows(e, outputs, C, D);
  auto Cx = Bq ? exact_at(C, point, "C", out.refusal) : std::nullopt;
  auto Du = Cx ? exact_at(D, point, "D", out.refusal) : std::nullopt;
  if (!Du) return out;
  GiNaC::matrix Minv = M->inverse(), lowerQ = Minv.mul(*Q).mul_scalar(-1), lowerP = Minv.mul(*P).mul_scalar(-1);
  out.A = GiNaC::matrix(2 * n, 2 * n);
  for (unsigned i = 0; i < n; ++i) {
    out.A(i, n + i) = 1;
    for (unsigned j = 0; j < n; ++j) out.A(n + i, j) = lowerQ(i, j).normal(), out.A(n + i, n + j) = lowerP(i, j).normal();
  }
  if (!s.inputs.empty()) {  // without inputs B_q is a single zero column
    GiNaC::matrix lowerB = Minv.mul(*Bq);
    out.B = at_values(stacked(GiNaC::matrix(n, lowerB.cols()), lowerB), {});
  }
  out.C = *Cx, out.D = *Du;
  return out;
}

}  // namespace eomgen
